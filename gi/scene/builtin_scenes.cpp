#include "gi/scene/builtin_scenes.h"

#include "gi/scene/generators/generators.h"

#include <array>
#include <cstdlib>

#ifdef _WIN32
#define WIN32_LEAN_AND_MEAN
#ifndef NOMINMAX // MinGW-w64's libstdc++ defines it already
#define NOMINMAX
#endif
#include <windows.h>
#endif

namespace lumina::scene {

namespace {

namespace fs = std::filesystem;

constexpr std::array kBuiltins = {
    BuiltinScene{"cornell_box", [] { return makeCornellBox(false); }},
    BuiltinScene{"cornell_box_point", [] { return makeCornellBox(true); }},
    BuiltinScene{"open_top_box", [] { return makeOpenTopBox(); }},
    BuiltinScene{"furnace_0.5", [] { return makeFurnace(0.5f); }},
    BuiltinScene{"furnace_0.8", [] { return makeFurnace(0.8f); }},
    BuiltinScene{"furnace_0.95", [] { return makeFurnace(0.95f); }},
    BuiltinScene{"furnace_0.99", [] { return makeFurnace(0.99f); }},
    BuiltinScene{"two_rooms", [] { return makeTwoRooms(); }},
    BuiltinScene{"sunlit_rooms", [] { return makeSunlitRooms(); }}, BuiltinScene{"atrium", nullptr},
    BuiltinScene{"city", nullptr},
    BuiltinScene{"two_cylinder_engine", nullptr}, // a glTF of assimp-testmodels
    // Dynamic scenes: their scene files animate them (docs/scenes.md, "Animation").
    BuiltinScene{"cornell_box_moving", nullptr}, // cornell_box's glTF, the short block sliding
    BuiltinScene{"atrium_day", nullptr},         // the atrium generator, the sun crossing the sky
    BuiltinScene{"door", nullptr},               // the door generator, the door swinging
};

std::optional<fs::path> executableDirectory() {
    std::error_code error;
#ifdef _WIN32
    wchar_t buffer[MAX_PATH];
    const DWORD length = GetModuleFileNameW(nullptr, buffer, MAX_PATH);
    if (length == 0 || length == MAX_PATH) {
        return std::nullopt;
    }
    return fs::path(std::wstring(buffer, length)).parent_path();
#else
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (error) {
        return std::nullopt;
    }
    return exe.parent_path();
#endif
}

bool holdsScenes(const fs::path& dir) {
    std::error_code error;
    return fs::is_regular_file(dir / "cornell_box" / "cornell_box.json", error);
}

} // namespace

std::span<const BuiltinScene> builtinScenes() {
    return kBuiltins;
}

bool isBuiltinScene(std::string_view name) {
    for (const BuiltinScene& scene : kBuiltins) {
        if (scene.name == name) {
            return true;
        }
    }
    return false;
}

std::optional<fs::path> findScenesDirectory() {
    if (const char* dir = std::getenv("LUMINA_SCENES_DIR"); dir && *dir && holdsScenes(dir)) {
        return fs::path(dir);
    }
    if (const char* source = std::getenv("LUMINA_SOURCE_DIR");
        source && *source && holdsScenes(fs::path(source) / "scenes")) {
        return fs::path(source) / "scenes";
    }
    if (const auto exe = executableDirectory()) {
        fs::path dir = *exe;
        for (int up = 0; up <= 3; ++up, dir = dir.parent_path()) {
            if (holdsScenes(dir / "scenes")) {
                return dir / "scenes";
            }
        }
    }
#ifdef LUMINA_SCENE_SOURCE_DIR
    if (holdsScenes(fs::path(LUMINA_SCENE_SOURCE_DIR) / "scenes")) {
        return fs::path(LUMINA_SCENE_SOURCE_DIR) / "scenes";
    }
#endif
    return std::nullopt;
}

} // namespace lumina::scene
