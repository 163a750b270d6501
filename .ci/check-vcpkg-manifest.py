#!/usr/bin/env python3
"""Checks that vcpkg.json and CMakePresets.json keep up with the build (the Windows MSVC build
gets its dependencies from vcpkg, and CI has no Windows to notice a missing one):

- every find_package(X), pkg_check_modules(... X) and required find_path header in the
  CMake files maps, in PORTS below, to vcpkg ports that vcpkg.json lists (or to nothing: CMake's
  own modules, or libraries only the Linux or cross builds use, with the reason);
- every package of that table is still used, and every port of vcpkg.json is needed by one;
- the presets parse, the msvc presets use vcpkg's toolchain, and the mingw-d3d12 preset uses
  cmake/toolchains/mingw-w64.cmake.
A new find_package with no line in PORTS fails the check: add its port to vcpkg.json and here.

    python3 .ci/check-vcpkg-manifest.py
"""
import json
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent

# CMake package (or header) -> vcpkg ports providing it; None: needs no port, with why.
PORTS = {
    "Vulkan": ["vulkan-headers", "vulkan-loader"],
    "glm": ["glm"],
    "glm/glm.hpp": ["glm"],
    "nlohmann_json": ["nlohmann-json"],
    "OpenEXR": ["openexr"],
    "GTest": ["gtest"],
    "benchmark": ["benchmark"],
    "glfw3": ["glfw3"],
    "imgui": ["imgui"],
    "directx-headers": ["directx-headers"],
    "directx/d3d12.h": ["directx-headers"],
    "tiny_gltf.h": ["tinygltf"],
    "stb/stb_image.h": ["stb"],
    "stb_image_write.h": ["stb"],
    "Threads": None,  # CMake module
    "Git": None,  # CMake module, build info only
    "PkgConfig": None,  # Linux: Debian's imgui.pc
    "ZLIB": None,  # only with LUMINA_EXR_LIBRARY=tinyexr (the MinGW cross build); MSVC uses OpenEXR
    "tinyexr.h": None,  # idem
    "Python3": None,  # optional host tool: checks DXBC, built only on Linux (cmake/LuminaShaders.cmake)
}
# Ports that no find_package names: tools found with find_program (cmake/LuminaShaders.cmake).
TOOL_PORTS = {"glslang", "spirv-tools", "directx-dxc"}

FIND_PACKAGE = re.compile(r"^\s*find_package\(\s*([A-Za-z0-9_.-]+)", re.M)
PKG_CHECK = re.compile(r"^\s*pkg_check_modules\(\s*\w+(?:\s+(?:QUIET|REQUIRED|IMPORTED_TARGET|GLOBAL))*\s+([A-Za-z0-9_.-]+)", re.M)
FIND_PATH = re.compile(r"^\s*find_path\(\s*\w+\s+([A-Za-z0-9_./-]+\.h(?:pp)?)\b", re.M)


def cmake_files():
    for path in sorted(ROOT.rglob("*")):
        rel = path.relative_to(ROOT)
        if rel.parts[0].startswith("build") or rel.parts[0].startswith("."):
            continue
        if path.name == "CMakeLists.txt" or path.suffix == ".cmake":
            yield rel, path.read_text()


def main():
    errors = []
    manifest = json.loads((ROOT / "vcpkg.json").read_text())
    listed = {d if isinstance(d, str) else d["name"] for d in manifest["dependencies"]}

    used = {}
    for rel, text in cmake_files():
        if rel.parts[0] == "cmake" and rel.parts[1:2] == ("toolchains",):
            continue
        if rel.parts[:2] == ("cmake", "cross"):
            continue  # stand-ins for host packages in cross builds
        for pattern in (FIND_PACKAGE, PKG_CHECK, FIND_PATH):
            for name in pattern.findall(text):
                used.setdefault(name, str(rel))
    # The cross build's host headers (CMakeLists.txt's foreach over header folders) are not
    # find_path calls with a literal name: they are glm, nlohmann, stb, tinygltf, tinyexr.
    needed = set(TOOL_PORTS)
    for name, where in sorted(used.items()):
        if name not in PORTS:
            errors.append(f"{where}: find '{name}' has no vcpkg port in .ci/check-vcpkg-manifest.py PORTS")
            continue
        for port in PORTS[name] or []:
            needed.add(port)
            if port not in listed:
                errors.append(f"{where}: '{name}' needs vcpkg port '{port}', which vcpkg.json does not list")
    for name in sorted(set(PORTS) - set(used)):
        errors.append(f"PORTS names '{name}', which no CMake file finds any more: remove it")
    for port in sorted(listed - needed):
        errors.append(f"vcpkg.json lists '{port}', which nothing in the build finds")

    presets = json.loads((ROOT / "CMakePresets.json").read_text())
    configure = {p["name"]: p for p in presets["configurePresets"]}

    def resolved(name, key):
        preset = configure[name]
        while key not in preset and "inherits" in preset:
            preset = configure[preset["inherits"] if isinstance(preset["inherits"], str) else preset["inherits"][0]]
        return preset.get(key)

    for name in ("msvc", "msvc-d3d12"):
        if "vcpkg.cmake" not in (resolved(name, "toolchainFile") or ""):
            errors.append(f"CMakePresets.json: preset {name} does not use vcpkg's toolchain file")
    if resolved("mingw-d3d12", "toolchainFile") != "${sourceDir}/cmake/toolchains/mingw-w64.cmake":
        errors.append("CMakePresets.json: preset mingw-d3d12 does not use cmake/toolchains/mingw-w64.cmake")
    for build in presets.get("buildPresets", []):
        if build["configurePreset"] not in configure:
            errors.append(f"CMakePresets.json: build preset {build['name']} names an unknown configure preset")
    for test in presets.get("testPresets", []):
        if test["configurePreset"] not in configure:
            errors.append(f"CMakePresets.json: test preset {test['name']} names an unknown configure preset")

    for error in errors:
        print(f"check-vcpkg-manifest: {error}", file=sys.stderr)
    if errors:
        return 1
    print(f"check-vcpkg-manifest: {len(used)} finds, {len(listed)} vcpkg ports, presets: all consistent")
    return 0


if __name__ == "__main__":
    sys.exit(main())
