#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): the stored references of the accuracy tests
# (tests/frame/data/SCENE_128x128.exr, 65,536 samples per pixel at pixel centres), and beside
# each, as a preview of what the tests will find, `lumina compare` of lumen at every preset
# and of direct light only against it, all at 128x128 (an animated scene at its first pose, held
# still, as the tests' harness renders it). LUMINA_SCENES names the scenes. Writes refs.tgz (the
# EXRs) and refs.txt under $OUT.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out/refs"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
scenes=${LUMINA_SCENES:-"two_cylinder_engine atrium_day atrium city cornell_box_moving"}
figures() { $lumina compare "$1" "$2" 2>&1 | grep -E 'relMSE|mean' | tr '\n' ' '; }
for scene in $scenes; do
  ref=$out/refs/${scene}_128x128.exr
  pose=""
  if $lumina info "$scene" 2>/dev/null | grep '^  animation' | grep -qv ' none$'; then
    pose="--animation-frame 0"
  fi
  /usr/bin/time -f "$scene: reference in %e s" $lumina reference "$scene" --size 128x128 --spp 65536 \
    --pixel-centres --out "$ref" 2>&1 | tail -2
  for preset in low medium high; do
    $lumina render "$scene" --preset "$preset" --size 128x128 $pose --exr "/tmp/${scene}_$preset.exr" \
      --out "/tmp/${scene}_$preset.png" >/dev/null 2>&1
    echo "$scene lumen $preset: $(figures "$ref" "/tmp/${scene}_$preset.exr")"
  done
  $lumina render "$scene" --technique direct --size 128x128 --frames 1 $pose --exr "/tmp/${scene}_direct.exr" \
    --out "/tmp/${scene}_direct.png" >/dev/null 2>&1
  echo "$scene direct: $(figures "$ref" "/tmp/${scene}_direct.exr")"
done 2>&1 | tee "$out/refs.txt"
(cd "$out" && tar czf refs.tgz refs && rm -rf refs)
