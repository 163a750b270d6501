#ifndef LUMINA_CARD_CAPTURE_SHARED_H
#define LUMINA_CARD_CAPTURE_SHARED_H
// Push constants of the card capture (card_capture.hlsl, gi/surface_cache/card_capture_pass.h):
// one draw per submesh of the card's instance.
#include "../common/shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct CardCaptureConstants {
    uint instance; // GpuInstance index (the card's instance)
    uint material; // GpuMaterial index of the submesh
    uint card;     // SurfaceCard index in the card buffer
    uint pad0;
};
LUMINA_STATIC_ASSERT_SIZE(CardCaptureConstants, 16);

LUMINA_GPU_NAMESPACE_END

#endif
