#!/usr/bin/env bash
# Issue 25's full matrix (docs/batch.md, docs/measurement.md): `lumina bench` over every built-in
# scene (the animated ones also measure convergence after change), every technique and preset and
# the path tracer at 1x/4x/16x time, at each size; then one Pareto plot per scene
# (scripts/plot_pareto.py: GPU ms against relMSE, the front marked) from the merged results.
#
# On the lent GPU machine (docs/gpu.md), one device call is limited to 10 minutes: run it as
# shards, one call each, then merge and plot here:
#   LUMINA_SHARD=0/8 scripts/gpu/bench_matrix.sh     # ... up to 7/8, each writes $OUT/matrix/SIZE/shard_I
#   scripts/gpu/bench_matrix.sh merge DIR...          # DIR: the calls' matrix folders; merges and plots
# Or one bench per scene, as many scenes as fit in one call (a shard of scenes keeps each scene's
# reference in one call; --shard splits a scene's techniques across calls, each rendering the
# reference again):
#   LUMINA_MATRIX_PER_SCENE=1 LUMINA_MATRIX_DEADLINE_S=540 LUMINA_MATRIX_SCENES=a,b scripts/gpu/bench_matrix.sh
#     writes $OUT/matrix/SIZE/SCENE/ per scene finished, and starts no scene after the deadline
#     (LUMINA_MATRIX_ARGS: more bench flags for each, e.g. "--check-auto 0.05"), and that folder
#     as $OUT/matrix_SIZE_SCENE.tar;
#   scripts/gpu/bench_matrix.sh plot CSV...           # plots the per-scene CSVs of several calls
# Without LUMINA_SHARD it runs everything in one go and plots. On lavapipe, tiny:
#   LUMINA=build/app/lumina LUMINA_MATRIX_SCENES=cornell_box_point LUMINA_MATRIX_SIZES=16x16 \
#   LUMINA_MATRIX_TECHNIQUES=direct,pathtracer LUMINA_MATRIX_FRAMES=2 LUMINA_MATRIX_SPP=8 \
#   OUT=/tmp/matrix scripts/gpu/bench_matrix.sh
# The plot needs python3-matplotlib; where it is missing the results stay and the merge step
# (run where matplotlib is) plots them.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
if [ -z "${LUMINA:-}" ]; then
  source scripts/gpu/prologue.sh
  LUMINA=.devbin/lumina
  export LUMINA_CACHE_DIR=${LUMINA_CACHE_DIR:-/tmp/lumina-cache}
fi
python=${LUMINA_PYTHON:-/usr/bin/python3}
scenes=${LUMINA_MATRIX_SCENES:-cornell_box,cornell_box_point,cornell_box_moving,open_top_box,two_rooms,sunlit_rooms,door,atrium,atrium_day,two_cylinder_engine,city}
sizes=${LUMINA_MATRIX_SIZES:-"960x540 1920x1080"}
techniques=${LUMINA_MATRIX_TECHNIQUES:-direct,lumen,ddgi,sh-grid,pathtracer}

plot() { # plot OUT_DIR CSV...
  if "$python" -c "import matplotlib" 2>/dev/null; then
    "$python" scripts/plot_pareto.py "$@"
  else
    echo "bench_matrix: no matplotlib here: run 'scripts/gpu/bench_matrix.sh merge DIR' where it is"
  fi
}

if [ "${1:-}" = plot ]; then
  shift
  plot "$out/matrix/pareto" "$@"
  exit
fi

if [ "${1:-}" = merge ]; then
  shift
  csvs=()
  for size in $sizes; do
    parts=()
    for dir in "$@"; do parts+=("$dir/$size"/shard_*); done
    $LUMINA merge "$out/matrix/$size/merged" "${parts[@]}" --no-plot || exit 1
    csvs+=("$out/matrix/$size/merged/bench.csv")
  done
  plot "$out/matrix/pareto" "${csvs[@]}"
  exit
fi

bench() { # bench DIR SIZE SCENES [ARG...]
  local dir=$1 size=$2 scenes=$3
  shift 3
  mkdir -p "$dir"
  $LUMINA bench --scenes "$scenes" --techniques "$techniques" --presets "${LUMINA_MATRIX_PRESETS:-low,medium,high}" \
    --pt-budgets 1,4,16 --size "$size" --frames "${LUMINA_MATRIX_FRAMES:-128}" \
    --reference-spp "${LUMINA_MATRIX_SPP:-4096}" --change-frames "${LUMINA_MATRIX_CHANGE_FRAMES:-32}" \
    --no-plot "$@" --out "$dir" 2>&1 | tr '\r' '\n' | grep -v '^\[' | tee "$dir/bench.log"
  return "${PIPESTATUS[0]}"
}

if [ -n "${LUMINA_MATRIX_PER_SCENE:-}" ]; then
  start=$(date +%s)
  for scene in ${scenes//,/ }; do
    for size in $sizes; do
      if [ -n "${LUMINA_MATRIX_DEADLINE_S:-}" ] && [ $(( $(date +%s) - start )) -ge "$LUMINA_MATRIX_DEADLINE_S" ]; then
        echo "bench_matrix: deadline reached before $scene at $size"
        exit 0
      fi
      t0=$(date +%s)
      # shellcheck disable=SC2086 # LUMINA_MATRIX_ARGS: extra bench flags, e.g. "--check-auto 0.05"
      bench "$out/matrix/$size/$scene" "$size" "$scene" ${LUMINA_MATRIX_ARGS:-} || echo "bench_matrix: $scene at $size failed"
      echo "bench_matrix: $scene at $size took $(( $(date +%s) - t0 )) s"
      # The device tool brings back files at most two folders deep: one tar per scene and size.
      tar -C "$out/matrix" -cf "$out/matrix_${size}_$scene.tar" "$size/$scene"
    done
  done
  exit 0
fi

csvs=()
for size in $sizes; do
  dir=$out/matrix/$size
  shard_args=()
  if [ -n "${LUMINA_SHARD:-}" ]; then
    shard_args=(--shard "$LUMINA_SHARD")
    dir=$dir/shard_${LUMINA_SHARD%%/*}
  fi
  bench "$dir" "$size" "$scenes" "${shard_args[@]}" || exit 1
  csvs+=("$dir/bench.csv")
done
[ -z "${LUMINA_SHARD:-}" ] && plot "$out/matrix/pareto" "${csvs[@]}"
exit 0
