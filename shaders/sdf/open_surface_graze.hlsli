#ifndef LUMINA_OPEN_SURFACE_GRAZE_HLSLI
#define LUMINA_OPEN_SURFACE_GRAZE_HLSLI
// A far-field hit on an open surface's shell that is a graze, not a hit (docs/gi.md, energy 29.).
// An open surface (a zero-thickness sheet: a ceiling panel, a quad wall) is closed in the global
// SDF by a shell of about half a global voxel plus 0.6 of its own mesh voxels, so that no ray
// slips between two voxel centres. Seen edge-on, the shell gives the sheet a thickness, and beside
// an edge it is rounded: a ray that passes just under a panel, or up through a skylight beside
// its rim, stops on the shell and reads the sheet, though it never meets it. So a hit on an open
// instance's shell is followed through the shell, stepped by the sheet's own distance:
//   - where the ray comes within reach of the sheet's own mesh (the sheet, a wall of the same mesh
//     that meets its edge as in the furnaces' one-box rooms, or its edge, clipped), or meets
//     another instance's surface (a voxel that names it, below the hit threshold: a wall that
//     meets the sheet's edge, tests/frame/data/sealed_box), the first hit stands;
//   - where the global SDF leaves every shell, and no mesh's own SDF lies on the way through it
//     (the near field: a solid thinner than the shell does not show in the global grid), the
//     march resumes from there (the sky past an opening's rim).
// Needs sdf/sdf_scene_bindings.hlsli first.

// How far a graze may be followed through the shell (world units): beyond it the first hit stands.
#define LUMINA_GRAZE_MAX_FOLLOW 0.5f
// Steps through the shell: at most this many, each at least this many reaches (below) long.
#define LUMINA_GRAZE_MAX_SAMPLES 32u
#define LUMINA_GRAZE_MIN_STEP_REACHES 0.25f

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
    // Through the shell, stepped by the sheet's own distance (less its reach, so that no stretch
    // within reach is stepped over) and at most half a global voxel (so that no other instance's
    // shell is).
    float reach = sdfOpenSurfaceReach(instance);
    float halfVoxel = 0.5f * sdfGlobalVoxelSize(cascade);
    float along = 0.0f;
    for (uint i = 0u; i < LUMINA_GRAZE_MAX_SAMPLES; ++i) {
        float3 q = p + along * direction;
        float own = sdfInstanceDistance(instance, q);
        // The ray meets the sheet's own mesh (the sheet, a wall of the same mesh that meets its
        // edge as in the furnaces' one-box rooms, or its edge, clipped): the first hit stands.
        if (!(own >= reach)) {
            return hit;
        }
        if (along > 0.0f) {
            if (sdfSampleGlobal(q) >= params.hitThresholdVoxels * sdfGlobalVoxelSizeAt(q)) {
                // Out of every shell, the sheet not met: the march goes on from here, if no mesh
                // lies on the way through the shell. Each mesh's own SDF tells (the near field);
                // the global grid cannot: a solid thinner than the shell (a door over a floor)
                // does not show in it, and its voxels name the shell's instance.
                SdfTraceParams segment = params;
                segment.maxDistance = along;
                segment.maxSteps = LUMINA_GRAZE_MAX_SAMPLES;
                if (!sdfIsMiss(sdfTraceNearField(p, direction, 0.0f, segment))) {
                    return hit;
                }
                params.maxDistance = max(params.maxDistance - t - along, 0.0f);
                SdfHit next = sdfTraceGlobal(q, direction, 0.0f, params);
                next.positionAndT.w += t + along;
                return next;
            }
            // Another instance's surface (its voxel, below the hit threshold): the first hit
            // stands. Stopping instead where the ray crosses the sheet's plane when that surface
            // carries it on (the ceiling around two_rooms' panel) let light through `door`'s
            // closed door (docs/gi.md, energy 29., v5-v8).
            uint other = sdfGlobalInstanceAt(q);
            if (other != index && other != LUMINA_SDF_NO_HIT) {
                return hit;
            }
        }
        if (!(along < LUMINA_GRAZE_MAX_FOLLOW)) {
            break;
        }
        along += clamp(own - reach, LUMINA_GRAZE_MIN_STEP_REACHES * reach, halfVoxel);
    }
    return hit; // too many steps to tell: the graze stays a hit
}

#endif
