#include "rhi/fault_injection.h"

#include "rhi/error.h"

#include <atomic>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string_view>

namespace lumina::rhi::fault {

namespace {

constexpr const char* kVariable = "LUMINA_FAULT_INJECT";
constexpr std::string_view kDeviceLostAfterSubmits = "device-lost-after-submits:";

struct Plan {
    std::string text;                       // the variable's value, for messages
    std::optional<uint64_t> submitsAllowed; // device-lost-after-submits:N
};

Plan readPlan() {
    const char* value = std::getenv(kVariable);
    if (!value || !*value) {
        return {};
    }
    Plan plan{.text = value, .submitsAllowed = std::nullopt};
    const std::string_view text = value;
    if (text.starts_with(kDeviceLostAfterSubmits)) {
        const std::string_view count = text.substr(kDeviceLostAfterSubmits.size());
        uint64_t n = 0;
        const auto [end, error] = std::from_chars(count.data(), count.data() + count.size(), n);
        if (error == std::errc() && end == count.data() + count.size() && !count.empty()) {
            plan.submitsAllowed = n;
            return plan;
        }
    }
    throw Error(std::string(kVariable) + "='" + plan.text +
                "': not a fault this build injects (the one it knows: device-lost-after-submits:N, N >= 0)");
}

// Read once, on the first submission; the environment of a test does not change under it.
const Plan& plan() {
    static const Plan parsed = readPlan();
    return parsed;
}

std::atomic<uint64_t> submissions{0};
std::atomic<bool> lost{false};

} // namespace

bool deviceLostOnSubmit() {
    const Plan& current = plan();
    if (!current.submitsAllowed) {
        return false;
    }
    if (lost.load() || submissions.fetch_add(1) >= *current.submitsAllowed) {
        lost.store(true);
        return true;
    }
    return false;
}

bool deviceLost() {
    return lost.load();
}

std::string injectedNote() {
    return "; injected by " + std::string(kVariable) + "=" + plan().text;
}

} // namespace lumina::rhi::fault
