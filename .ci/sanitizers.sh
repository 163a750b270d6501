#!/usr/bin/env bash
# The sanitizer step of CI (issue 24; docs/gi_tests.md#sanitizers): an ASan + UBSan +
# LeakSanitizer build in build-asan, then every unit test and a bounded set of the lavapipe
# GPU tests on it. Any sanitizer report fails the test it came from. Bounded so that the step
# adds about 16 minutes to CI on a 2-core machine (measured: 705 s of build, 276 s of tests;
# docs/gi_tests.md#sanitizers): the GPU tests are those of the executables
# built below, minus the suites that run long (the furnace, Cornell and stored-reference
# accuracy tests, the real scenes), which exercise no code the others do not.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)

targets=(
  # unit tests (ctest -L unit)
  scene_tests image_tests exr_tinyexr_tests measure_tests
  rhi_state_tracker_test bvh_tests gi_core_tests golden_compare_test
  bench_unit_tests ddgi_unit_test deferred_unit_test
  pathtracer_tests screen_probes_unit_test sdf_tests
  sh_grid_unit_test surface_cache_tests
  # GPU tests on lavapipe, with the Vulkan validation layer
  rhi_conformance deferred_gpu_test pathtracer_gpu_tests
  bvh_gpu_tests sdf_gpu_tests
  # the CLI, for its smoke tests and the out-of-memory test; the EXRs unit.compare_smoke compares
  lumina make_compare_inputs
)
# GPU tests left out: suites of many frames (seconds to minutes each on lavapipe) and tests of
# executables not built above (ctest lists those as *_NOT_BUILT). check_finite_cli took 198 s
# here (13 s unsanitized: thousands of validated check dispatches a frame), the step's longest
# test by three times, for the finite check's host code (gi/core/finite_check.cpp, about 150
# lines); the main test step keeps running it, and finite_check_gpu_test.
slow='NOT_BUILT|poison_stress|viewer|bench_smoke|skip_check_smoke|render_command|sky_cli_smoke|sealed_box_leak_smoke|sh_grid_cli|ddgi_cli|check_finite_cli|Furnace|Cornell|RealScene|StoredReference|VsPathTracer|SkyRadiosity|DynamicScene'

# No DXBC kernels: the D3D12 build is not sanitized. Where the Linux build exists (CI builds it
# first) its kernels are brought up to date and loaded: sanitizers do not change a kernel.
kernels=
if [ -f build/build.ninja ]; then
  cmake --build build --target lumina_kernels
  kernels=$PWD/build/shaders
fi
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Release -DLUMINA_SANITIZE=ON -DLUMINA_VKD3D_COMPILER=OFF \
  -DLUMINA_PREBUILT_KERNELS_DIR="$kernels"
cmake --build build-asan --target "${targets[@]}"
built=$(date +%s)

supp=$PWD/tests/sanitizers
# detect_leaks: LeakSanitizer at exit. The suppressions name system libraries' own leaks only
# (tests/sanitizers/lsan.supp says which and why); Lumina's are never suppressed.
export ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=0
export LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=$supp/ubsan.supp
# The tests that run the path tracer's kernel over several samples: lavapipe compiles a copy of
# the kernel for each new value of its per-sample constants and never frees it (lavapipe's own
# leak: tests/sanitizers/lsan_lavapipe_jit.supp has the evidence). They run in a second pass
# whose suppressions add lavapipe's JIT to lsan.supp's; every other test runs without it. The
# render CLI's smoke test joins them: its DDGI and lumen frames leak the same way (the same two
# lavapipe frames in their reports).
jit='AnalyticLightTest|ConvergenceTest|DeterminismTest|EmitterTest|EnvironmentSkyTest|reference_cli_smoke|shard_smoke|auto_technique_smoke|device_lost_cli|render_cli_smoke'
status=0
ctest --test-dir build-asan --output-on-failure -j2 -L 'unit|gpu' -E "$slow|$jit" || status=$?
cat "$supp/lsan.supp" "$supp/lsan_lavapipe_jit.supp" >build-asan/lsan_jit.supp
LSAN_OPTIONS=suppressions=$PWD/build-asan/lsan_jit.supp:print_suppressions=0 \
  ctest --test-dir build-asan --output-on-failure -j2 -L 'unit|gpu' -E "$slow" -R "$jit" || status=$?
echo "sanitizers: build $((built - start)) s, tests $(( $(date +%s) - built )) s, exit $status"
exit "$status"
