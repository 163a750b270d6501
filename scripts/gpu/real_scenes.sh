#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): the real-scene figures of README and docs/gi.md.
#   1. every scene x preset at 1728x864 and 1920x1080: per-pass GPU times (median of frames
#      100..300, no validation), atlas occupancy and cards per level of detail, GPU memory per
#      subsystem;
#   2. accuracy at 256x256: lumen (converged) and direct-only against path-traced references
#      (LUMINA_REFERENCE_SPP samples, default 16384).
# Every result file names the device, the driver and the commit (the --timings-json header and
# the first lines of real_scenes.txt). Writes under $OUT.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
scenes=${LUMINA_SCENES:-"cornell_box atrium city"}
accuracy_scenes=${LUMINA_ACCURACY_SCENES:-"atrium"}
presets=${LUMINA_PRESETS:-"low medium high"}
sizes=${LUMINA_SIZES:-"1728x864 1920x1080"}
spp=${LUMINA_REFERENCE_SPP:-16384}
{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown)"
  $lumina --list-devices 2>&1 | head -5
  for scene in $scenes; do
    for size in $sizes; do
      for preset in $presets; do
        echo "== $scene $preset $size"
        start=$(date +%s.%N)
        timeout 300 $lumina render "$scene" --preset "$preset" --size "$size" --frames 300 --warmup 100 \
          --timings --timings-json "$out/t_${scene}_${preset}_${size}.json" --out "/tmp/${scene}_${preset}_${size}.png" \
          2>&1 | grep -v '^frame '
        echo "exit ${PIPESTATUS[0]}, wall $(echo "$(date +%s.%N) - $start" | bc) s"
      done
    done
  done
  for scene in $accuracy_scenes; do
    echo "== accuracy $scene 256x256, reference $spp spp"
    timeout 300 $lumina reference "$scene" --size 256x256 --spp "$spp" --pixel-centres --out "/tmp/ref_$scene.exr" 2>&1 | tail -2
    for preset in $presets; do
      timeout 300 $lumina render "$scene" --preset "$preset" --size 256x256 --out "/tmp/lumen_${scene}_$preset.png" \
        --exr "/tmp/lumen_${scene}_$preset.exr" 2>&1 | grep -E '^(frames|surface)'
      echo "lumen $preset: $($lumina compare "/tmp/ref_$scene.exr" "/tmp/lumen_${scene}_$preset.exr" 2>&1 | tr '\n' ' ')"
    done
    timeout 120 $lumina render "$scene" --technique direct --size 256x256 --out "/tmp/direct_$scene.png" \
      --exr "/tmp/direct_$scene.exr" >/dev/null 2>&1
    echo "direct: $($lumina compare "/tmp/ref_$scene.exr" "/tmp/direct_$scene.exr" 2>&1 | tr '\n' ' ')"
  done
} 2>&1 | tee "$out/real_scenes.txt"
# Images of the default view at medium, 1728x864, for the README.
(cd /tmp && tar czf "$out/images.tgz" *_medium_1728x864.png lumen_*_medium.png direct_*.png 2>/dev/null)
