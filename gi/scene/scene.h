#pragma once
// The CPU scene model every consumer reads: the real-time renderer's upload, the path
// tracer, the SDF builder and the surface cache. Pure data, no GPU types. Units are those
// of units.h: lengths in scene units, light radiometric.
//
// Meshes hold geometry in object space; instances place a mesh in the world. A mesh may be
// instanced many times (columns of the atrium, buildings of the city), so per-instance
// counts (Scene::triangleCount) and per-mesh counts (Scene::meshTriangleCount) differ.
#include "gi/scene/scene_animation.h"

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lumina::scene {

inline constexpr uint32_t kNoTexture = std::numeric_limits<uint32_t>::max();

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::infinity()};
    glm::vec3 max{-std::numeric_limits<float>::infinity()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Bounds& other) {
        if (!other.empty()) {
            extend(other.min);
            extend(other.max);
        }
    }
    glm::vec3 centre() const { return (min + max) * 0.5f; }
    glm::vec3 size() const { return empty() ? glm::vec3(0.0f) : max - min; }
    // Closed boxes that share a point overlap; an empty box overlaps nothing.
    bool overlaps(const Bounds& other) const {
        return glm::all(glm::lessThanEqual(min, other.max)) && glm::all(glm::lessThanEqual(other.min, max));
    }
};

// The bounds of `local` after `transform`: its eight corners transformed (conservative).
Bounds transformBounds(const Bounds& local, const glm::mat4& transform);

// Decoded texels, 4 bytes per texel, rows top to bottom, as stored in the file: base colour
// and emission textures hold sRGB-encoded colour (glTF's rule), decoded by the consumer.
struct Texture {
    std::string name; // image name, else its URI, else "image N"
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> rgba8;
};

// Shading is diffuse for now: baseColor.rgb (times its texture) is the albedo. Metallic and
// roughness are kept for later (a glTF material without them gets glTF's defaults, 1 and 1;
// a material made in code defaults to a diffuse dielectric). Emission leaves the front face only
// (counter-clockwise winding) unless doubleSided.
struct Material {
    std::string name;
    glm::vec4 baseColor{1.0f}; // linear RGBA factor
    uint32_t baseColorTexture = kNoTexture;
    glm::vec3 emission{0.0f}; // radiance: glTF emissiveFactor x KHR_materials_emissive_strength
    uint32_t emissionTexture = kNoTexture;
    float metallic = 0.0f;
    float roughness = 1.0f;
    bool doubleSided = false;
};

// A run of a mesh's index buffer drawn with one material.
struct Submesh {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    uint32_t material = 0;
};

// An indexed triangle list. normals and uvs have one entry per position (uvs are zero when
// the source had none); normals are unit length. Front faces wind counter-clockwise.
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;
    std::vector<Submesh> submeshes;
    Bounds bounds; // object space

    uint64_t triangleCount() const { return indices.size() / 3; }
};

// A mesh placed in the world. A transform with a negative determinant mirrors, and so
// flips the winding of the mesh's front faces.
struct Instance {
    uint32_t mesh = 0;
    glm::mat4 transform{1.0f};
    std::string name;
};

enum class LightType { Directional, Point, Spot };

const char* lightTypeName(LightType type);

// Intensity in scene units (units.h): irradiance for directional lights, I with irradiance
// I/d^2 for point and spot lights. The light's RGB strength is color * intensity.
struct Light {
    LightType type = LightType::Point;
    std::string name;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float range = 0.0f;          // scene units; 0: unlimited
    float innerConeAngle = 0.0f; // radians from the axis, spot only
    float outerConeAngle = 0.78539816f;
    glm::vec3 position{0.0f};               // world space; point and spot
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; // world space, unit: where the light travels

    glm::vec3 strength() const { return color * intensity; }
    bool operator==(const Light&) const = default;
};

// Indices of the lights that differ between two light lists of the same scene: edited ones, and
// every index only one of them has (added or removed).
std::vector<uint32_t> changedLights(std::span<const Light> before, std::span<const Light> after);

// A perspective camera in world space; forward and up are unit length and orthogonal,
// the image's right is cross(forward, up). The aspect ratio is the image's.
struct Camera {
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovY = 0.78539816f; // vertical field of view, radians
    float nearPlane = 0.1f;   // scene units
    float farPlane = 1000.0f; // scene units; finishCamera makes it finite

    glm::vec3 right() const { return glm::normalize(glm::cross(forward, up)); }
};

struct ImageSize {
    uint32_t width = 1280;
    uint32_t height = 720;
};

struct Units {
    double metresPerUnit = 1.0;
};

// What the loader repaired or ignored: a documented repair is never silent.
struct LoadReport {
    std::vector<std::string> warnings;
    uint64_t degenerateTrianglesDropped = 0;
    uint64_t nonTrianglePrimitivesSkipped = 0;
    uint64_t normalsRepaired = 0;
};

// An equirectangular sky (docs/scenes.md, "Sky"): texel (x, y) holds the radiance arriving from
// the direction at longitude 2 pi ((x + 0.5) / width - 0.5) about +y, measured from -z towards
// +x, and polar angle pi (y + 0.5) / height from +y: row 0 is the zenith, the middle column of
// the image lies towards -z. sky_environment.h reads one from an EXR and samples it.
struct SkyEnvironment {
    std::filesystem::path file;
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<glm::vec3> radiance; // rows top to bottom, the file's texels x intensity
    float intensity = 1.0f;          // the factor already applied to `radiance`
};

// A DDGI probe volume placed by the scene file ("ddgiVolumes"): probes at the centres of `counts`
// cells dividing `box` (docs/ddgi.md).
struct ProbeVolume {
    Bounds box;
    glm::uvec3 counts{16};
    bool operator==(const ProbeVolume&) const = default;
};

struct Scene {
    std::string name;                 // built-in name, or the file's stem
    std::filesystem::path sourceFile; // the scene file or glTF that was loaded
    std::filesystem::path gltfFile;   // empty for generated scenes
    std::string generator;            // "atrium", "city", or empty
    std::string description;

    std::vector<Mesh> meshes;
    std::vector<Instance> instances;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Light> lights;
    Camera camera;
    bool cameraFromFile = false; // false: framed from the bounds
    glm::vec3 sky{0.0f};         // uniform sky radiance; ignored when skyEnvironment is set
    std::optional<SkyEnvironment> skyEnvironment;
    bool defaultLight = false; // the loader added the default sun and sky (default_light.h)
    ImageSize image;
    std::string technique;                 // GI technique name; empty: the renderer's default
    std::string preset;                    // quality preset name; empty: the renderer's default
    std::vector<ProbeVolume> probeVolumes; // DDGI volumes; empty: fitted to the scene
    Units units;
    LoadReport report;
    // What moves and changes over time (scene_animation.h); animateScene(scene, frame) applies it.
    // The loaders leave the scene at frame 0; the rest poses the tracks start from live in it.
    SceneAnimation animation;
    float framesPerSecond = 60.0f; // animation time = frame / framesPerSecond (scene file key)

    uint64_t triangleCount() const; // summed over instances: what is drawn
    uint64_t meshTriangleCount() const;
    uint64_t vertexCount() const; // over meshes
    Bounds worldBounds() const;
    float aspect() const { return float(image.width) / float(image.height); }
    // Whether any light reaches the scene from the sky (uniform or environment).
    bool hasSky() const;
};

// A camera outside `bounds` looking along -z at its centre, far enough to see all of it.
Camera frameBounds(const Bounds& bounds, float fovY);

// Gives a scene without a camera one framing its bounds, and a camera with an infinite far
// plane (glTF's zfar absent) one beyond the scene's farthest corner.
void finishCamera(Scene& scene);

} // namespace lumina::scene
