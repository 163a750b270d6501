#include "gi/sdf/scene_sdf_data.h"

#include "gi/sdf/sdf_cache.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <unordered_map>

namespace lumina::sdf {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Rows r of a 3x4 affine matrix (glm is column-major: m[column][row]).
void writeRows(const glm::mat4& m, gpu::float4 rows[3]) {
    for (int r = 0; r < 3; ++r) {
        rows[r] = glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
    }
}

} // namespace

gpu::SdfInstanceDesc makeInstanceDesc(const gpu::SdfVolumeDesc& volume, uint32_t volumeIndex,
                                      const glm::mat4& meshToWorld, uint32_t mesh, uint32_t sceneInstance,
                                      float globalVoxelSize) {
    gpu::SdfInstanceDesc desc{};
    writeRows(glm::inverse(meshToWorld), desc.worldToObject);
    writeRows(meshToWorld, desc.objectToWorld);
    const bvh::Aabb box = instanceWorldBox(volume, meshToWorld);
    const float scale = instanceDistanceScale(meshToWorld);
    desc.worldMinAndScale = glm::vec4(box.min, scale);
    desc.worldMax = glm::vec4(box.max, openSurfaceShell(volume, scale, globalVoxelSize));
    desc.ids = glm::uvec4(volumeIndex, mesh, sceneInstance, 0u);
    return desc;
}

glm::mat4 objectToWorld(const gpu::SdfInstanceDesc& instance) {
    glm::mat4 m(1.0f);
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) {
            m[c][r] = instance.objectToWorld[r][c];
        }
    }
    return m;
}

bvh::Aabb worldBox(const gpu::SdfInstanceDesc& instance) {
    return {glm::vec3(instance.worldMinAndScale), glm::vec3(instance.worldMax)};
}

GlobalSdfSettings globalGridFor(const bvh::Aabb& box, uint32_t resolution, uint32_t padding,
                                float maxDistanceVoxels) {
    if (resolution < 2 * padding + 1 || resolution > 1024) {
        throw std::invalid_argument("global SDF resolution " + std::to_string(resolution) + " with padding " +
                                    std::to_string(padding) + ": need 2 * padding < resolution <= 1024");
    }
    if (!(maxDistanceVoxels > 0.0f)) {
        throw std::invalid_argument("global SDF truncation must be positive, got " +
                                    std::to_string(maxDistanceVoxels) + " voxels");
    }
    GlobalSdfSettings grid;
    const bvh::Aabb b = box.empty() ? bvh::Aabb{glm::vec3(-0.5f), glm::vec3(0.5f)} : box;
    const glm::vec3 extent = b.size();
    const float longest = std::max({extent.x, extent.y, extent.z, 1e-6f * (1.0f + glm::length(b.centre()))});
    const uint32_t interior = resolution - 2 * padding;
    grid.voxelSize = longest / float(interior);
    for (int a = 0; a < 3; ++a) {
        const uint32_t inner =
            std::clamp(uint32_t(std::ceil(extent[a] / grid.voxelSize - 1e-3f)), 1u, interior);
        grid.dims[a] = inner + 2 * padding;
    }
    grid.boundsMin = b.centre() - 0.5f * glm::vec3(grid.dims) * grid.voxelSize;
    grid.maxDistance = maxDistanceVoxels * grid.voxelSize;
    return grid;
}

std::vector<SdfInstance> SceneSdfData::composeInstances() const {
    std::vector<SdfInstance> out;
    out.reserve(instances.size());
    for (const gpu::SdfInstanceDesc& instance : instances) {
        out.push_back({objectToWorld(instance), instance.ids.x});
    }
    return out;
}

gpu::SdfSceneInfo SceneSdfData::sceneInfo(uint32_t instanceBvhNodes,
                                          std::span<const glm::ivec3> windows) const {
    if (windows.size() != cascades.count) {
        throw std::invalid_argument("SceneSdfData::sceneInfo: " + std::to_string(windows.size()) +
                                    " windows for " + std::to_string(cascades.count) + " cascades");
    }
    gpu::SdfSceneInfo info{};
    info.invAtlasDims = glm::vec3(atlas.info().invAtlasDims);
    bvh::Aabb covered;
    for (uint32_t c = 0; c < cascades.count; ++c) {
        const GlobalSdfSettings grid = cascadeGrid(cascades, c, windows[c]);
        const glm::vec3 gridMax = grid.boundsMin + glm::vec3(grid.dims) * grid.voxelSize;
        covered.extend(grid.boundsMin);
        covered.extend(gridMax);
        gpu::SdfGlobalCascade& cascade = info.cascades[c];
        cascade.boxMin = grid.boundsMin;
        cascade.voxelSize = grid.voxelSize;
        cascade.boxMax = gridMax;
        cascade.maxDistance = grid.maxDistance;
        cascade.latticeOrigin = cascades.latticeOrigin;
        cascade.openShellExtra = grid.openShellExtra;
        cascade.window = glm::uvec3(windows[c]); // int bits
        cascade.wrap = cascadeTexel(cascades, windows[c], glm::uvec3(0));
        cascade.slabFirstZ = c * grid.dims.z;
        cascade.dims = grid.dims;
    }
    const GlobalSdfSettings finest = cascadeGrid(cascades, 0, windows[0]);
    info.globalMin = covered.min;
    info.globalVoxelSize = finest.voxelSize;
    info.globalMax = covered.max;
    info.globalMaxDistance = finest.maxDistance;
    info.globalDims = cascades.dims;
    info.cascadeCount = cascades.count;
    info.instanceCount = uint32_t(instances.size());
    info.instanceBvhNodeCount = instanceBvhNodes;
    info.volumeCount = uint32_t(atlas.volumes.size());
    return info;
}

bool hasBoundaryEdges(std::span<const glm::vec3> positions, std::span<const uint32_t> indices) {
    // Vertices welded by exact position, then every undirected edge counted.
    std::map<std::array<float, 3>, uint32_t> weld;
    std::vector<uint32_t> id(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) {
        id[i] = weld.try_emplace({positions[i].x, positions[i].y, positions[i].z}, uint32_t(weld.size()))
                    .first->second;
    }
    std::unordered_map<uint64_t, uint32_t> edges;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        for (int e = 0; e < 3; ++e) {
            const uint32_t a = id[indices[t + e]], b = id[indices[t + (e + 1) % 3]];
            if (a != b) {
                ++edges[(uint64_t(std::min(a, b)) << 32) | std::max(a, b)];
            }
        }
    }
    return std::any_of(edges.begin(), edges.end(), [](const auto& edge) { return edge.second % 2 != 0; });
}

bool everyFaceBacksOntoInside(const SdfAtlas& atlas, uint32_t volume, std::span<const glm::vec3> positions,
                              std::span<const uint32_t> indices) {
    const float voxel = atlas.volumes.at(volume).volumeMinAndVoxelSize.w;
    bool anyFace = false;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::vec3 a = positions[indices[t]], b = positions[indices[t + 1]],
                        c = positions[indices[t + 2]];
        const glm::vec3 cross = glm::cross(b - a, c - a);
        const float length = glm::length(cross);
        if (!(length > 0.0f)) {
            continue; // degenerate: no side to test
        }
        anyFace = true;
        const glm::vec3 behind = (a + b + c) / 3.0f - (cross / length) * voxel;
        if (!(sampleSdf(atlas, volume, behind) < 0.0f)) {
            return false;
        }
    }
    return anyFace;
}

SceneSdfData buildSceneSdfData(const scene::Scene& scene, const SceneSdfSettings& settings) {
    validate(settings.mesh);
    SceneSdfData data;
    std::vector<bool> used(scene.meshes.size(), false);
    for (const scene::Instance& instance : scene.instances) {
        if (instance.mesh >= scene.meshes.size()) {
            throw std::invalid_argument("scene '" + scene.name + "': instance '" + instance.name +
                                        "' names mesh " + std::to_string(instance.mesh) + " of " +
                                        std::to_string(scene.meshes.size()));
        }
        used[instance.mesh] = true;
    }

    const Clock::time_point meshStart = Clock::now();
    SdfCache cache(settings.cacheDirectory.empty() ? SdfCache::defaultDirectory() : settings.cacheDirectory);
    std::vector<MeshSdf> sdfs;
    data.meshVolume.assign(scene.meshes.size(), kNoVolume);
    std::unordered_map<uint64_t, uint32_t> volumeByKey;
    std::vector<MeshSdfReport> sharedLines; // appended after the built and loaded ones
    std::vector<uint32_t> toBuild;          // volumes the cache did not have
    std::vector<uint64_t> toBuildKeys;
    for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const scene::Mesh& mesh = scene.meshes[m];
        if (!used[m] || mesh.indices.empty()) {
            continue;
        }
        MeshSdfReport line;
        line.mesh = m;
        line.name = mesh.name;
        // Meshes of identical geometry (the atrium's three drapes) share one volume.
        const uint64_t key = SdfCache::key(mesh.positions, mesh.indices, settings.mesh);
        if (const auto same = volumeByKey.find(key); same != volumeByKey.end()) {
            line.sharedWith = data.report.meshes[same->second].mesh; // dims filled in once built
            data.meshVolume[m] = same->second;
            ++data.report.meshesShared;
            sharedLines.push_back(std::move(line));
            continue;
        }
        volumeByKey.emplace(key, uint32_t(sdfs.size()));
        MeshSdf sdf;
        if (settings.useCache) {
            const Clock::time_point loadStart = Clock::now();
            if (std::optional<MeshSdf> cached = cache.load(key, &line.note)) {
                sdf = std::move(*cached);
                line.fromCache = true;
                line.note.clear();
                line.seconds = secondsSince(loadStart);
            }
        } else {
            line.note = "cache off";
        }
        if (!line.fromCache) {
            toBuild.push_back(uint32_t(sdfs.size()));
            toBuildKeys.push_back(key);
        }
        data.meshVolume[m] = uint32_t(sdfs.size());
        sdfs.push_back(std::move(sdf));
        data.report.meshes.push_back(std::move(line));
    }
    // Everything the cache did not have, built as one batch (buildMeshSdfs: all threads on all
    // meshes' slices), then stored.
    std::vector<MeshSdfInput> inputs;
    for (uint32_t v : toBuild) {
        const scene::Mesh& mesh = scene.meshes[data.report.meshes[v].mesh];
        inputs.push_back({mesh.positions, mesh.indices});
    }
    std::vector<MeshSdf> built = buildMeshSdfs(inputs, settings.mesh);
    for (size_t b = 0; b < toBuild.size(); ++b) {
        MeshSdfReport& line = data.report.meshes[toBuild[b]];
        line.seconds = built[b].stats.seconds;
        std::string storeError;
        if (settings.useCache && !cache.store(toBuildKeys[b], built[b], &storeError)) {
            line.note += "; not stored: " + storeError;
        }
        sdfs[toBuild[b]] = std::move(built[b]);
    }
    for (uint32_t v = 0; v < sdfs.size(); ++v) {
        MeshSdfReport& line = data.report.meshes[v];
        line.dims = sdfs[v].dims;
        line.triangles = sdfs[v].stats.triangles;
        const uint64_t voxels = uint64_t(sdfs[v].dims.x) * sdfs[v].dims.y * sdfs[v].dims.z;
        (line.fromCache ? data.report.voxelsLoaded : data.report.voxelsBuilt) += voxels;
        ++(line.fromCache ? data.report.meshesLoaded : data.report.meshesBuilt);
    }
    for (MeshSdfReport& line : sharedLines) {
        const MeshSdf& shared = sdfs[data.meshVolume[line.mesh]];
        line.dims = shared.dims;
        line.triangles = shared.stats.triangles;
    }
    data.report.buildThreads = toBuild.empty() ? 0 : sdfBuildThreads(settings.mesh);
    data.report.meshSeconds = secondsSince(meshStart);
    // report.meshes[v] is volume v's own line up to here; then the sharing meshes.
    data.report.meshes.insert(data.report.meshes.end(), sharedLines.begin(), sharedLines.end());

    const Clock::time_point packStart = Clock::now();
    SdfAtlasSettings atlasSettings;
    atlasSettings.format = settings.atlasFormat;
    data.atlas = packSdfs(sdfs, atlasSettings);
    data.report.packSeconds = secondsSince(packStart);

    for (MeshSdfReport& line : data.report.meshes) {
        const scene::Mesh& mesh = scene.meshes[line.mesh];
        gpu::SdfVolumeDesc& volume = data.atlas.volumes[data.meshVolume[line.mesh]];
        // A mesh with boundary edges is open unless every face has the mesh's inside behind it:
        // a solid whose missing faces lie against other geometry (a wall built of boxes without
        // the faces it shares with the floor) is resolved by its signed field and needs no
        // shell, which would thicken it and narrow every doorway in it (docs/gi.md, energy).
        if (hasBoundaryEdges(mesh.positions, mesh.indices) &&
            !everyFaceBacksOntoInside(data.atlas, data.meshVolume[line.mesh], mesh.positions, mesh.indices)) {
            volume.dims.w |= LUMINA_SDF_VOLUME_OPEN;
        }
        line.open = (volume.dims.w & LUMINA_SDF_VOLUME_OPEN) != 0;
    }

    // The grid covers every instance's volume; the shells need its voxel size.
    bvh::Aabb sceneBox;
    for (const scene::Instance& instance : scene.instances) {
        const uint32_t volume = data.meshVolume[instance.mesh];
        if (volume != kNoVolume) {
            sceneBox.extend(instanceWorldBox(data.atlas.volumes[volume], instance.transform));
        }
    }
    std::vector<float> sizes;
    for (const scene::Instance& instance : scene.instances) {
        const uint32_t volume = data.meshVolume[instance.mesh];
        if (volume != kNoVolume) {
            const glm::vec3 size = instanceWorldBox(data.atlas.volumes[volume], instance.transform).size();
            sizes.push_back(std::max({size.x, size.y, size.z}));
        }
    }
    if (!sizes.empty()) {
        std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
        data.medianInstanceSize = sizes[sizes.size() / 2];
    }
    if (!(settings.globalCascadeBelowVoxelsPerInstance > 0.0f) ||
        !(settings.globalFinestVoxelsPerInstance > 0.0f) || !(settings.globalFinestVoxelSize >= 0.0f)) {
        throw std::invalid_argument("global SDF cascades: voxels per instance " +
                                    std::to_string(settings.globalCascadeBelowVoxelsPerInstance) + " and " +
                                    std::to_string(settings.globalFinestVoxelsPerInstance) +
                                    " must be > 0, the finest voxel size " +
                                    std::to_string(settings.globalFinestVoxelSize) + " >= 0");
    }
    uint32_t maxCascades = settings.globalCascades;
    if (settings.globalFinestVoxelSize > 0.0f) {
        data.finestVoxelWanted = settings.globalFinestVoxelSize;
    } else {
        const float fittedVoxel = globalGridFor(sceneBox, settings.globalResolution, settings.globalPadding,
                                                settings.globalMaxDistanceVoxels)
                                      .voxelSize;
        // Voxels of a kCascadeRuleResolution grid: exactly the fitted ones at that resolution.
        const float ruleScale = float(settings.globalResolution) / float(kCascadeRuleResolution);
        data.finestVoxelWanted =
            data.medianInstanceSize / (settings.globalFinestVoxelsPerInstance * ruleScale);
        if (!(data.medianInstanceSize > 0.0f) ||
            !(fittedVoxel * ruleScale * settings.globalCascadeBelowVoxelsPerInstance >
              data.medianInstanceSize)) {
            maxCascades = 1; // fine enough (or no instance at all): the scene-fitted grid
        }
    }
    data.cascades = cascadeLayoutFor(sceneBox, settings.globalResolution, settings.globalPadding,
                                     settings.globalMaxDistanceVoxels, maxCascades,
                                     data.finestVoxelWanted > 0.0f ? data.finestVoxelWanted : 1.0f);
    data.camera = scene.camera.position;
    data.global = cascadeGrid(data.cascades, 0, cascadeWindowFor(data.cascades, 0, data.camera));
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const scene::Instance& instance = scene.instances[i];
        const uint32_t volume = data.meshVolume[instance.mesh];
        if (volume != kNoVolume) {
            data.instances.push_back(makeInstanceDesc(data.atlas.volumes[volume], volume, instance.transform,
                                                      instance.mesh, i, data.global.voxelSize));
        }
    }
    return data;
}

} // namespace lumina::sdf
