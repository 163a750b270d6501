#pragma once
// Errors carry context: the API call, the resource, the value that was wrong.
#include <stdexcept>
#include <string>

namespace lumina::rhi {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Thrown when the device is lost (TDR, DEVICE_REMOVED): message holds the backend's report.
class DeviceLostError : public Error {
public:
    using Error::Error;
};

} // namespace lumina::rhi
