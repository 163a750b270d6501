#pragma once
// The CPU half of a scene's distance fields: every mesh SDF built (or loaded from the
// SdfCache), packed into one atlas; the instance table the GPU traces through; the layout of
// the global SDF grid. gi/sdf/scene_sdf.h uploads it and composes the global SDF on the GPU;
// tests use it directly as the reference.
#include "gi/bvh/bvh.h"
#include "gi/scene/scene.h"
#include "gi/sdf/global_sdf.h"
#include "gi/sdf/global_sdf_cascades.h"
#include "gi/sdf/mesh_sdf.h"
#include "gi/sdf/sdf_atlas.h"
#include "shaders/common/sdf_scene_shared.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace lumina::sdf {

inline constexpr uint32_t kNoVolume = 0xFFFFFFFFu;

// The global resolution the cascade rules below are stated at.
inline constexpr uint32_t kCascadeRuleResolution = 64;

struct SceneSdfSettings {
    SdfSettings mesh; // per-mesh build: 64 voxels along the longest axis by default
    SdfTexelFormat atlasFormat = SdfTexelFormat::R16F;
    // Global voxels along the longest axis of the scene, padding included, when one grid covers
    // it; per side of every cascade when the scene needs cascades (gi/sdf/global_sdf_cascades.h).
    uint32_t globalResolution = 64;
    // Clipmap cascades (gi/sdf/global_sdf_cascades.h). The scene's detail is measured by its
    // median instance (the longest side of its SDF volume's world box: a yardstick free of the
    // scene's units). A scene whose scene-fitted grid gives that instance at least
    // globalCascadeBelowVoxelsPerInstance voxels keeps that one grid (the Cornell boxes: 60,
    // furnaces: 60, open_top_box: 13, atrium: 3.6); a coarser one (the city: 1.6) gets cascades
    // halving the voxel size from the fitted one towards median / globalFinestVoxelsPerInstance,
    // at most globalCascades (<= LUMINA_SDF_MAX_CASCADES) of globalResolution^3 voxels.
    // globalFinestVoxelSize > 0 (world units) replaces both rules: cascades whenever the
    // fitted voxel is coarser than it, towards it. Both rules count voxels of a
    // kCascadeRuleResolution-voxel grid (the scene-fitted voxel times globalResolution /
    // kCascadeRuleResolution): a finer resolution refines the cascades (the finest voxel wanted
    // shrinks with it) rather than trading them for one finer scene-fitted grid, which in the city
    // at 128 was coarser near the camera than 64's finest cascade (docs/gi.md energy 48.).
    uint32_t globalCascades = 4;
    float globalCascadeBelowVoxelsPerInstance = 2.0f;
    float globalFinestVoxelsPerInstance = 16.0f;
    float globalFinestVoxelSize = 0.0f;
    uint32_t globalPadding = 2; // global voxels of margin around the instances' boxes
    // Truncation of the global SDF, in global voxels: distances are clamped to
    // +-maxDistance, which bounds the region one moved instance can change (and so the
    // incremental recompose) and the far-field tracer's step.
    float globalMaxDistanceVoxels = 8.0f;
    bool useCache = true;
    std::filesystem::path cacheDirectory; // empty: SdfCache::defaultDirectory()
};

struct MeshSdfReport {
    uint32_t mesh = 0;
    std::string name;
    glm::uvec3 dims{0};
    uint32_t triangles = 0;
    double seconds = 0.0; // load from the cache, or build: thread time spent on this mesh
    bool fromCache = false;
    bool open = false;               // LUMINA_SDF_VOLUME_OPEN: boundary edges or no negative voxel
    uint32_t sharedWith = kNoVolume; // a mesh of identical geometry whose volume this one uses
    std::string note;                // why the cache was not used, or why the mesh has no SDF
};

struct SceneSdfReport {
    // Meshes that have a volume: line v is volume v's own mesh, in scene order; then the
    // meshes that share a volume with an identical one, in scene order.
    std::vector<MeshSdfReport> meshes;
    uint32_t meshesBuilt = 0;
    uint32_t meshesLoaded = 0;
    uint32_t meshesShared = 0; // neither built nor loaded: identical to an earlier mesh
    uint64_t voxelsBuilt = 0;  // zero when every SDF came from the cache
    uint64_t voxelsLoaded = 0;
    double meshSeconds = 0.0;  // building or loading all mesh SDFs (wall time)
    uint32_t buildThreads = 0; // threads the build used (sdfBuildThreads); 0 when nothing was built
    double packSeconds = 0.0;
};

struct SceneSdfData {
    SdfAtlas atlas;
    std::vector<uint32_t> meshVolume; // per scene mesh: its volume, kNoVolume when unused or empty
    // One per scene instance whose mesh has a volume, in scene order; instance ids in the
    // global SDF and the instance BVH index this table.
    std::vector<gpu::SdfInstanceDesc> instances;
    GlobalSdfCascadeLayout cascades; // the global SDF's cascades (one: the scene-fitted grid)
    // The finest cascade's grid with its window around the scene camera (the scene-fitted grid
    // for a single cascade); its voxel size sizes the open instances' shells.
    GlobalSdfSettings global;
    glm::vec3 camera{0.0f};          // the scene camera's position: where the cascades start
    float medianInstanceSize = 0.0f; // longest side of the median instance's world box
    float finestVoxelWanted = 0.0f;  // the finest cascade voxel the settings asked for
    SceneSdfReport report;

    // The instance table as composeGlobalSdf takes it.
    std::vector<SdfInstance> composeInstances() const;
    // The constant buffer of the tracing library for the cascades' current windows.
    gpu::SdfSceneInfo sceneInfo(uint32_t instanceBvhNodes, std::span<const glm::ivec3> windows) const;
};

// Throws std::invalid_argument for bad settings; a scene without triangles gives an empty
// table and a one-voxel grid.
SceneSdfData buildSceneSdfData(const scene::Scene& scene, const SceneSdfSettings& settings = {});

// The table entry of one instance of `volume` (index volumeIndex) placed by meshToWorld.
// globalVoxelSize sizes the open-surface shell (worldMax.w).
gpu::SdfInstanceDesc makeInstanceDesc(const gpu::SdfVolumeDesc& volume, uint32_t volumeIndex,
                                      const glm::mat4& meshToWorld, uint32_t mesh, uint32_t sceneInstance,
                                      float globalVoxelSize);

// Whether a triangle mesh has boundary edges: an edge (vertices compared by position, so
// seams of split vertices do not count) used by an odd number of triangles. Such meshes are
// flagged LUMINA_SDF_VOLUME_OPEN unless everyFaceBacksOntoInside.
bool hasBoundaryEdges(std::span<const glm::vec3> positions, std::span<const uint32_t> indices);

// Whether the mesh's SDF (`volume` of `atlas`, mesh units) is negative one voxel behind the
// centre of every non-degenerate triangle (front faces wind counter-clockwise): the mesh is a
// solid, whatever faces it lacks. False for a mesh of no such triangle.
bool everyFaceBacksOntoInside(const SdfAtlas& atlas, uint32_t volume, std::span<const glm::vec3> positions,
                              std::span<const uint32_t> indices);
glm::mat4 objectToWorld(const gpu::SdfInstanceDesc& instance);
bvh::Aabb worldBox(const gpu::SdfInstanceDesc& instance);

// Cubic voxels over `box`: `resolution` along its longest axis (padding included), the
// other axes as many as cover it, centred on the box.
GlobalSdfSettings globalGridFor(const bvh::Aabb& box, uint32_t resolution, uint32_t padding,
                                float maxDistanceVoxels);

} // namespace lumina::sdf
