#include "gi/frame/frame_finite_check.h"

namespace lumina::gi {

void watchFloatBuffers(FiniteCheck& check, const FrameRenderer& renderer) {
    const LumenGi* lumen = renderer.lumen();
    if (lumen == nullptr) {
        return;
    }
    const ScreenProbeResources& r = lumen->screenProbes().resources();
    for (const rhi::BufferHandle& buffer :
         {r.rayRadiance, r.nearField, r.frameRadiance, r.history[0], r.history[1], r.filtered, r.sh}) {
        if (buffer) {
            check.watchBuffer(*buffer);
        }
    }
}

} // namespace lumina::gi
