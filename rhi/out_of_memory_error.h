#pragma once
// rhi::OutOfMemoryError, beside rhi/error.h's Error and DeviceLostError (a header of its own
// so that the many files including error.h do not depend on it).
#include "rhi/error.h"

namespace lumina::rhi {

// Thrown when a resource does not fit in GPU memory: larger than the device allocates at once,
// or the driver is out of memory. The message names the resource and its size, so the user
// knows what to make smaller (tools add how).
class OutOfMemoryError : public Error {
public:
    using Error::Error;
};

} // namespace lumina::rhi
