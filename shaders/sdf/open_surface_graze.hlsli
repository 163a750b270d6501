#ifndef LUMINA_OPEN_SURFACE_GRAZE_HLSLI
#define LUMINA_OPEN_SURFACE_GRAZE_HLSLI
// A far-field hit on an open surface's shell that is a graze, not a hit (docs/gi.md, energy 29.).
// An open surface (a zero-thickness sheet: a ceiling panel, a quad wall) is closed in the global
// SDF by a shell of about half a global voxel plus 0.6 of its own mesh voxels, so that no ray
// slips between two voxel centres. Seen edge-on, the shell gives the sheet a thickness: a ray that
// passes just under two_rooms' panel, and would meet the ceiling beyond it, stops on the panel's
// shell and reads the panel, and such rays were most of that scene's bright first bounce. So a hit
// on an open instance's shell is followed along the ray to where it crosses the sheet's plane; if
// the sheet is not there (its own SDF reads more than its shell: the ray passes the sheet's edge),
// the ray goes on, stepped along the segment to that crossing:
//   - where it comes within reach of the sheet's own mesh again (a wall of the same mesh that
//     meets the sheet's edge, as in the furnaces' one-box rooms; or the sheet's edge, clipped) it
//     stops there;
//   - any other instance's surface met on the way (a step ends at most half a voxel on, in a voxel
//     that names it, below the hit threshold) stops it there: a wall that meets the sheet's edge
//     keeps the ray inside (tests/frame/data/sealed_box, gpu.sealed_box_leak_smoke), and a surface
//     that carries on the sheet's plane (the ceiling around the panel: its normal within
//     LUMINA_GRAZE_COPLANAR_COS of the sheet's) is met where the ray crosses that plane;
//   - else the march resumes from the plane's crossing (the sky past an opening's rim).
// Needs sdf/sdf_scene_bindings.hlsli first.

// How far a graze may be followed (world units): a ray nearly parallel to the sheet crosses its
// plane far away, past whatever the segment check could miss at that length.
#define LUMINA_GRAZE_MAX_FOLLOW 0.5f
// Steps of the segment check: at most this many, each at least this many reaches (below) long.
#define LUMINA_GRAZE_MAX_SAMPLES 32u
#define LUMINA_GRAZE_MIN_STEP_REACHES 0.25f
#define LUMINA_GRAZE_COPLANAR_COS 0.9f

// An instance's own distance at world point p (no shell), world units.
float sdfInstanceDistance(SdfInstanceDesc instance, float3 p) {
    SdfVolumeDesc volume = LUMINA_SDF_VOLUME(instance.ids.x);
    return sdfSampleVolume(volume, LUMINA_SDF_SCENE.invAtlasDims, sdfWorldToObject(instance, p)) *
           instance.worldMinAndScale.w;
}

// How near an open instance's own surface a point must be to lie on it, world units: its mesh
// SDF's hit threshold (the near field's), since a zero-thickness sheet's unsigned distance,
// interpolated between voxels, never falls much below half a voxel.
float sdfOpenSurfaceReach(SdfInstanceDesc instance) {
    SdfVolumeDesc volume = LUMINA_SDF_VOLUME(instance.ids.x);
    return LUMINA_SDF_OPEN_SURFACE_THRESHOLD_VOXELS * volume.volumeMinAndVoxelSize.w *
           instance.worldMinAndScale.w;
}

// `hit` of a far-field march along unit `direction`, or where a graze of an open surface's shell
// leads (above). `params` are the march's.
SdfHit sdfFollowGraze(SdfHit hit, float3 direction, SdfTraceParams params) {
    if (sdfIsMiss(hit)) {
        return hit;
    }
    float3 p = hit.positionAndT.xyz;
    float t = hit.positionAndT.w;
    uint index = sdfGlobalInstanceAt(p);
    if (index == LUMINA_SDF_NO_HIT) {
        return hit;
    }
    SdfInstanceDesc instance = LUMINA_SDF_INSTANCE(index);
    // Closed volumes have no shell (worldMax.w is 0): their zero crossing is their surface.
    if (!(instance.worldMax.w > 0.0f)) {
        return hit;
    }
    uint cascade = sdfGlobalCascadeAt(p);
    float shell = instance.worldMax.w + LUMINA_SDF_SCENE.cascades[cascade].openShellExtra;
    float3 n = sdfFacingNormal(hit.normalAndCoverage.xyz, direction, t);
    float cosine = -dot(direction, n);
    float ownAtHit = sdfInstanceDistance(instance, p);
    float depth = min(ownAtHit, shell);
    if (!(cosine > 0.0f) || !(depth > 0.0f)) {
        return hit;
    }
    float follow = depth / cosine;
    if (!(follow <= LUMINA_GRAZE_MAX_FOLLOW) ||
        !(sdfInstanceDistance(instance, p + follow * direction) > shell)) {
        return hit; // the sheet is where the ray crosses its plane: a hit
    }
    // The segment to the plane's crossing, stepped by the sheet's own distance (less its reach,
    // so that no stretch within reach is stepped over) and at most half a global voxel (so that
    // no other instance's shell is).
    float3 origin = p - t * direction;
    float reach = sdfOpenSurfaceReach(instance);
    float halfVoxel = 0.5f * sdfGlobalVoxelSize(cascade);
    float along = 0.0f;
    for (uint i = 0u; i < LUMINA_GRAZE_MAX_SAMPLES; ++i) {
        float3 q = p + along * direction;
        float own = along > 0.0f ? sdfInstanceDistance(instance, q) : ownAtHit;
        // The ray meets the sheet's own mesh: a wall of the same mesh that meets the sheet's edge
        // (a room built as one box, the furnaces), or the sheet's edge itself, clipped.
        if (!(own >= reach)) {
            if (along > 0.0f) {
                hit = sdfGlobalHit(origin, direction, t + along, hit.ids.w, 0.0f);
            }
            return hit;
        }
        uint other = sdfGlobalInstanceAt(q);
        if (along > 0.0f && other != index && other != LUMINA_SDF_NO_HIT &&
            sdfSampleGlobal(q) < params.hitThresholdVoxels * sdfGlobalVoxelSizeAt(q)) {
            bool carriesPlane = abs(dot(sdfGlobalNormal(q), n)) > LUMINA_GRAZE_COPLANAR_COS;
            return sdfGlobalHit(origin, direction, t + (carriesPlane ? follow : along), hit.ids.w, 0.0f);
        }
        if (along >= follow) {
            params.maxDistance = max(params.maxDistance - t - follow, 0.0f);
            SdfHit next = sdfTraceGlobal(p + follow * direction, direction, 0.0f, params);
            next.positionAndT.w += t + follow;
            return next;
        }
        along = min(along + clamp(own - reach, LUMINA_GRAZE_MIN_STEP_REACHES * reach, halfVoxel), follow);
    }
    return hit; // too many steps to tell: the graze stays a hit
}

#endif
