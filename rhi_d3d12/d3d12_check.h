#pragma once
// HRESULTs become rhi::Error with the call that failed and the code's name and text; a removed
// device becomes rhi::DeviceLostError carrying the device-removed report (d3d12_dred.cpp).
#include "rhi/error.h"
#include "rhi_d3d12/d3d12_headers.h"

#include <string>
#include <string_view>

namespace lumina::d3d12 {

class DeviceContext;

// "0x887A0005 DXGI_ERROR_DEVICE_REMOVED (The GPU device instance has been suspended...)".
std::string hresultText(HRESULT hr);

bool isDeviceLoss(HRESULT hr);

// Throws rhi::Error("<call> failed: <hresultText>") when hr is a failure code.
void check(HRESULT hr, std::string_view call);
// As above; a lost device throws rhi::DeviceLostError with the context's removal report.
void check(HRESULT hr, std::string_view call, DeviceContext& context);

std::wstring toWide(std::string_view utf8);
std::string toUtf8(std::wstring_view wide);

// Names the object for debuggers, PIX, the debug layer and DRED.
void setDebugName(ID3D12Object* object, std::string_view name);

} // namespace lumina::d3d12
