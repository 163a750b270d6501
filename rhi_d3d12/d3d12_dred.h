#pragma once
// Device Removed Extended Data: enabled before the device is created, read after it is lost.
#include "rhi_d3d12/d3d12_headers.h"

#include <string>

namespace lumina::d3d12 {

// Turns on DRED auto-breadcrumbs, breadcrumb contexts (marker text) and page-fault reporting
// for devices created afterwards. Returns false, with the reason in `why`, where the runtime
// has no DRED (Windows before 10 1903, Wine's vkd3d).
bool enableDred(std::string& why);

// The removal reason, every command list that had not finished with its breadcrumbs around
// the last completed operation, and the allocations near a page fault.
std::string dredReport(ID3D12Device* device, bool dredEnabled);

} // namespace lumina::d3d12
