#!/usr/bin/env bash
# Runs on the lent GPU machine (docs/gpu.md): the RHI conformance tests and the GPU test
# binaries with validation, then the path tracer's and the SDF tracer's throughput figures
# quoted in docs/pathtracer.md and docs/sdf.md. Writes every log under $OUT (or ./gpu-out).
set -uo pipefail
out=${OUT:-$PWD/gpu-out}
mkdir -p "$out"
source scripts/gpu/prologue.sh
export LUMINA_CACHE_DIR=/tmp/lumina-cache
{
  nvidia-smi -L
  .devbin/lumina --list-devices
  .devbin/lumina gpu-check --validation
} 2>&1 | tee "$out/device.txt"
if ! .devbin/lumina --list-devices >/dev/null 2>&1; then
  VK_LOADER_DEBUG=error,warn,driver .devbin/lumina --list-devices 2>&1 | tail -60 | tee -a "$out/device.txt"
  exit 1
fi
for t in rhi_conformance pathtracer_gpu_tests bvh_gpu_tests sdf_gpu_tests sdf_scene_gpu_tests \
         deferred_gpu_test surface_cache_gpu_tests; do
  [ -x .devbin/tests/$t ] || continue
  echo "== $t"
  timeout 120 .devbin/tests/$t 2>&1 | tee "$out/$t.log" | grep -E "FAILED|PASSED|validation message"
done 2>&1 | tee "$out/tests.txt"
{
  echo "== reference cornell_box 512x512"
  timeout 60 .devbin/lumina reference cornell_box --spp 256 --out /tmp/cb.exr 2>&1 | tr '\r' '\n' | tail -4
  echo "== reference city 1280x720"
  timeout 90 .devbin/lumina reference city --spp 64 --out /tmp/city.exr 2>&1 | tr '\r' '\n' | tail -4
  for s in cornell_box atrium city; do
    echo "== sdf $s"
    timeout 60 .devbin/lumina sdf $s --trace-bench --size 1920x1080 --frames 20 2>&1 | tail -15
  done
} 2>&1 | tee "$out/throughput.txt"
