#ifndef LUMINA_RAY_TRIANGLE_HLSLI
#define LUMINA_RAY_TRIANGLE_HLSLI
// Watertight ray/triangle intersection: Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2(1), 2013. Shared by C++ (gi/bvh/) and HLSL through shared_types.h.
//
// The ray is sheared and scaled once so that it runs along +z through the origin; the
// three 2D edge functions U, V, W of the projected triangle then decide the hit. A shared
// edge yields edge functions that are exact negations of each other in both triangles
// (the same products, subtracted the other way round), so a ray can never slip between
// two triangles that share bit-identical vertices. That needs the products left
// uncontracted: LUMINA_PRECISE forbids FMA in HLSL; C++ builds in ISO mode, where GCC
// and MSVC do not contract, and clang is told not to below.
//
// Both faces are hit (no culling). When an edge function is exactly zero, C++ recomputes
// all three in double precision as the paper does; HLSL keeps the float result (zero
// counts as inside, so the ray hits both triangles of the edge: never a hole).
#include "shared_types.h"

LUMINA_GPU_NAMESPACE_BEGIN

struct WatertightRay {
    float3 origin;
    int3 axes;    // kx, ky, kz: kz is the dominant direction axis
    float3 shear; // Sx, Sy, Sz
};

LUMINA_INLINE WatertightRay makeWatertightRay(float3 origin, float3 direction) {
    WatertightRay ray;
    ray.origin = origin;
    float3 a = abs(direction);
    int kz = (a.x > a.y) ? ((a.x > a.z) ? 0 : 2) : ((a.y > a.z) ? 1 : 2);
    int kx = (kz + 1) % 3;
    int ky = (kx + 1) % 3;
    if (direction[kz] < 0.0f) { // keep the winding of the projected triangle
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    ray.axes = int3(kx, ky, kz);
    ray.shear = float3(direction[kx] / direction[kz], direction[ky] / direction[kz], 1.0f / direction[kz]);
    return ray;
}

// Hit when the ray meets the triangle at a distance t with tMin < t <= tMax (t measured in
// units of the direction's length). bary = weights of v1 and v2; v0's is 1 - bary.x - bary.y.
LUMINA_INLINE bool intersectTriangleWatertight(WatertightRay ray, float3 v0, float3 v1, float3 v2, float tMin,
                                               float tMax, LUMINA_OUT(float) t, LUMINA_OUT(float2) bary) {
#if defined(__cplusplus) && defined(__clang__)
#pragma clang fp contract(off)
#endif
    t = 0.0f;
    bary = float2(0.0f, 0.0f);
    int kx = ray.axes.x;
    int ky = ray.axes.y;
    int kz = ray.axes.z;
    float3 A = v0 - ray.origin;
    float3 B = v1 - ray.origin;
    float3 C = v2 - ray.origin;
    LUMINA_PRECISE float Ax = A[kx] - ray.shear.x * A[kz];
    LUMINA_PRECISE float Ay = A[ky] - ray.shear.y * A[kz];
    LUMINA_PRECISE float Bx = B[kx] - ray.shear.x * B[kz];
    LUMINA_PRECISE float By = B[ky] - ray.shear.y * B[kz];
    LUMINA_PRECISE float Cx = C[kx] - ray.shear.x * C[kz];
    LUMINA_PRECISE float Cy = C[ky] - ray.shear.y * C[kz];
    LUMINA_PRECISE float U = Cx * By - Cy * Bx;
    LUMINA_PRECISE float V = Ax * Cy - Ay * Cx;
    LUMINA_PRECISE float W = Bx * Ay - By * Ax;
#ifdef __cplusplus
    if (U == 0.0f || V == 0.0f || W == 0.0f) {
        double CxBy = double(Cx) * double(By);
        double CyBx = double(Cy) * double(Bx);
        double AxCy = double(Ax) * double(Cy);
        double AyCx = double(Ay) * double(Cx);
        double BxAy = double(Bx) * double(Ay);
        double ByAx = double(By) * double(Ax);
        U = float(CxBy - CyBx);
        V = float(AxCy - AyCx);
        W = float(BxAy - ByAx);
    }
#endif
    if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) {
        return false;
    }
    float det = U + V + W;
    if (det == 0.0f) {
        return false; // seen edge-on
    }
    float Az = ray.shear.z * A[kz];
    float Bz = ray.shear.z * B[kz];
    float Cz = ray.shear.z * C[kz];
    float T = U * Az + V * Bz + W * Cz;
    // Compare T against the range scaled by |det| without dividing: flip both by det's sign.
    uint detSign = asuint(det) & 0x80000000u;
    float signedT = asfloat(asuint(T) ^ detSign);
    float absDet = abs(det);
    if (signedT <= tMin * absDet || signedT > tMax * absDet) {
        return false;
    }
    float rcpDet = 1.0f / det;
    t = T * rcpDet;
    bary = float2(V * rcpDet, W * rcpDet);
    return true;
}

LUMINA_GPU_NAMESPACE_END

#endif
