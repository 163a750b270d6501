#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): what async compute buys `lumina render`
# (docs/performance.md, change 3). Each scene and technique at 1920x1080 for LUMINA_ASYNC_FRAMES
# frames (default 400, the first 100 left out), two frames in flight, no validation, with and
# with --async-compute off and on: the median wall time per frame (the GPU's throughput where the GPU
# is the longer side; the timings' frame row sums passes that overlap, so it does not show the
# gain), and the two final images compared (they must be identical: the same passes in the
# same order on the GPU). Writes $OUT/async_compute.txt.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
frames=${LUMINA_ASYNC_FRAMES:-400}
{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown)"
  .devbin/lumina --list-devices 2>&1 | head -5
  for run in "city --technique ddgi --preset low" "city --technique ddgi --preset medium" \
      "city --technique lumen --preset low" "atrium --technique ddgi --preset medium" \
      "atrium --technique lumen --preset medium" "cornell_box --technique ddgi --preset medium" \
      "cornell_box_moving --technique lumen --preset medium"; do
    for mode in one-queue async; do
      flag="--async-compute off"
      [ "$mode" = async ] && flag="--async-compute on"
      echo "== $run, $mode"
      # shellcheck disable=SC2086
      timeout 240 .devbin/lumina render $run --size 1920x1080 --frames "$frames" --warmup 100 --timings \
        $flag --out "/tmp/async-$mode.exr" 2>&1 | grep -E '^(wall time|async compute|  frame |render:)|rror'
    done
    .devbin/lumina compare /tmp/async-one-queue.exr /tmp/async-async.exr 2>&1 | grep -E 'relMSE|max error'
  done
} 2>&1 | tee "$out/async_compute.txt"
