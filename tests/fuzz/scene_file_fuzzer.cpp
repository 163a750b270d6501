// libFuzzer target for scene files (JSON, docs/scenes.md): every input goes through the
// parser `lumina` uses for a .json scene. A SceneError is the expected answer to bad input;
// anything else is a bug. Parsing reads no other file (the glTF a scene names is loaded
// later, by the scene loader), so no input reaches the file system.
#include "gi/scene/scene_error.h"
#include "gi/scene/scene_file.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    try {
        (void)lumina::scene::parseSceneFileText(std::string_view(reinterpret_cast<const char*>(data), size),
                                                "fuzz.json");
    } catch (const lumina::scene::SceneError&) {
    }
    return 0;
}
