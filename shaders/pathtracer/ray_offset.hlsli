#ifndef LUMINA_PT_RAY_OFFSET_HLSLI
#define LUMINA_PT_RAY_OFFSET_HLSLI
// Where a secondary ray starts: the hit point pushed off the surface along its geometric
// normal by a few hundred ulps, so that the ray cannot hit the surface it leaves whatever the
// scene's scale (Waechter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection",
// Ray Tracing Gems, chapter 6, 2019). Near the origin, where ulps are tiny, a fixed offset
// takes over. The constants are the chapter's.

// Below this magnitude a coordinate gets the fixed offset instead of the ulp offset.
#define LUMINA_PT_OFFSET_ORIGIN (1.0f / 32.0f)
// The fixed offset, in scene units, along the normal.
#define LUMINA_PT_OFFSET_FLOAT_SCALE (1.0f / 65536.0f)
// The ulp offset: 256 ulps along a unit normal component.
#define LUMINA_PT_OFFSET_INT_SCALE 256.0f

float ptOffsetComponent(float p, float n) {
    int ulps = int(LUMINA_PT_OFFSET_INT_SCALE * n);
    float moved = asfloat(asint(p) + (p < 0.0f ? -ulps : ulps));
    return abs(p) < LUMINA_PT_OFFSET_ORIGIN ? p + LUMINA_PT_OFFSET_FLOAT_SCALE * n : moved;
}

// p: the hit point; n: the unit geometric normal on the side the new ray leaves towards.
float3 ptOffsetRayOrigin(float3 p, float3 n) {
    return float3(ptOffsetComponent(p.x, n.x), ptOffsetComponent(p.y, n.y), ptOffsetComponent(p.z, n.z));
}

#endif
