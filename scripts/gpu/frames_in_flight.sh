#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): what frames in flight buy `lumina render`
# (docs/performance.md, "Frames in flight"). Each scene and technique at 1920x1080 for
# LUMINA_FIF_FRAMES frames (default 400, the first 100 left out), with 1, 2 and 3 frames in
# flight, no validation: the median GPU frame time from the timestamps and the median wall
# time per frame (CPU recording and submission, which waits only when the GPU is behind).
# Writes $OUT/frames_in_flight.txt.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
frames=${LUMINA_FIF_FRAMES:-400}
{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown)"
  .devbin/lumina --list-devices 2>&1 | head -5
  for run in "cornell_box --technique direct" "cornell_box --technique lumen --preset low" \
      "atrium --technique lumen --preset medium" "city --technique direct"; do
    for n in 1 2 3; do
      echo "== $run, $n frame(s) in flight"
      # shellcheck disable=SC2086
      timeout 240 .devbin/lumina render $run --size 1920x1080 --frames "$frames" --warmup 100 --timings \
        --frames-in-flight "$n" --out /tmp/fif.png 2>&1 | grep -E '^(wall time|  frame |render:)|rror'
    done
  done
} 2>&1 | tee "$out/frames_in_flight.txt"
