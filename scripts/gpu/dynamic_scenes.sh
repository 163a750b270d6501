#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): the dynamic-scene figures of docs/dynamic_scenes.md
# and the README.
#   1. `lumina bench --change-frames`: for cornell_box_moving, door and atrium_day, each real-time
#      technique and preset plays the animation for LUMINA_CHANGE_FRAMES frames, holds the pose,
#      and counts the frames and GPU ms until it is within relMSE 0.01 of a fresh converged render
#      of that pose; with the frame cost while moving against static (change_response.csv);
#   2. per-pass timings while the animation plays (--timings, no validation), per scene at 1920x1080;
#   3. the README's door strip: the door scene after 60, 90, 120, 150 and 180 frames of its animation;
#   4. the `long` tests (tests/frame/dynamic_stress_test.cpp: 1,000 frames of atrium_day), which
#      CI leaves out; needs .devbin/tests/dynamic_stress_test.
# Every result names the device, driver and commit. Writes under $OUT.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
scenes=${LUMINA_SCENES:-"cornell_box_moving door atrium_day"}
size=${LUMINA_BENCH_SIZE:-256x256}
change_frames=${LUMINA_CHANGE_FRAMES:-120}
{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown)"
  $lumina --list-devices 2>&1 | head -5
  echo "== bench --change-frames $change_frames at $size"
  timeout 900 $lumina bench --scenes "$(echo "$scenes" | tr ' ' ',')" --techniques direct,lumen \
    --presets low,medium,high --size "$size" --frames 64 --reference-spp 1024 --change-frames "$change_frames" \
    --out "$out/bench" --no-plot 2>&1 | grep -v '^  reference .*spp$'
  echo "exit ${PIPESTATUS[0]}"
  for scene in $scenes; do
    echo "== $scene medium 1920x1080, 300 frames of its animation"
    timeout 300 $lumina render "$scene" --preset medium --size 1920x1080 --frames 300 --warmup 60 --timings \
      --timings-json "$out/t_${scene}_moving.json" --out "/tmp/${scene}_moving.png" 2>&1 | grep -v '^frame '
    echo "exit ${PIPESTATUS[0]}"
  done
  for frames in 60 90 120 150 180; do
    timeout 120 $lumina render door --preset high --size 640x360 --frames "$frames" \
      --out "/tmp/door_strip_$frames.png" 2>&1 | grep -E '^(animation|wrote)'
  done
  if [ -x .devbin/tests/dynamic_stress_test ]; then
    echo "== long: dynamic_stress_test"
    timeout 600 .devbin/tests/dynamic_stress_test 2>&1 | tail -15
  fi
} 2>&1 | tee "$out/dynamic_scenes.txt"
(cd /tmp && tar czf "$out/images.tgz" door_strip_*.png *_moving.png 2>/dev/null)
(cd "$out" && tar czf results.tgz bench t_*.json && rm -rf bench t_*.json)
