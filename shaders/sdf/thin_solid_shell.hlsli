#ifndef LUMINA_THIN_SOLID_SHELL_HLSLI
#define LUMINA_THIN_SOLID_SHELL_HLSLI
// The thin-solid shell of the global SDF composition, the GPU twin of thinSolidShell
// (gi/sdf/global_sdf.cpp, which says why): how much a closed volume's distance at mesh-space
// point p drops so that a solid thinner than a global voxel is one voxel thick to the grid.
// Needs common/sdf_sampling.hlsli (sdfSampleVolume) first.

// Gradient of a volume's field at p, from tetrahedral differences e apart (four samples).
float3 sdfThinSolidGradient(SdfVolumeDesc volume, float3 invAtlasDims, float3 p, float e) {
    float3 k0 = float3(1.0f, -1.0f, -1.0f);
    float3 k1 = float3(-1.0f, -1.0f, 1.0f);
    float3 k2 = float3(-1.0f, 1.0f, -1.0f);
    float3 k3 = float3(1.0f, 1.0f, 1.0f);
    float3 sum = k0 * sdfSampleVolume(volume, invAtlasDims, p + e * k0) +
                 k1 * sdfSampleVolume(volume, invAtlasDims, p + e * k1) +
                 k2 * sdfSampleVolume(volume, invAtlasDims, p + e * k2) +
                 k3 * sdfSampleVolume(volume, invAtlasDims, p + e * k3);
    return sum / (4.0f * e);
}

// Its direction; zero where the differences vanish (the middle of a thin slab).
float3 sdfThinSolidDirection(SdfVolumeDesc volume, float3 invAtlasDims, float3 p, float e) {
    float3 gradient = sdfThinSolidGradient(volume, invAtlasDims, p, e);
    return gradient / max(length(gradient), 1e-30f);
}

// Mesh units throughout; `distance` is the sample at p, `halfThickness` the depth the grid
// needs. 0 where the solid is at least that deep.
float sdfThinSolidShell(SdfVolumeDesc volume, float3 invAtlasDims, float3 p, float distance,
                        float halfThickness) {
    if (distance <= -halfThickness) {
        return 0.0f;
    }
    float voxel = volume.volumeMinAndVoxelSize.w;
    float e = 0.5f * voxel;
    // The nearest surface point, from p held a voxel inside the volume's box.
    float3 x =
        clamp(p, volume.volumeMinAndVoxelSize.xyz + voxel, volume.volumeMaxAndInvVoxelSize.xyz - voxel);
    // A field steeper than a distance is a missing face's sign flip, not a thin part.
    float3 gradient = sdfThinSolidGradient(volume, invAtlasDims, x, e);
    float slope = length(gradient);
    if (slope > LUMINA_SDF_THIN_SOLID_MAX_SLOPE) {
        return 0.0f;
    }
    float3 n = gradient / max(slope, 1e-30f);
    x -= n * sdfSampleVolume(volume, invAtlasDims, x);
    x -= n * sdfSampleVolume(volume, invAtlasDims, x);
    // Beside a face of a thick solid one sample straight in proves it.
    if (sdfSampleVolume(volume, invAtlasDims, x - n * (1.5f * halfThickness)) <= -halfThickness) {
        return 0.0f;
    }
    // Down the gradient until deep enough, no deeper, or out on the far side.
    float stepLength = 0.25f * halfThickness;
    float deepest = min(distance, 0.0f);
    float last = 0.0f;
    for (uint i = 0u; i < LUMINA_SDF_THIN_SOLID_STEPS; ++i) {
        x -= sdfThinSolidDirection(volume, invAtlasDims, x, e) * stepLength;
        float s = sdfSampleVolume(volume, invAtlasDims, x);
        if (s >= last && last < 0.0f) {
            break; // past the middle of a thin part, or out of it
        }
        last = s;
        deepest = min(deepest, s);
        if (deepest <= -halfThickness) {
            break;
        }
    }
    return max(halfThickness + deepest, 0.0f);
}

#endif
