#include "gi/scene/gltf_loader.h"

#include "gi/scene/gltf_internal.h"
#include "gi/scene/gltf_precheck.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <new>
#include <string_view>

namespace lumina::scene {

namespace {

namespace fs = std::filesystem;

// Larger external buffers are refused: 4 GiB is beyond what glTF's 32-bit GLB can address.
constexpr uint64_t kMaxExternalFileBytes = uint64_t(1) << 32;

struct FileAccess {
    bool allowExternal = true;
};

bool fileExists(const std::string& path, void* user) {
    std::error_code error;
    return static_cast<FileAccess*>(user)->allowExternal && fs::is_regular_file(path, error);
}

std::string expandFilePath(const std::string& path, void*) {
    return path;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    if (!static_cast<FileAccess*>(user)->allowExternal) {
        *err += "external file '" + path + "' not read: only embedded data is allowed here\n";
        return false;
    }
    std::error_code error;
    const auto size = fs::file_size(path, error);
    if (error || !fs::is_regular_file(path, error) || size > kMaxExternalFileBytes) {
        *err += "cannot read '" + path + "' (missing, not a regular file, or larger than 4 GiB)\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(size_t(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
        *err += "cannot read '" + path + "'\n";
        return false;
    }
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    *err += "writing is not supported\n";
    return false;
}

// Keeps an image's encoded bytes; gltf_textures.cpp decodes those that materials use. Images
// in a bufferView are read from it later, through bounds-checked code.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    image->as_is = true;
    if (image->bufferView < 0 && bytes != nullptr && size > 0) {
        image->image.assign(bytes, bytes + size);
    }
    return true;
}

// tinygltf's multi-line messages on one line.
std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) {
        text.pop_back();
    }
    std::replace(text.begin(), text.end(), '\n', ';');
    return text.empty() ? "unknown error" : text;
}

void checkVersionAndExtensions(const gltf::Context& context) {
    const tinygltf::Model& model = context.model;
    if (model.asset.version.rfind("2.", 0) != 0) {
        context.fail("glTF version '" + model.asset.version + "' is not supported (glTF 2.0 only)");
    }
    for (const std::string& name : model.extensionsRequired) {
        if (!isSupportedRequiredExtension(name)) {
            context.fail("requires extension " + name + ", which Lumina does not support");
        }
    }
}

// Drops meshes no instance draws, so counts describe the scene as drawn.
void pruneUnusedMeshes(Scene& scene) {
    std::vector<bool> used(scene.meshes.size(), false);
    for (const Instance& instance : scene.instances) {
        used[instance.mesh] = true;
    }
    std::vector<uint32_t> newIndex(scene.meshes.size(), 0);
    std::vector<Mesh> kept;
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        if (used[i]) {
            newIndex[i] = uint32_t(kept.size());
            kept.push_back(std::move(scene.meshes[i]));
        }
    }
    for (Instance& instance : scene.instances) {
        instance.mesh = newIndex[instance.mesh];
    }
    scene.meshes = std::move(kept);
}

bool usesMaterial(const Scene& scene, uint32_t material) {
    for (const Mesh& mesh : scene.meshes) {
        for (const Submesh& submesh : mesh.submeshes) {
            if (submesh.material == material) {
                return true;
            }
        }
    }
    return false;
}

Scene convertModel(const tinygltf::Model& model, const fs::path& file, const GltfLoadOptions& options) {
    Scene scene;
    scene.name = file.stem().string();
    scene.sourceFile = file;
    scene.gltfFile = file;
    scene.units.metresPerUnit = options.metresPerUnit;
    const gltf::Context context{model, file, options, scene.report};
    checkVersionAndExtensions(context);
    gltf::convertMaterials(context, scene);
    const auto defaultMaterial = uint32_t(scene.materials.size());
    const std::vector<int64_t> meshIndex = gltf::convertMeshes(context, scene, defaultMaterial);
    if (usesMaterial(scene, defaultMaterial)) {
        scene.materials.push_back(Material{.name = "default"});
    }
    const gltf::NodeOrigins origins = gltf::convertNodes(context, meshIndex, scene);
    gltf::convertAnimations(context, origins, scene);
    pruneUnusedMeshes(scene);
    if (scene.instances.empty()) {
        context.fail(
            std::string("the scene is empty: no node draws a triangle") +
            (scene.report.nonTrianglePrimitivesSkipped != 0 ? " (its points and lines are skipped)" : ""));
    }
    animateScene(scene, 0); // a loaded scene shows its first frame
    finishCamera(scene);
    return scene;
}

std::vector<uint8_t> readFile(const fs::path& file) {
    std::error_code error;
    if (!fs::exists(file, error)) {
        throw SceneError(file, "no such file");
    }
    if (!fs::is_regular_file(file, error)) {
        throw SceneError(file, "not a regular file");
    }
    const auto size = fs::file_size(file, error);
    if (error || size > kMaxExternalFileBytes) {
        throw SceneError(file, "cannot read (larger than 4 GiB?)");
    }
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    std::ifstream in(file, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) {
        throw SceneError(file, "cannot read");
    }
    return bytes;
}

} // namespace

Scene loadGltfMemory(std::span<const uint8_t> bytes, bool binary, const fs::path& file,
                     const fs::path& baseDir, const GltfLoadOptions& options) {
    if (bytes.size() >= kMaxExternalFileBytes) {
        throw SceneError(file, "larger than 4 GiB");
    }
    if (bytes.empty()) {
        throw SceneError(file, "the file is empty");
    }
    const GltfContainer container = readGltfContainer(bytes, binary, file);
    precheckGltfJson(container.json, file);

    FileAccess access{options.allowExternalFiles};
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepEncodedImage, nullptr);
    loader.SetFsCallbacks({fileExists, expandFilePath, readWholeFile, refuseWrite, &access});
    tinygltf::Model model;
    std::string err, warn;
    bool ok = false;
    try {
        const std::string base = baseDir.string();
        ok =
            binary
                ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), base)
                : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                             unsigned(bytes.size()), base);
    } catch (const std::exception& error) {
        throw SceneError(file, std::string("malformed glTF: ") + error.what());
    }
    if (!ok) {
        throw SceneError(file, "malformed glTF: " + oneLine(err));
    }
    Scene scene;
    try {
        scene = convertModel(model, file, options);
    } catch (const std::bad_alloc&) {
        throw SceneError(file, "out of memory while converting the glTF");
    }
    if (!warn.empty()) {
        scene.report.warnings.push_back("tinygltf: " + oneLine(warn));
    }
    return scene;
}

Scene loadGltfFile(const fs::path& file, const GltfLoadOptions& options) {
    const std::vector<uint8_t> bytes = readFile(file);
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    const bool binary =
        extension == ".glb" || (extension != ".gltf" && bytes.size() >= 4 &&
                                std::string_view(reinterpret_cast<const char*>(bytes.data()), 4) == "glTF");
    return loadGltfMemory(bytes, binary, file, file.parent_path(), options);
}

} // namespace lumina::scene
