#include "rhi_d3d12/d3d12_check.h"

#include "rhi/out_of_memory_error.h"
#include "rhi_d3d12/d3d12_context.h"

#include <cstdio>

namespace lumina::d3d12 {

namespace {

// The codes D3D12 and DXGI return in practice; anything else is printed as hex and the
// system's message text.
const char* hresultName(HRESULT hr) {
    switch (hr) {
    case E_FAIL:
        return "E_FAIL";
    case E_INVALIDARG:
        return "E_INVALIDARG";
    case E_OUTOFMEMORY:
        return "E_OUTOFMEMORY";
    case E_NOTIMPL:
        return "E_NOTIMPL";
    case E_NOINTERFACE:
        return "E_NOINTERFACE";
    case E_POINTER:
        return "E_POINTER";
    case DXGI_ERROR_DEVICE_REMOVED:
        return "DXGI_ERROR_DEVICE_REMOVED";
    case DXGI_ERROR_DEVICE_HUNG:
        return "DXGI_ERROR_DEVICE_HUNG";
    case DXGI_ERROR_DEVICE_RESET:
        return "DXGI_ERROR_DEVICE_RESET";
    case DXGI_ERROR_DRIVER_INTERNAL_ERROR:
        return "DXGI_ERROR_DRIVER_INTERNAL_ERROR";
    case DXGI_ERROR_INVALID_CALL:
        return "DXGI_ERROR_INVALID_CALL";
    case DXGI_ERROR_NOT_FOUND:
        return "DXGI_ERROR_NOT_FOUND";
    case DXGI_ERROR_UNSUPPORTED:
        return "DXGI_ERROR_UNSUPPORTED";
    case DXGI_ERROR_SDK_COMPONENT_MISSING:
        return "DXGI_ERROR_SDK_COMPONENT_MISSING";
    case D3D12_ERROR_ADAPTER_NOT_FOUND:
        return "D3D12_ERROR_ADAPTER_NOT_FOUND";
    case D3D12_ERROR_DRIVER_VERSION_MISMATCH:
        return "D3D12_ERROR_DRIVER_VERSION_MISMATCH";
    default:
        return nullptr;
    }
}

std::string systemMessage(HRESULT hr) {
    char* buffer = nullptr;
    const DWORD length = FormatMessageA(
        FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr,
        static_cast<DWORD>(hr), 0, reinterpret_cast<char*>(&buffer), 0, nullptr);
    std::string text = length ? std::string(buffer, length) : std::string();
    if (buffer) {
        LocalFree(buffer);
    }
    while (!text.empty() &&
           (text.back() == '\n' || text.back() == '\r' || text.back() == ' ' || text.back() == '.')) {
        text.pop_back();
    }
    return text;
}

} // namespace

std::string hresultText(HRESULT hr) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%08lX", static_cast<unsigned long>(hr));
    std::string text = hex;
    if (const char* name = hresultName(hr)) {
        text += ' ';
        text += name;
    }
    if (const std::string message = systemMessage(hr); !message.empty()) {
        text += " (" + message + ")";
    }
    return text;
}

bool isDeviceLoss(HRESULT hr) {
    return hr == DXGI_ERROR_DEVICE_REMOVED || hr == DXGI_ERROR_DEVICE_HUNG || hr == DXGI_ERROR_DEVICE_RESET ||
           hr == DXGI_ERROR_DRIVER_INTERNAL_ERROR;
}

void check(HRESULT hr, std::string_view call) {
    if (hr == E_OUTOFMEMORY) {
        throw rhi::OutOfMemoryError("out of GPU memory: " + std::string(call) +
                                    " failed: " + hresultText(hr));
    }
    if (FAILED(hr)) {
        throw rhi::Error(std::string(call) + " failed: " + hresultText(hr));
    }
}

void check(HRESULT hr, std::string_view call, DeviceContext& context) {
    if (isDeviceLoss(hr)) {
        context.throwDeviceLost(std::string(call) + " returned " + hresultText(hr));
    }
    check(hr, call);
}

std::wstring toWide(std::string_view utf8) {
    if (utf8.empty()) {
        return {};
    }
    const int length =
        MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), nullptr, 0);
    std::wstring wide(static_cast<size_t>(length), L'\0');
    MultiByteToWideChar(CP_UTF8, 0, utf8.data(), static_cast<int>(utf8.size()), wide.data(), length);
    return wide;
}

std::string toUtf8(std::wstring_view wide) {
    if (wide.empty()) {
        return {};
    }
    const int length = WideCharToMultiByte(CP_UTF8, 0, wide.data(), static_cast<int>(wide.size()), nullptr, 0,
                                           nullptr, nullptr);
    std::string utf8(static_cast<size_t>(length), '\0');
    WideCharToMultiByte(CP_UTF8, 0, wide.data(), static_cast<int>(wide.size()), utf8.data(), length, nullptr,
                        nullptr);
    return utf8;
}

void setDebugName(ID3D12Object* object, std::string_view name) {
    if (object && !name.empty()) {
        object->SetName(toWide(name).c_str());
    }
}

} // namespace lumina::d3d12
