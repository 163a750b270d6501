#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): the same renders with several builds of the kernels,
# for a change meant to keep every image and lower a pass's cost (the radiosity trace's single
# march loop, docs/surface_cache.md#cost-of-the-radiosity-trace). Each set is a folder of compiled
# kernels carried in .devbin (a build's shaders/ folder, or one with some kernels replaced).
#   LUMINA_KERNEL_SETS  "name=folder ..." (default "current=.devbin/shaders"); the first is the baseline
#   LUMINA_SCENES, LUMINA_PRESETS, LUMINA_SIZE, LUMINA_FRAMES  what is rendered (default city,
#                       medium, 1920x1080, 200 frames from the first: the surface cache's passes run
#                       while it converges, and their medians are over the frames they ran in)
# Per render: the passes' median GPU times (--timings, no validation) and the image's relMSE against
# the baseline set's. Writes kernel_variants.txt under $OUT.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
sets=${LUMINA_KERNEL_SETS:-"current=.devbin/shaders"}
scenes=${LUMINA_SCENES:-city}
presets=${LUMINA_PRESETS:-medium}
size=${LUMINA_SIZE:-1920x1080}
frames=${LUMINA_FRAMES:-200}
{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown)"
  nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null
  for scene in $scenes; do
    for preset in $presets; do
      baseline=
      for set in $sets; do
        name=${set%%=*}
        folder=${set#*=}
        image=/tmp/${scene}_${preset}_${name}.exr
        echo "== $scene $preset $size, kernels: $name ($folder)"
        LUMINA_SHADER_DIR=$PWD/$folder timeout 240 .devbin/lumina render "$scene" --preset "$preset" \
          --size "$size" --frames "$frames" --timings --out "$image" 2>&1 | grep -vE '^frame [0-9]+/'
        if [ -z "$baseline" ]; then
          baseline=$image
        else
          echo "image against the $(basename "$baseline" .exr) kernels:"
          .devbin/lumina compare "$baseline" "$image" 2>&1 | grep -E 'relMSE|mean'
        fi
      done
    done
  done
} 2>&1 | tee "$out/kernel_variants.txt"
