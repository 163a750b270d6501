#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): per-pass GPU timings of the lumen GI at
# 1920x1080 for each preset, with validation, after the surface cache has converged (the
# median over frames 100..300 is the steady state; the table's runs column shows how often the
# surface-cache passes ran while converging). Writes the tables and JSON under $OUT.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
scenes=${LUMINA_TIMING_SCENES:-"cornell_box cornell_box_point open_top_box"}
presets=${LUMINA_TIMING_PRESETS:-"low medium high"}
for scene in $scenes; do
  for preset in $presets; do
    echo "== $scene $preset 1920x1080"
    timeout 120 .devbin/lumina render "$scene" --preset "$preset" --size 1920x1080 --frames 300 --warmup 100 \
      --timings --timings-json "$out/timings_${scene}_${preset}.json" --out "$out/${scene}_${preset}.png" \
      --validation 2>&1 | grep -v '^frame '
  done
done 2>&1 | tee "$out/lumen_timings.txt"
