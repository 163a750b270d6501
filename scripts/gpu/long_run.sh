#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): the long run under change of docs/gi_tests.md.
# tests/frame/dynamic_long_run_test.cpp plays tests/frame/data/atrium_sun_and_column.json (the sun
# and a column moving, a 1,200-frame loop) for LUMINA_LONG_RUN_FRAMES frames (default here
# 100,000) at 64 x 64, low preset, without validation (the frame times are the renderer's own),
# and checks the image finite on the frames it reads back and every probe history every 500 frames, the indirect term's frame-to-frame change bounded, and no growth
# of GPU memory or frame time from the second loop to the last. Needs
# .devbin/tests/dynamic_long_run_test (scripts/gpu/package.sh). Writes $OUT/long_run.txt.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
# The frame-to-frame change is measured on every 20th pair of frames: a readback costs more than a
# frame here, and 100,000 frames with one each would not fit a 10-minute call.
export LUMINA_LONG_RUN_FRAMES=${LUMINA_LONG_RUN_FRAMES:-100000} LUMINA_LONG_RUN_VALIDATION=0
export LUMINA_LONG_RUN_STEP_EVERY=${LUMINA_LONG_RUN_STEP_EVERY:-20}
{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown)"
  .devbin/lumina --list-devices 2>&1 | head -5
  echo "== dynamic_long_run_test, $LUMINA_LONG_RUN_FRAMES frames, validation off"
  start=$(date +%s)
  timeout "${LUMINA_LONG_RUN_TIMEOUT:-580}" .devbin/tests/dynamic_long_run_test --gtest_filter='*vulkan*'
  echo "exit $? after $(( $(date +%s) - start )) s"
} 2>&1 | tee "$out/long_run.txt"
