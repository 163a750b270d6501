#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): `lumina bench` over the small scenes with every
# technique (LUMINA_BENCH_TECHNIQUES), references of 4096 spp, no plot (the machine has no
# matplotlib: plot the JSON afterwards with scripts/plot_bench.py). Published timings are taken
# without validation; LUMINA_BENCH_VALIDATION=1 turns it on. Writes under $OUT/bench.
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
timeout ${LUMINA_BENCH_TIMEOUT:-420} .devbin/lumina bench --size ${LUMINA_BENCH_SIZE:-960x540} --frames 128 \
  --reference-spp 4096 --techniques ${LUMINA_BENCH_TECHNIQUES:-direct,lumen,ddgi,sh-grid,pathtracer} \
  --pt-budgets 1,4,16 --no-plot $([ "${LUMINA_BENCH_VALIDATION:-0}" = 1 ] && echo --validation) \
  --out "$out/bench" 2>&1 | grep -v '^frame ' | tr '\r' '\n' | grep -v '^\[' | tee "$out/bench.log"
