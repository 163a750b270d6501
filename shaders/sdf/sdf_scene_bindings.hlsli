#ifndef LUMINA_SDF_SCENE_BINDINGS_HLSLI
#define LUMINA_SDF_SCENE_BINDINGS_HLSLI
// The registers SceneSdf::bindForTracing (gi/sdf/scene_sdf.h) fills, and the whole tracing
// library (near field, far field, cone) on top of them. Registers t6 and up, b1 and up, and
// every u register are left to the kernel.
#include "common/bindings.hlsli"
#include "common/bvh_shared.h"
#include "common/sdf_scene_shared.h"
#include "common/sdf_shared.h"

ConstantBuffer<SdfSceneInfo> gSdfScene : register(b0);
Texture3D<float> gSdfAtlas : register(t0);
StructuredBuffer<SdfVolumeDesc> gSdfVolumes : register(t1);
StructuredBuffer<SdfInstanceDesc> gSdfInstances : register(t2);
StructuredBuffer<BvhNode> gSdfInstanceNodes : register(t3);
StructuredBuffer<uint> gSdfInstanceList : register(t4);
Texture3D<float2> gGlobalSdf : register(t5);
SamplerState gSdfLinearClamp : register(s0);

#define LUMINA_SDF_ATLAS gSdfAtlas
#define LUMINA_SDF_SAMPLER gSdfLinearClamp
#define LUMINA_SDF_SCENE gSdfScene
#define LUMINA_SDF_VOLUME(i) gSdfVolumes[i]
#define LUMINA_SDF_INSTANCE(i) gSdfInstances[i]
#define LUMINA_SDF_INSTANCE_NODE(i) gSdfInstanceNodes[i]
#define LUMINA_SDF_INSTANCE_LIST(i) gSdfInstanceList[i]
#define LUMINA_SDF_GLOBAL gGlobalSdf
#include "common/sdf_far_field.hlsli"
#include "common/sdf_near_field.hlsli"

#endif
