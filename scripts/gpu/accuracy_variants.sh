#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): the 256² accuracy of lumen at every preset for
# several variants of the renderer, each a set of compiled kernels and/or extra `lumina render`
# flags, against 65,536-spp references (docs/gi.md's energy notes use it to measure a change before
# it lands). LUMINA_VARIANTS is a list of "name|kernel folder|flags" (folder relative to the
# repository, empty for .devbin/shaders; flags such as "--probe-spacing 12"); LUMINA_SCENES and
# LUMINA_PRESETS choose what is rendered (a scene may be SCENE@F, posed at frame F: scene_entry.sh). LUMINA_TIMING_SCENE (e.g. city) adds each variant's
# per-pass GPU times at 1920x1080 (300 frames, medians after 100, no validation).
# Prints "scene variant preset relMSE mean/reference" rows; writes accuracy_variants.txt under $OUT.
#   LUMINA_VARIANTS="base||  cosine|.devbin/shaders_cos|" bash scripts/gpu/accuracy_variants.sh
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
source scripts/gpu/scene_entry.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
variants=${LUMINA_VARIANTS:-"shipped||"}
scenes=${LUMINA_SCENES:-"cornell_box cornell_box_point two_rooms open_top_box sunlit_rooms"}
presets=${LUMINA_PRESETS:-"low medium high"}
size=${LUMINA_SIZE:-256x256}
spp=${LUMINA_REFERENCE_SPP:-65536}

source scripts/gpu/figures.sh

{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown), $size, reference $spp spp"
  nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null
  for entry in $scenes; do
    scene_entry "$entry"
    ref=/tmp/ref_$entry_name.exr
    cached_reference "$ref" "$size" "$spp"
    # shellcheck disable=SC2086 # pose is words
    timeout 120 $lumina render "$scene" --technique direct --size "$size" --frames 1 $pose --exr "/tmp/direct_$entry_name.exr" \
      --out "/tmp/direct_$entry_name.png" >/dev/null 2>&1
    echo "$entry direct - $(figures "$ref" "/tmp/direct_$entry_name.exr")"
    for variant in $variants; do
      IFS='|' read -r name folder flags <<<"$variant"
      for preset in $presets; do
        exr=/tmp/${entry_name}_${name}_$preset.exr
        # shellcheck disable=SC2086 # flags are words
        LUMINA_SHADER_DIR=$PWD/${folder:-.devbin/shaders} timeout 600 $lumina render "$scene" --preset "$preset" \
          --size "$size" $pose $flags --exr "$exr" --out /tmp/variant.png >/dev/null 2>&1
        echo "$entry $name $preset $(figures "$ref" "$exr")"
      done
    done
  done
  if [ -n "${LUMINA_TIMING_SCENE:-}" ]; then
    for variant in $variants; do
      IFS='|' read -r name folder flags <<<"$variant"
      for preset in $presets; do
        echo "== $LUMINA_TIMING_SCENE 1920x1080 $name $preset"
        # shellcheck disable=SC2086
        LUMINA_SHADER_DIR=$PWD/${folder:-.devbin/shaders} timeout 300 $lumina render "$LUMINA_TIMING_SCENE" \
          --preset "$preset" $flags --size 1920x1080 --frames 300 --warmup 100 --timings --out /tmp/timing.png 2>&1 |
          grep -E 'screen probes: |radiosity trace|^  frame |wall time'
      done
    done
  fi
} 2>&1 | tee "$out/accuracy_variants.txt"
