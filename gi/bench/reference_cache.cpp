#include "gi/bench/reference_cache.h"

#include "gi/core/cache_dir.h"
#include "gi/core/frame_context.h"
#include "gi/image/exr.h"
#include "gi/pathtracer/path_tracer.h"
#include "gi/pathtracer/path_tracer_scene.h"
#include "gi/sdf/sdf_cache.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <system_error>

namespace lumina::gi {

namespace {

// Bump when the path tracer's output changes for the same inputs: old references then miss.
constexpr uint32_t kReferenceFormatVersion = 1;
// Samples per submission: short enough that no submission runs long on lavapipe.
constexpr uint32_t kSamplesPerSubmission = 4;

template <typename T>
uint64_t hashValue(const T& value, uint64_t hash) {
    return sdf::fnv1a64(&value, sizeof(value), hash);
}

template <typename T>
uint64_t hashSpan(const std::vector<T>& values, uint64_t hash) {
    hash = hashValue(uint64_t(values.size()), hash);
    return values.empty() ? hash : sdf::fnv1a64(values.data(), values.size() * sizeof(T), hash);
}

} // namespace

std::filesystem::path defaultReferenceDirectory() {
    return cacheRoot() / "references";
}

uint64_t sceneDigest(const scene::Scene& scene) {
    uint64_t hash = hashValue(kReferenceFormatVersion, 14695981039346656037ull);
    for (const scene::Mesh& mesh : scene.meshes) {
        hash = hashSpan(mesh.positions, hash);
        hash = hashSpan(mesh.normals, hash);
        hash = hashSpan(mesh.uvs, hash);
        hash = hashSpan(mesh.indices, hash);
        hash = hashSpan(mesh.submeshes, hash);
    }
    for (const scene::Instance& instance : scene.instances) {
        hash = hashValue(instance.mesh, hash);
        hash = hashValue(instance.transform, hash);
    }
    for (const scene::Material& material : scene.materials) {
        hash = hashValue(material.baseColor, hash);
        hash = hashValue(material.baseColorTexture, hash);
        hash = hashValue(material.emission, hash);
        hash = hashValue(material.emissionTexture, hash);
        hash = hashValue(material.doubleSided, hash);
    }
    for (const scene::Texture& texture : scene.textures) {
        hash = hashValue(texture.width, hash);
        hash = hashSpan(texture.rgba8, hash);
    }
    for (const scene::Light& light : scene.lights) {
        const float fields[] = {light.color.x,        light.color.y,         light.color.z,
                                light.intensity,      light.range,           light.innerConeAngle,
                                light.outerConeAngle, light.position.x,      light.position.y,
                                light.position.z,     light.direction.x,     light.direction.y,
                                light.direction.z,    float(int(light.type))};
        hash = sdf::fnv1a64(fields, sizeof(fields), hash);
    }
    if (scene.skyEnvironment) { // only then: the keys of uniform skies stay as they were
        hash = hashValue(scene.skyEnvironment->width, hash);
        hash = hashSpan(scene.skyEnvironment->radiance, hash);
    }
    const scene::Camera& camera = scene.camera;
    const float cameraFields[] = {camera.position.x, camera.position.y, camera.position.z, camera.forward.x,
                                  camera.forward.y,  camera.forward.z,  camera.up.x,       camera.up.y,
                                  camera.up.z,       camera.fovY,       scene.sky.x,       scene.sky.y,
                                  scene.sky.z};
    return sdf::fnv1a64(cameraFields, sizeof(cameraFields), hash);
}

uint64_t referenceKey(const scene::Scene& scene, const ReferenceRequest& request) {
    const uint32_t fields[] = {request.width, request.height, request.spp, request.seed, request.maxBounces};
    return sdf::fnv1a64(fields, sizeof(fields), sceneDigest(scene));
}

std::filesystem::path referencePath(const std::filesystem::path& directory, const scene::Scene& scene,
                                    const ReferenceRequest& request) {
    char name[256];
    std::snprintf(name, sizeof(name), "%s_%ux%u_%uspp_%016llx.exr", scene.name.c_str(), request.width,
                  request.height, request.spp, static_cast<unsigned long long>(referenceKey(scene, request)));
    return directory / name;
}

image::Image rgbOf(const image::Image& source, const std::string& prefix) {
    image::Image out = image::Image::rgb(source.width(), source.height());
    for (const char* c : {"R", "G", "B"}) {
        const std::string name = prefix + "." + c;
        if (!source.hasChannel(name)) {
            throw image::ImageError("image has no channel '" + name + "'");
        }
        std::ranges::copy(source.channel(name), out.channel(c).begin());
    }
    return out;
}

Reference loadOrRenderReference(rhi::IDevice& device, PipelineCache& pipelines, const scene::Scene& scene,
                                const ReferenceRequest& request, const std::filesystem::path& directory,
                                const std::function<void(uint32_t, uint32_t)>& progress) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    Reference reference;
    reference.path = referencePath(directory, scene, request);
    std::error_code ignored;
    if (std::filesystem::exists(reference.path, ignored)) {
        try {
            reference.image = image::readExr(reference.path);
            if (reference.image.width() == request.width && reference.image.height() == request.height &&
                reference.image.hasChannel("indirect.R")) {
                reference.reused = true;
                reference.seconds = std::chrono::duration<double>(Clock::now() - start).count();
                return reference;
            }
        } catch (const image::ImageError&) {
            // A damaged or foreign file under our name: render it again below.
        }
    }

    const PathTracerScene traced(device, scene);
    PathTracer tracer(device, traced, scene,
                      {.width = request.width,
                       .height = request.height,
                       .maxBounces = request.maxBounces,
                       .seed = request.seed,
                       .aovs = true});
    rhi::CommandListHandle list = device.createCommandList();
    rhi::IQueue& queue = device.queue(rhi::QueueType::Graphics);
    for (uint64_t submission = 0; tracer.samples() < request.spp; ++submission) {
        list->begin();
        FrameContext frame(pipelines, *list, submission);
        tracer.recordSamples(frame, std::min(kSamplesPerSubmission, request.spp - tracer.samples()));
        list->end();
        queue.waitForValue(queue.submit(*list));
        if (progress) {
            progress(tracer.samples(), request.spp);
        }
    }
    const PathTracerResult result = tracer.readResult();
    if (result.nonFiniteSamples != 0) {
        throw std::runtime_error("reference of '" + scene.name +
                                 "': " + std::to_string(result.nonFiniteSamples) + " non-finite samples");
    }
    reference.image = result.image;
    std::filesystem::create_directories(directory);
    // Written under a temporary name and renamed, so an interrupted run leaves no torn file;
    // the name is this process's own, so bench shards sharing a cache never write one file.
    const std::filesystem::path partial =
        reference.path.string() + ".partial" + std::to_string(std::random_device{}());
    image::writeExr(partial, reference.image);
    std::filesystem::rename(partial, reference.path);
    reference.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return reference;
}

} // namespace lumina::gi
