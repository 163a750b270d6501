#ifndef LUMINA_SURFACE_LINE_START_HLSLI
#define LUMINA_SURFACE_LINE_START_HLSLI
// Where a ray of a probe that sits off its surface starts, so that it sees what the surface's own
// point sees (docs/gi.md, energy 19.-21.). Used by the radiosity probes and the screen probes; needs
// the global SDF (sdf/sdf_scene_bindings.hlsli).
//
// A probe's origin sits h above its surface point (lifted and pushed clear of the surface, since a
// trace that starts on the surface hits it at once). From there a ray sees the scene from h up:
// nearer the ceiling, so an overhead source looks larger, and the lowest strip of the walls lies
// below its horizon. The surface point's own view along `dir` is the line through that point; it
// reaches height h a distance h tan(theta) along the surface. So the start slides that far from the
// origin along the surface, towards the ray's direction, as far as free space reaches: each step
// is certified by a global SDF sample at its start (any point within distance d of a sample of d
// is free), less a margin of `marginVoxels` global SDF voxels there.

// SDF samples a slide may take: enough for the three steeper of four cos(theta) bands over an open
// floor; the shallowest slides part way. Not 16: the APIs' rounding then parted the starts of
// about 100 of open_top_box's 8,364 radiosity probes (none with 8), and D3D12's screen probes
// drifted from Vulkan's (docs/gi.md, energy 22.).
#define LUMINA_SURFACE_LINE_SLIDE_STEPS 8u

// The radiosity trace's slide (docs/gi.md, energy 28. and 29.): 16 steps, each certified also by
// a sample raised by the origin's height (where the surface's own plane is the nearest thing, that
// ball reaches about 1.4 times the height along the surface), so that its shallow rays reach their
// line too. D3D12 under Wine matches Vulkan's goldens at these 16 steps (the drift above did not
// come back: docs/gi.md, energy 29.).
#define LUMINA_SURFACE_LINE_RAISED_SLIDE_STEPS 16u

// `origin` lies above `surfacePoint` along the unit normal `n`; `cosTheta` is dot(dir, n), passed
// in because a caller that built `dir` from it has the exact value. `raised`: certify each step by
// a sample raised by the origin's height as well.
float3 surfaceLineSlide(float3 origin, float3 surfacePoint, float3 n, float3 dir, float cosTheta,
                        float marginVoxels, uint steps, bool raised) {
    float height = dot(origin - surfacePoint, n);
    float3 along = dir - cosTheta * n;
    float sinTheta = length(along);
    if (height <= 0.0f || sinTheta <= 1e-4f || cosTheta <= 0.0f) {
        return origin;
    }
    along /= sinTheta;
    float wanted = height * sinTheta / cosTheta;
    float slid = 0.0f;
    // A flag, not `break` in a loop whose condition also tests `slid`: with 16 steps, lavapipe's
    // Vulkan and vkd3d's D3D12 computed that loop differently (the emissive box's cache 5 % apart).
    bool sliding = true;
    for (uint step = 0u; step < steps; ++step) {
        if (sliding) {
            float3 p = origin + slid * along;
            float margin = marginVoxels * sdfGlobalVoxelSizeAt(p);
            float free = sdfSampleGlobal(p) - margin;
            if (raised) {
                float freeAbove = sdfSampleGlobal(p + height * n) - margin;
                free = max(free, freeAbove > height ? sqrt(freeAbove * freeAbove - height * height) : 0.0f);
            }
            sliding = free > 0.0f;
            slid = sliding ? min(slid + free, wanted) : slid;
            sliding = sliding && slid < wanted;
        }
    }
    return origin + slid * along;
}

float3 surfaceLineStart(float3 origin, float3 surfacePoint, float3 n, float3 dir, float cosTheta,
                        float marginVoxels) {
    return surfaceLineSlide(origin, surfacePoint, n, dir, cosTheta, marginVoxels,
                            LUMINA_SURFACE_LINE_SLIDE_STEPS, false);
}

float3 surfaceLineStartRaised(float3 origin, float3 surfacePoint, float3 n, float3 dir, float cosTheta,
                              float marginVoxels) {
    return surfaceLineSlide(origin, surfacePoint, n, dir, cosTheta, marginVoxels,
                            LUMINA_SURFACE_LINE_RAISED_SLIDE_STEPS, true);
}

#endif
