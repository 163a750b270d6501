#!/usr/bin/env bash
# On the development machine: gathers the libFuzzer targets (built by the ctest test fuzz.build
# into build/tests/fuzz/build), the libraries they load, their seed corpora (the same globs as
# tests/fuzz/CMakeLists.txt) and dictionaries into .fuzz/, for long fuzzing runs on a machine
# with more cores (scripts/gpu/fuzz_long.sh; docs/gi_tests.md, "Fuzzing").
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${LUMINA_FUZZ_BUILD:-$root/build/tests/fuzz/build}
dest=$root/.fuzz
mkdir -p "$dest/bin" "$dest/lib" "$dest/dict"
assimp=/usr/share/assimp/models
declare -A seeds=(
  [gltf_loader]="$root/scenes/*.gltf $assimp/glTF2/*.gltf $assimp/glTF2/*.glb $assimp/glTF/*.gltf $assimp/glTF/*.glb"
  [scene_file]="$root/scenes/*.json"
  [png_reader]="$root/tests/fuzz/seeds/png_reader/* $assimp/glTF2/*.png $assimp/glTF2/*.jpg"
  [exr_openexr]="$root/tests/golden/data/*.exr"
  [exr_tinyexr]="$root/tests/golden/data/*.exr"
  [cli_args]="$root/tests/fuzz/seeds/cli_args/*"
)
shopt -s nullglob globstar
for name in "${!seeds[@]}"; do
  # Without DWARF (function names stay for the reports): the folder travels to another machine.
  strip --strip-debug -o "$dest/bin/${name}_fuzzer" "$build/${name}_fuzzer"
  mkdir -p "$dest/seeds/$name"
  # Seed globs are recursive as in run_fuzzer.cmake; files over 64 KiB are left out as there.
  set -f # the patterns are globbed below, recursively
  patterns=(${seeds[$name]} "$root/tests/fuzz/regressions/$name/*")
  set +f
  for pattern in "${patterns[@]}"; do
    dir=$(dirname "$pattern")
    for f in "$dir"/**/$(basename "$pattern"); do
      if [ -f "$f" ] && [ "$(stat -c %s "$f")" -le 65536 ]; then
        cp "$f" "$dest/seeds/$name/$(echo "$f" | md5sum | cut -c1-12)_$(basename "$f")"
      fi
    done
  done
  ldd "$build/${name}_fuzzer" | awk '/=> \// {print $3}' | { grep -E 'OpenEXR|Imath|Iex|IlmThread' || true; } | xargs -r cp -L -t "$dest/lib/"
done
cp "$root"/tests/fuzz/*.dict "$dest/dict/"
for name in "${!seeds[@]}"; do echo "$name: $(ls "$dest/seeds/$name" | wc -l) seeds"; done
du -sh "$dest"
