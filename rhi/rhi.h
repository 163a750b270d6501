#pragma once
// The whole API-neutral interface. Nothing here names a Vulkan or D3D12 type.
#include "rhi/binding.h"
#include "rhi/command_list.h"
#include "rhi/device.h"
#include "rhi/error.h"
#include "rhi/format.h"
#include "rhi/pipeline.h"
#include "rhi/resource.h"
#include "rhi/shader_library.h"
#include "rhi/state_tracker.h"
#include "rhi/swapchain.h"
#include "rhi/transfer.h"
