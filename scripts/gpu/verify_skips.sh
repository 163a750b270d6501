#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): `lumina bench --verify-skips` (docs/measurement.md#skips)
# over scenes that reach every kind of reused work: a point light's cube shadow map
# (cornell_box_point), the sun's shadow map and thin walls (sunlit_rooms), moving geometry and a
# moving light (cornell_box_moving, door), and a large scene with a sun (atrium). Every real-time
# technique and preset; each skip forced off in turn, what it saves per frame and how far the
# image moves (at most relMSE 0.001, else the bench exits 1).
# Writes $OUT/skips.tar: one folder per scene with bench.log and skips.csv, and summary.txt.
#   LUMINA_SKIP_SCENES (default below), LUMINA_SKIP_SIZE (960x540), LUMINA_SKIP_FRAMES (128),
#   LUMINA_SKIP_PRESETS (low,medium,high),
#   LUMINA_SKIP_DEADLINE_S: start no scene after this many seconds.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
work=/tmp/skips
rm -rf "$work"
mkdir -p "$out" "$work"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=${LUMINA_CACHE_DIR:-/tmp/lumina-cache}
lumina=.devbin/lumina
scenes=${LUMINA_SKIP_SCENES:-cornell_box_point,sunlit_rooms,cornell_box_moving,door,atrium}
size=${LUMINA_SKIP_SIZE:-960x540}
frames=${LUMINA_SKIP_FRAMES:-128}
start=$(date +%s)
{
  echo "commit $(cat .devbin/commit 2>/dev/null || echo unknown)"
  $lumina --list-devices 2>&1 | head -3
} > "$work/summary.txt"
status=0
for scene in ${scenes//,/ }; do
  if [ -n "${LUMINA_SKIP_DEADLINE_S:-}" ] && [ $(( $(date +%s) - start )) -ge "$LUMINA_SKIP_DEADLINE_S" ]; then
    echo "verify_skips: deadline reached before $scene" | tee -a "$work/summary.txt"
    break
  fi
  mkdir -p "$work/$scene"
  t0=$(date +%s)
  # The reference only feeds the bench's error column; the skip check compares forced against
  # unforced images, so a small reference is enough.
  $lumina bench --scenes "$scene" --techniques direct,lumen,ddgi,sh-grid --presets "${LUMINA_SKIP_PRESETS:-low,medium,high}" \
    --pt-budgets 1 --size "$size" --frames "$frames" --reference-spp 64 --verify-skips \
    --out "$work/$scene" --no-plot 2>&1 | tr '\r' '\n' | grep -v '^\[' > "$work/$scene/bench.log"
  rc=${PIPESTATUS[0]}
  [ "$rc" -eq 0 ] || status=$rc
  echo "$scene: exit $rc, $(( $(date +%s) - t0 )) s" >> "$work/summary.txt"
  grep "skip check" "$work/$scene/bench.log" >> "$work/summary.txt"
  tar -C "$work" -cf "$out/skips.tar" .
done
cat "$work/summary.txt"
exit "$status"
