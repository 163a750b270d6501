#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): how much of the light that reaches `door`'s dark
# room through the gap around its shut door lumen finds, against the gap's width and the mesh
# SDFs' resolution (docs/gi.md, energy 48.). For each gap in LUMINA_GAPS (metres; scene files
# with "doorGap", the door still and shut) a path-traced reference at LUMINA_SIZE (pixel centres,
# LUMINA_REFERENCE_SPP samples), direct only, and lumen at every preset in LUMINA_PRESETS with
# each pair of SDF resolutions in LUMINA_RESOLUTIONS, "MESH/GLOBAL" (`lumina render
# --mesh-sdf-resolution MESH --global-sdf-resolution GLOBAL`; the presets' are 64/64).
# Prints "gap technique MESH/GLOBAL preset relMSE mean/reference" rows; writes door_gaps.txt
# under $OUT.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
gaps=${LUMINA_GAPS:-"0.01 0.02 0.05 0.1"}
resolutions=${LUMINA_RESOLUTIONS:-"64/64 64/128 64/256 256/256"}
presets=${LUMINA_PRESETS:-"low medium high"}
size=${LUMINA_SIZE:-256x256}
spp=${LUMINA_REFERENCE_SPP:-65536}

source scripts/gpu/figures.sh

{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown), $size, reference $spp spp"
  nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null
  mkdir -p /tmp/door_gaps
  for gap in $gaps; do
    scene=/tmp/door_gaps/door_gap_$gap.json
    printf '{ "generator": "door", "doorGap": %s }\n' "$gap" >"$scene"
    ref=/tmp/door_gaps/ref_$gap.exr
    timeout 600 $lumina reference "$scene" --size "$size" --spp "$spp" --pixel-centres --out "$ref" 2>&1 | tail -1
    timeout 120 $lumina render "$scene" --technique direct --size "$size" --frames 1 \
      --exr /tmp/door_gaps/direct.exr --out /tmp/door_gaps/direct.png >/dev/null 2>&1
    echo "$gap direct - - $(figures "$ref" /tmp/door_gaps/direct.exr)"
    for resolution in $resolutions; do
      for preset in $presets; do
        exr=/tmp/door_gaps/lumen_${gap}_${resolution%/*}_${resolution#*/}_$preset.exr
        timeout 300 $lumina render "$scene" --preset "$preset" --size "$size" --mesh-sdf-resolution \
          "${resolution%/*}" --global-sdf-resolution "${resolution#*/}" --exr "$exr" \
          --out /tmp/door_gaps/lumen.png >/dev/null 2>&1
        echo "$gap lumen $resolution $preset $(figures "$ref" "$exr")"
      done
    done
  done
} 2>&1 | tee "$out/door_gaps.txt"
