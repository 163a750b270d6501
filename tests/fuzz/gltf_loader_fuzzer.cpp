// libFuzzer target for the glTF loader: every input is tried as a binary glTF and as glTF
// text, through the same code `lumina` uses. A SceneError is the expected answer to bad
// input; anything else (a crash, a sanitizer report, another exception, a leak of time or
// memory past libFuzzer's limits) is a bug. External files are off, so no input reads the
// file system. tests/fuzz/run_fuzzer.cmake builds and runs it.
#include "gi/scene/gltf_loader.h"
#include "gi/scene/scene_error.h"

#include <cstddef>
#include <cstdint>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace lumina::scene;
    const std::span<const uint8_t> bytes(data, size);
    // Budgets well inside libFuzzer's 2 GiB RSS limit (the defaults are sized for real scenes).
    const GltfLoadOptions options{.allowExternalFiles = false,
                                  .maxVertices = uint64_t(1) << 22,
                                  .maxTextureBytes = uint64_t(256) << 20};
    for (const bool binary : {true, false}) {
        try {
            (void)loadGltfMemory(bytes, binary, binary ? "fuzz.glb" : "fuzz.gltf", "", options);
        } catch (const SceneError&) {
        }
    }
    return 0;
}
