#pragma once
// Groups of the one-thread-per-probe DDGI passes (reset, relocate, classify).
#include "gi/ddgi/ddgi_resources.h"
#include "shaders/ddgi/ddgi_shared.h"

namespace lumina::gi {

inline uint32_t ddgiProbeGroups(const DdgiResources& r) {
    return (r.layout.probes + LUMINA_DDGI_PROBE_GROUP - 1) / LUMINA_DDGI_PROBE_GROUP;
}

} // namespace lumina::gi
