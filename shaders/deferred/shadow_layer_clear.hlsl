// lumina-kernel: vs vsMain
// lumina-kernel: ps psMain
// Clears one layer of a cube shadow map by drawing over it: a triangle covering the viewport at
// depth 1 (depth test Always) writing distance 1, "as far as the shadow range". A copy-queue
// clear takes the whole array; when one light of several moved, only its six faces are redrawn
// (gi/deferred/point_shadow_pass.cpp), so the others must keep their texels.

struct Varyings {
    float4 position : SV_Position;
};

Varyings vsMain(uint vertexId : SV_VertexID) {
    // (-1,-1), (3,-1), (-1,3): one triangle over the whole viewport.
    const float2 corner = float2(float((vertexId << 1u) & 2u), float(vertexId & 2u));
    Varyings output;
    output.position = float4(corner * 2.0 - 1.0, 1.0, 1.0);
    return output;
}

float psMain(Varyings input) : SV_Target0 {
    return 1.0;
}
