#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): issue 20's performance matrix. For every scene x
# size x technique x preset, `lumina render` without validation, 300 frames of which the first
# 100 are left out (the surface cache converges meanwhile; passes that ran only then show in the
# runs column), per-pass median GPU ms as JSON (each file names the commit, device, driver and
# API), and the GPU memory per subsystem from the render log. Then scripts/perf_tables.py turns
# the JSON into the README's tables. Writes under $OUT; packs everything into perf.tgz.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out/perf"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
lumina=.devbin/lumina
scenes=${LUMINA_SCENES:-"cornell_box atrium city"}
sizes=${LUMINA_SIZES:-"1280x720 1920x1080 3840x2160"}
configs=${LUMINA_CONFIGS:-"direct:medium lumen:low lumen:medium lumen:high ddgi:low ddgi:medium ddgi:high sh-grid:low sh-grid:medium sh-grid:high"}
frames=${LUMINA_FRAMES:-300}
warmup=${LUMINA_WARMUP:-100}
# Runs not started by then are left out and named in perf.log, so that one device call still
# brings back what it measured.
deadline=$(( $(date +%s) + ${LUMINA_PERF_BUDGET_S:-540} ))
{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown)"
  nvidia-smi --query-gpu=name,driver_version,clocks.max.sm,clocks.max.mem --format=csv 2>/dev/null
  $lumina --list-devices 2>&1 | head -5
  for scene in $scenes; do
    for size in $sizes; do
      for config in $configs; do
        technique=${config%%:*}
        preset=${config##*:}
        name="${scene}_${technique}_${preset}_${size}"
        echo "== $scene $technique $preset $size"
        if [ "$(date +%s)" -ge "$deadline" ]; then
          echo "skipped: past the time budget"
          continue
        fi
        timeout 240 $lumina render "$scene" --technique "$technique" --preset "$preset" --size "$size" \
          --frames "$frames" --warmup "$warmup" --timings-json "$out/perf/$name.json" --out "/tmp/$name.png" \
          2>&1 | grep -E "^(GPU memory|surface cache|error)"
        echo "exit ${PIPESTATUS[0]}"
      done
    done
  done
} 2>&1 | tee "$out/perf/perf.log"
python3 scripts/perf_tables.py "$out/perf" > "$out/perf/tables.md" 2>&1 || true
(cd "$out" && tar czf perf.tgz perf && rm -rf perf)
