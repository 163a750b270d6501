#!/usr/bin/env bash
# Builds Lumina (Release) and gathers what the lent GPU machine needs into .devbin/:
# the executables, the compiled kernels and every shared library they link that the GPU
# machine lacks (it has no Vulkan loader; .gl/ carries that, see docs/gpu.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${LUMINA_GPU_BUILD:-$root/build-release}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build"
rm -rf "$root/.devbin"
mkdir -p "$root/.devbin/lib" "$root/.devbin/tests"
cp "$build/app/lumina" "$root/.devbin/"
cp -r "$build/shaders" "$root/.devbin/"
for test in "$build"/tests/*/*; do
  if [ -f "$test" ] && [ -x "$test" ]; then cp "$test" "$root/.devbin/tests/"; fi
done
for exe in "$root/.devbin/lumina" "$root"/.devbin/tests/*; do
  ldd "$exe" | awk '/=> \//{print $3}'
done | sort -u | grep -vE 'libc\.so|libm\.so|ld-linux|libvulkan|libpthread|libdl|librt' \
  | xargs -r -I{} cp {} "$root/.devbin/lib/"
# Built-in scenes that load a model from a Debian package (two_cylinder_engine: assimp-testmodels)
# name it by its absolute path; the GPU machine has no such package, so the files travel in
# .devbin/sysroot/ and prologue.sh puts them at the same paths there.
grep -ho '"gltf": *"/[^"]*"' "$root"/scenes/*/*.json | sed 's/.*"\(\/[^"]*\)"/\1/' | sort -u |
  while read -r model; do
    mkdir -p "$root/.devbin/sysroot$(dirname "$model")"
    cp "$model" "$root/.devbin/sysroot$model"
  done
du -sh "$root/.devbin"
git -C "$root" rev-parse --short HEAD > "$root/.devbin/commit" 2>/dev/null || true
