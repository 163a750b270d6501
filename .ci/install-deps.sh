#!/usr/bin/env bash
# Installs every Debian 12 package that Lumina's build, tests and tools need.
# Safe to run twice: apt-get install is idempotent. Works as root or with sudo.
# Then .ci/install-dxbc-tools.sh: vkd3d-compiler (DXBC) and Mesa 25's lavapipe for the D3D12
# run under Wine, unpacked into /opt/lumina/d3d12-tools (nothing installed system-wide).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git clang clang-format libclang-rt-14-dev
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-tools spirv-tools
  # libxrandr-dev: glfw3native.h includes Xrandr.h (the viewer's native X11 window handle)
  libglm-dev libglfw3-dev libxrandr-dev libimgui-dev libopenexr-dev libtinygltf-dev nlohmann-json3-dev libstb-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib
  assimp-testmodels
  # The Direct3D 12 backend, cross-compiled and run under Wine (.ci/build-d3d12-mingw.sh)
  g++-mingw-w64-x86-64 directx-headers-dev googletest wine64 xvfb xauth
  # EXR in the cross build (gi/image/exr_tinyexr.cpp); dpkg-source unpacks GLFW and Dear ImGui
  # (.ci/fetch-debian-sources.sh)
  libtinyexr-dev zlib1g-dev libz-mingw-w64-dev dpkg-dev
)

if [ "$(id -u)" -eq 0 ]; then
  sudo_cmd=()
elif command -v sudo >/dev/null 2>&1; then
  sudo_cmd=(sudo)
else
  echo "install-deps: run as root or install sudo first" >&2
  exit 1
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
"$(dirname "$0")/install-dxbc-tools.sh"
