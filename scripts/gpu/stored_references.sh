#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): the stored references of the accuracy tests
# (tests/frame/data/SCENE_128x128.exr, 65,536 samples per pixel at pixel centres), and beside
# each, as a preview of what the tests will find, `lumina compare` of lumen at every preset
# and of direct light only against it, all at 128x128 (an animated scene at its first pose, held
# still, as the tests' harness renders it; SCENE@F at frame F, into SCENE_frameF_128x128.exr, as
# tests/frame/stored_reference.h names it). LUMINA_SCENES names the scenes. Writes refs.tgz (the
# EXRs) and refs.txt under $OUT.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out/refs"
source scripts/gpu/prologue.sh
source scripts/gpu/scene_entry.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
scenes=${LUMINA_SCENES:-"two_cylinder_engine atrium_day atrium city cornell_box_moving"}
figures() { $lumina compare "$1" "$2" 2>&1 | grep -E 'relMSE|mean' | tr '\n' ' '; }
for entry in $scenes; do
  scene_entry "$entry"
  ref=$out/refs/${entry_name}_128x128.exr
  /usr/bin/time -f "$entry: reference in %e s" $lumina reference "$scene" --size 128x128 --spp 65536 \
    --pixel-centres $pose --out "$ref" 2>&1 | tail -2
  for preset in low medium high; do
    $lumina render "$scene" --preset "$preset" --size 128x128 $pose --exr "/tmp/${entry_name}_$preset.exr" \
      --out "/tmp/${entry_name}_$preset.png" >/dev/null 2>&1
    echo "$entry lumen $preset: $(figures "$ref" "/tmp/${entry_name}_$preset.exr")"
  done
  $lumina render "$scene" --technique direct --size 128x128 --frames 1 $pose --exr "/tmp/${entry_name}_direct.exr" \
    --out "/tmp/${entry_name}_direct.png" >/dev/null 2>&1
  echo "$entry direct: $(figures "$ref" "/tmp/${entry_name}_direct.exr")"
done 2>&1 | tee "$out/refs.txt"
(cd "$out" && tar czf refs.tgz refs && rm -rf refs)
