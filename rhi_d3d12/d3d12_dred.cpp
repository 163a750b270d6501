#include "rhi_d3d12/d3d12_dred.h"

#include "rhi_d3d12/d3d12_check.h"
#include "rhi_d3d12/d3d12_context.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace lumina::d3d12 {

namespace {

// Breadcrumbs printed before the last completed operation, and pending ones after it.
constexpr uint32_t kBreadcrumbsBefore = 8;
constexpr uint32_t kBreadcrumbsAfter = 8;

const char* breadcrumbName(D3D12_AUTO_BREADCRUMB_OP op) {
    switch (op) {
    case D3D12_AUTO_BREADCRUMB_OP_SETMARKER:
        return "SetMarker";
    case D3D12_AUTO_BREADCRUMB_OP_BEGINEVENT:
        return "BeginEvent";
    case D3D12_AUTO_BREADCRUMB_OP_ENDEVENT:
        return "EndEvent";
    case D3D12_AUTO_BREADCRUMB_OP_DRAWINSTANCED:
        return "DrawInstanced";
    case D3D12_AUTO_BREADCRUMB_OP_DRAWINDEXEDINSTANCED:
        return "DrawIndexedInstanced";
    case D3D12_AUTO_BREADCRUMB_OP_EXECUTEINDIRECT:
        return "ExecuteIndirect";
    case D3D12_AUTO_BREADCRUMB_OP_DISPATCH:
        return "Dispatch";
    case D3D12_AUTO_BREADCRUMB_OP_COPYBUFFERREGION:
        return "CopyBufferRegion";
    case D3D12_AUTO_BREADCRUMB_OP_COPYTEXTUREREGION:
        return "CopyTextureRegion";
    case D3D12_AUTO_BREADCRUMB_OP_COPYRESOURCE:
        return "CopyResource";
    case D3D12_AUTO_BREADCRUMB_OP_CLEARRENDERTARGETVIEW:
        return "ClearRenderTargetView";
    case D3D12_AUTO_BREADCRUMB_OP_CLEARUNORDEREDACCESSVIEW:
        return "ClearUnorderedAccessView";
    case D3D12_AUTO_BREADCRUMB_OP_CLEARDEPTHSTENCILVIEW:
        return "ClearDepthStencilView";
    case D3D12_AUTO_BREADCRUMB_OP_RESOURCEBARRIER:
        return "ResourceBarrier";
    case D3D12_AUTO_BREADCRUMB_OP_RESOLVEQUERYDATA:
        return "ResolveQueryData";
    case D3D12_AUTO_BREADCRUMB_OP_BEGINSUBMISSION:
        return "BeginSubmission";
    case D3D12_AUTO_BREADCRUMB_OP_ENDSUBMISSION:
        return "EndSubmission";
    case D3D12_AUTO_BREADCRUMB_OP_WRITEBUFFERIMMEDIATE:
        return "WriteBufferImmediate";
    case D3D12_AUTO_BREADCRUMB_OP_SETPIPELINESTATE1:
        return "SetPipelineState1";
    default:
        return nullptr;
    }
}

std::string opText(D3D12_AUTO_BREADCRUMB_OP op) {
    const char* name = breadcrumbName(op);
    return name ? name : "op " + std::to_string(int(op));
}

std::string objectName(const char* narrow, const wchar_t* wide) {
    if (wide && *wide) {
        return toUtf8(wide);
    }
    if (narrow && *narrow) {
        return narrow;
    }
    return "(unnamed)";
}

// One node per command list that was executing; contexts (marker text) only with DRED 1.2.
template <typename Node>
void printNode(std::ostringstream& out, const Node& node, const std::map<uint32_t, std::wstring>& contexts) {
    const uint32_t count = node.BreadcrumbCount;
    const uint32_t completed = node.pLastBreadcrumbValue ? *node.pLastBreadcrumbValue : 0;
    if (completed >= count) {
        return; // this list finished; it is not where the GPU stopped
    }
    out << "  command list '" << objectName(node.pCommandListDebugNameA, node.pCommandListDebugNameW)
        << "' on queue '" << objectName(node.pCommandQueueDebugNameA, node.pCommandQueueDebugNameW)
        << "': " << completed << " of " << count << " operations completed\n";
    const uint32_t first = completed > kBreadcrumbsBefore ? completed - kBreadcrumbsBefore : 0;
    const uint32_t last = std::min(count, completed + kBreadcrumbsAfter);
    for (uint32_t i = first; i < last; ++i) {
        out << (i < completed    ? "      done  "
                : i == completed ? "  --> next  "
                                 : "   pending  ")
            << opText(node.pCommandHistory[i]);
        if (const auto it = contexts.find(i); it != contexts.end()) {
            out << " \"" << toUtf8(it->second) << '"';
        }
        out << '\n';
    }
}

void printAllocations(std::ostringstream& out, const char* title, const D3D12_DRED_ALLOCATION_NODE* node) {
    out << "  " << title << ":";
    if (!node) {
        out << " none\n";
        return;
    }
    out << '\n';
    for (; node; node = node->pNext) {
        out << "    '" << objectName(node->ObjectNameA, node->ObjectNameW) << "' (allocation type "
            << int(node->AllocationType) << ")\n";
    }
}

} // namespace

bool enableDred(std::string& why) {
    ComPtr<ID3D12DeviceRemovedExtendedDataSettings> settings;
    const HRESULT hr = D3D12GetDebugInterface(IID_PPV_ARGS(&settings));
    if (FAILED(hr)) {
        why = "D3D12GetDebugInterface(ID3D12DeviceRemovedExtendedDataSettings): " + hresultText(hr);
        return false;
    }
    settings->SetAutoBreadcrumbsEnablement(D3D12_DRED_ENABLEMENT_FORCED_ON);
    settings->SetPageFaultEnablement(D3D12_DRED_ENABLEMENT_FORCED_ON);
    ComPtr<ID3D12DeviceRemovedExtendedDataSettings1> settings1;
    if (SUCCEEDED(settings.As(&settings1))) {
        settings1->SetBreadcrumbContextEnablement(D3D12_DRED_ENABLEMENT_FORCED_ON);
    }
    return true;
}

std::string dredReport(ID3D12Device* device, bool dredEnabled) {
    std::ostringstream out;
    out << "removal reason: " << hresultText(device->GetDeviceRemovedReason()) << '\n';
    if (!dredEnabled) {
        out << "DRED: not available on this runtime, no breadcrumbs or page-fault data\n";
        return out.str();
    }
    ComPtr<ID3D12DeviceRemovedExtendedData> dred;
    if (FAILED(device->QueryInterface(IID_PPV_ARGS(&dred)))) {
        out << "DRED: the device exposes no ID3D12DeviceRemovedExtendedData\n";
        return out.str();
    }
    out << "DRED breadcrumbs (unfinished command lists):\n";
    ComPtr<ID3D12DeviceRemovedExtendedData1> dred1;
    D3D12_DRED_AUTO_BREADCRUMBS_OUTPUT1 breadcrumbs1{};
    D3D12_DRED_AUTO_BREADCRUMBS_OUTPUT breadcrumbs{};
    if (SUCCEEDED(dred.As(&dred1)) && SUCCEEDED(dred1->GetAutoBreadcrumbsOutput1(&breadcrumbs1))) {
        for (const D3D12_AUTO_BREADCRUMB_NODE1* node = breadcrumbs1.pHeadAutoBreadcrumbNode; node;
             node = node->pNext) {
            std::map<uint32_t, std::wstring> contexts;
            for (uint32_t i = 0; i < node->BreadcrumbContextsCount; ++i) {
                const D3D12_DRED_BREADCRUMB_CONTEXT& context = node->pBreadcrumbContexts[i];
                contexts[context.BreadcrumbIndex] = context.pContextString ? context.pContextString : L"";
            }
            printNode(out, *node, contexts);
        }
    } else if (SUCCEEDED(dred->GetAutoBreadcrumbsOutput(&breadcrumbs))) {
        for (const D3D12_AUTO_BREADCRUMB_NODE* node = breadcrumbs.pHeadAutoBreadcrumbNode; node;
             node = node->pNext) {
            printNode(out, *node, {});
        }
    } else {
        out << "  none recorded\n";
    }
    D3D12_DRED_PAGE_FAULT_OUTPUT pageFault{};
    if (SUCCEEDED(dred->GetPageFaultAllocationOutput(&pageFault)) && pageFault.PageFaultVA != 0) {
        out << "DRED page fault at GPU virtual address 0x" << std::hex << pageFault.PageFaultVA << std::dec
            << '\n';
        printAllocations(out, "allocations at that address", pageFault.pHeadExistingAllocationNode);
        printAllocations(out, "recently freed allocations there", pageFault.pHeadRecentFreedAllocationNode);
    } else {
        out << "DRED: no page fault reported\n";
    }
    return out.str();
}

std::string DeviceContext::deviceRemovedReport() {
    return dredReport(device_.Get(), dredEnabled);
}

} // namespace lumina::d3d12
