#!/usr/bin/env bash
# The Direct3D 12 backend in CI, without Windows:
#  1. cross-compiles the whole product for Windows with MinGW-w64, warnings as errors: every
#     library of rhi/, rhi_d3d12/ and gi/, lumina.exe with all its commands, lumina-viewer.exe
#     (GLFW and Dear ImGui compiled from Debian's source packages, .ci/fetch-debian-sources.sh)
#     and every test executable, so none of it can rot on Windows; every kernel is compiled to
#     DXBC with vkd3d-compiler;
#  2. runs lumina.exe (--help, info, compare) under Wine, and the RHI conformance tests against
#     D3D12, whose d3d12.dll is vkd3d on Vulkan (lavapipe here), kernels included: vkd3d takes
#     DXBC only and needs Mesa 25's lavapipe (VK_EXT_descriptor_indexing), both from
#     .ci/install-dxbc-tools.sh (/opt/lumina/d3d12-tools, or $LUMINA_D3D12_TOOLS_DIR). A test
#     that cannot run there says why in its skip message (docs/d3d12.md lists them).
# Exits non-zero when the build or any test fails. Packages: .ci/install-deps.sh
# (g++-mingw-w64-x86-64, directx-headers-dev, googletest, libtinyexr-dev, libz-mingw-w64-dev,
# dpkg-dev, wine64, xvfb, xauth, and vulkan-validationlayers and mesa-vulkan-drivers, which the
# Vulkan build needs too; it also runs .ci/install-dxbc-tools.sh). ccache is used when installed
# (LUMINA_CCACHE=0: not).
#
# Kernels are the Linux build's ($LUMINA_LINUX_BUILD_DIR, default build/), brought up to date
# first, where that build exists and compiles DXBC: the same files, and three CPU-minutes saved
# (cmake/LuminaShaders.cmake, LUMINA_PREBUILT_KERNELS_DIR). Otherwise this build compiles its own.
#
#   .ci/build-d3d12-mingw.sh              # build-mingw/ beside the sources
#   LUMINA_MINGW_BUILD_DIR=/tmp/b JOBS=2 .ci/build-d3d12-mingw.sh
#   .ci/build-d3d12-mingw.sh --gtest_filter='*Buffer*'   # extra arguments go to the tests
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${LUMINA_MINGW_BUILD_DIR:-$root/build-mingw}
jobs=${JOBS:-$(nproc)}
start=$(date +%s)

fail() {
    echo "build-d3d12-mingw: $*" >&2
    exit 1
}
for tool in cmake ninja x86_64-w64-mingw32-g++-posix Xvfb; do
    command -v "$tool" >/dev/null 2>&1 || fail "$tool not found (run .ci/install-deps.sh)"
done
wine=
for candidate in /usr/lib/wine/wine64 "$(command -v wine64 || true)" "$(command -v wine || true)"; do
    if [ -n "$candidate" ] && [ -x "$candidate" ]; then
        wine=$candidate
        break
    fi
done
[ -n "$wine" ] || fail "wine64 not found (run .ci/install-deps.sh)"
[ -f /usr/include/directx/d3d12.h ] || fail "DirectX-Headers missing (apt-get install directx-headers-dev)"
[ -f /usr/src/googletest/CMakeLists.txt ] || fail "GoogleTest sources missing (apt-get install googletest)"
tools=${LUMINA_D3D12_TOOLS_DIR:-/opt/lumina/d3d12-tools}
[ -x "$tools/bin/vkd3d-compiler" ] && [ -f "$tools/lvp_icd.json" ] ||
    fail "vkd3d-compiler and Mesa 25's lavapipe missing in $tools (run .ci/install-dxbc-tools.sh)"
[ -f /usr/include/tinyexr.h ] || fail "tinyexr missing (apt-get install libtinyexr-dev)"
[ -f /usr/x86_64-w64-mingw32/lib/libz.a ] || fail "zlib for MinGW-w64 missing (apt-get install libz-mingw-w64-dev)"

echo "== vcpkg.json and CMakePresets.json against the build's find_package calls"
python3 "$root/.ci/check-vcpkg-manifest.py"
echo "== Debian sources of GLFW and Dear ImGui (for lumina-viewer.exe)"
debian_sources=${LUMINA_DEBIAN_SOURCES:-$build/debian-sources}
"$root/.ci/fetch-debian-sources.sh" "$debian_sources"
launcher=()
if [ "${LUMINA_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null 2>&1; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi

linux_build=${LUMINA_LINUX_BUILD_DIR:-$root/build}
prebuilt=
if [ -f "$linux_build/build.ninja" ] && [ -f "$linux_build/shaders/rhi_tests/chain_seed.dxbc" ]; then
    echo "== kernels: the Linux build's ($linux_build/shaders), brought up to date"
    cmake --build "$linux_build" --target lumina_kernels
    prebuilt=$linux_build/shaders
fi
kernels=${prebuilt:-$build/shaders}

echo "== configure ($build)"
cmake -S "$root" -B "$build" -G Ninja \
    -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/mingw-w64.cmake" \
    -DCMAKE_BUILD_TYPE=Release \
    -DLUMINA_D3D12=ON -DLUMINA_VULKAN=OFF -DLUMINA_WERROR=ON -DLUMINA_TESTS=ON \
    -DLUMINA_PREBUILT_KERNELS_DIR="$prebuilt" \
    -DLUMINA_DEBIAN_SOURCES_DIR="$debian_sources" "${launcher[@]}"
echo "== build (everything)"
cmake --build "$build" -j "$jobs"
# The whole product, not a part of it: a target that configured itself away fails here.
for exe in app/lumina.exe app/viewer/lumina-viewer.exe tests/rhi/rhi_conformance.exe \
    tests/image/image_tests.exe tests/frame/frame_gpu_test.exe tests/measure/make_compare_inputs.exe; do
    [ -f "$build/$exe" ] || fail "$exe was not built"
done
echo "== built: $(find "$build" -name '*.exe' -not -path '*/CMakeFiles/*' | wc -l) Windows executables"
built=$(date +%s)
[ -f "$kernels/rhi_tests/chain_seed.dxbc" ] ||
    fail "the build made no DXBC kernels (configure did not find $tools/bin/vkd3d-compiler)"

# A throw-away Wine prefix: nothing from earlier runs, no Mono or Gecko installers.
prefix=$(mktemp -d "${TMPDIR:-/tmp}/lumina-wine.XXXXXX")
export WINEPREFIX=$prefix WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml=" WINEARCH=win64
# One virtual X display (Wine's DXGI needs a display driver to list adapters) for every Wine
# program here, kept until the end. A display per program (scripts/with_virtual_display.sh) closed
# under the prefix's own processes whenever the program that started them ended, while the other
# test executable of the pair below still ran in the same prefix ("X connection to :0 broken" in
# the log); once such an executable exited non-zero after every one of its tests had passed.
xvfb_dir=$(mktemp -d "${TMPDIR:-/tmp}/lumina-xvfb.XXXXXX")
mkfifo "$xvfb_dir/display"
# Started from a subshell, so that it is no job of this shell: the GI tests below `wait` for all
# their jobs, which would then include the display server.
(Xvfb -displayfd 3 -screen 0 640x480x24 -nolisten tcp 3>"$xvfb_dir/display" 2>"$xvfb_dir/xvfb.log" &
    echo $! >"$xvfb_dir/pid")
cleanup() {
    WINEPREFIX=$prefix "$(dirname "$wine")/wineserver" -k >/dev/null 2>&1 || wineserver -k >/dev/null 2>&1 || true
    kill "$(cat "$xvfb_dir/pid" 2>/dev/null)" 2>/dev/null || true
    rm -rf "$prefix" "$xvfb_dir"
}
trap cleanup EXIT
# -displayfd writes the display's number once the server accepts connections.
display=$(head -n 1 "$xvfb_dir/display")
[ -n "$display" ] || { cat "$xvfb_dir/xvfb.log" >&2; fail "Xvfb did not start"; }
export DISPLAY=:$display
run_wine() {
    "$wine" "$@"
}
# gtest_xml_passed XML: true when gtest's XML report (written once every test has run, before the
# program exits) counts at least one test and no failure or error.
gtest_xml_passed() {
    [ -s "$1" ] && python3 - "$1" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
ok = int(root.get("tests", 0)) > 0 and root.get("failures") == "0" and root.get("errors") == "0"
sys.exit(0 if ok else 1)
PY
}
# Wine's server kills a process (SIGKILL, exit 137) one second after the last of its Windows
# threads ended, if its Unix side has not exited by then. What runs in that second is the host
# libraries' teardown: lavapipe's, LLVM's and the validation layer's destructors and the unmapping
# of gigabytes, which on two busy cores sometimes took longer: in CI a GI suite was killed so, right
# after gtest's "[  PASSED  ]" line. killed_at_exit_after_passing STATUS XML: for exit 137 with
# gtest's report complete and every test in it passed, prints a note and succeeds; otherwise fails.
killed_at_exit_after_passing() {
    [ "$1" -eq 137 ] && gtest_xml_passed "$2" || return 1
    echo "   (Wine killed it at exit, after its report counted every test passed: docs/d3d12.md)"
}

# vkd3d 1.6 (Wine 8) reads every descriptor table as zero on Debian 12's lavapipe (Mesa 22.3,
# no VK_EXT_descriptor_indexing); Mesa 25's lavapipe from install-dxbc-tools.sh has it.
# virtual_heaps: vkd3d's other descriptor-heap model works too, but each kernel test then took
# 5 to 20 s instead of under 1 s. The kernels: the DXBC beside the build (Wine maps Z: to /).
export VK_ICD_FILENAMES=$tools/lvp_icd.json VKD3D_CONFIG=virtual_heaps
export LUMINA_SHADER_DIR="Z:$kernels"

# The prefix is made by the first program Wine starts; once (of many runs) that first program
# exited 1 after its output, as its virtual display closed under the prefix's setup. So the
# prefix is set up first, on its own, and waited for (wineserver -w).
echo "== wine: prefix"
sh -c '"$1" wineboot --init && "$2" -w' wineboot "$wine" "$(dirname "$wine")/wineserver" ||
    echo "(wineboot --init exited $?; the first run sets the prefix up)"

echo "== wine: lumina.exe"
run_wine "$build/app/lumina.exe" --version
run_wine "$build/app/lumina.exe" --help
run_wine "$build/app/lumina.exe" info cornell_box
# compare: EXR reading (tinyexr), metrics, a PNG heat map and JSON, all on Windows.
compare_dir=$build/wine-compare
rm -rf "$compare_dir" && mkdir -p "$compare_dir"
run_wine "$build/tests/measure/make_compare_inputs.exe" "Z:$compare_dir"
run_wine "$build/app/lumina.exe" compare "Z:$compare_dir/ref.exr" "Z:$compare_dir/test.exr" \
    --heatmap "Z:$compare_dir/diff.png" --json "Z:$compare_dir/compare.json"
[ -s "$compare_dir/diff.png" ] && [ -s "$compare_dir/compare.json" ] || fail "lumina.exe compare wrote no heat map or JSON"
echo "== wine: image_tests.exe (EXR through tinyexr, PNG)"
run_wine "$build/tests/image/image_tests.exe" --gtest_brief=1
run_wine "$build/app/lumina.exe" --list-devices --api d3d12

# D3D12 has no debug layer under Wine. What can be checked is vkd3d's Vulkan: the Khronos
# validation layer with synchronization validation, loaded beneath vkd3d by the host's Vulkan
# loader, sees what each D3D12 barrier (or missing one) became. Any message fails the run.
# LUMINA_WINE_VK_VALIDATION=0 turns it off (for a quick local run; it costs the GI suites about 5 %).
if [ "${LUMINA_WINE_VK_VALIDATION:-1}" != 0 ]; then
    export VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation
    export VK_LAYER_ENABLES=VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT
    loader_log=$(VK_LOADER_DEBUG=layer run_wine "$build/app/lumina.exe" --list-devices --api d3d12 2>&1 || true)
    grep -q 'Insert instance layer "VK_LAYER_KHRONOS_validation"' <<<"$loader_log" ||
        fail "the Vulkan validation layer does not load beneath vkd3d (install vulkan-validationlayers," \
            "or set LUMINA_WINE_VK_VALIDATION=0)"
    echo "(Vulkan validation with synchronization validation is on beneath vkd3d)"
fi

echo "== wine: rhi_state_tracker_test.exe"
run_wine "$build/tests/rhi/rhi_state_tracker_test.exe" --gtest_brief=1

echo "== wine: rhi_conformance.exe on D3D12 (vkd3d on lavapipe)"
log=$build/wine-rhi-conformance.log
# Wine maps Z: to /; gtest would take a bare /path for a relative one.
set +e
run_wine "$build/tests/rhi/rhi_conformance.exe" --gtest_output="xml:Z:$build/wine-rhi-conformance.xml" "$@" 2>&1 |
    tee "$log"
status=${PIPESTATUS[0]}
set -e
if [ "$status" -ne 0 ] && killed_at_exit_after_passing "$status" "$build/wine-rhi-conformance.xml"; then
    status=0
fi
passed=$(grep -c '^\[       OK \]' "$log" || true)
skipped=$(grep -c '^\[  SKIPPED \] .*(' "$log" || true)
failed=$(grep -c '^\[  FAILED  \] .*(' "$log" || true)
end=$(date +%s)
echo "== D3D12 under Wine: $passed passed, $skipped skipped, $failed failed" \
    "(build $((built - start)) s, tests $((end - built)) s)"
# Every skip with its reason (gtest prints the reason on the line before [  SKIPPED ]).
if [ "$skipped" -gt 0 ]; then
    echo "== skipped on D3D12 under Wine, and why:"
    grep -B1 '^\[  SKIPPED \] .*(' "$log" | grep -v '^--$' | paste - - | sed 's/^/  /' || true
fi
[ "$status" -eq 0 ] || fail "rhi_conformance.exe failed under Wine (exit $status); log: $log"
[ "$passed" -gt 0 ] || fail "no conformance test ran under Wine"
if grep -qE 'Validation (Error|Warning)' "$log"; then
    grep -E -B2 'Validation (Error|Warning)' "$log" >&2
    fail "Vulkan validation reported problems beneath vkd3d; log: $log"
fi

# check_vkd3d_validation LOG WHAT: fails on any Vulkan validation message in LOG but one, which
# vkd3d 1.6 (Wine 8) makes of valid D3D12 (docs/d3d12.md tells what was tried): a depth buffer
# going from DEPTH_WRITE to DEPTH_READ after a render pass whose depth writes happen at the late
# fragment tests (the surface cache's card capture writes depth, then tests occluders against
# it): its layout transition is reported as a write-after-write hazard. (A second one, vkd3d's
# single dispatch for ClearUnorderedAccessViewUint of a buffer over 8 MiB, is gone: the backend
# fills such buffers by copies.) The same tests on the Vulkan backend are clean under the same
# validation (their own barriers are checked there). Those messages are counted and printed,
# never hidden.
VKD3D_KNOWN_MESSAGES='usage: SYNC_IMAGE_LAYOUT_TRANSITION, prior_usage: SYNC_LATE_FRAGMENT_TESTS_DEPTH_STENCIL_ATTACHMENT_WRITE, write_barriers: 0, command: vkCmdEndRenderPass'
check_vkd3d_validation() {
    local log=$1 what=$2 known others
    known=$(grep -E 'Validation (Error|Warning)' "$log" | grep -cE "$VKD3D_KNOWN_MESSAGES" || true)
    others=$(grep -E 'Validation (Error|Warning)' "$log" | grep -vcE "$VKD3D_KNOWN_MESSAGES" || true)
    if [ "$known" -gt 0 ]; then
        echo "   $what: $known messages of vkd3d's own translation (known, docs/d3d12.md)"
    fi
    if [ "$others" -gt 0 ]; then
        grep -E 'Validation (Error|Warning)' "$log" | grep -vE "$VKD3D_KNOWN_MESSAGES" | head -n 20 >&2 || true
        fail "Vulkan validation reported $others problems beneath vkd3d in $what; log: $log"
    fi
}

# The GI passes' own GPU tests, their D3D12 half (the same test bodies as on Vulkan, each test
# instantiated for both APIs): SDFs, BVH, deferred renderer, surface cache, screen probes, sky,
# path tracer, the deferred, SDF, lumen-frame and DDGI goldens, DDGI, the SH grid, the dynamic
# scenes and the real glTF files; the frame accuracy tests against path-traced references and the
# furnaces (frame_gpu_test), atrium at every preset and city at low (real_scenes_gpu_test) and the
# 1,000-frame stress tests (frame_stress_test). Left out, as on Vulkan, what is labelled `long`
# there (both rho 0.99 furnaces, city at medium and high), and, for CI's 90 minutes, sunlit_rooms at
# the high preset (a 4096^2 atlas; its medium runs here) and the stored-reference accuracy of the
# moving box (the Cornell box's, which runs here), the engine, the open door and the real scenes
# (whose frames run here in real_scenes_gpu_test). docs/d3d12.md lists what runs here.
# Two executables run at a time (WINE_JOBS): one test under Wine keeps about one core busy (the
# validation layer and vkd3d's translation run in the submitting thread), so one after another
# left the second core of a CI machine idle. The longest are listed first, so that none starts
# last and runs alone; each has its own log, joined in list order into $gi_log.
# Every suite runs with the validation layer beneath vkd3d. For a while the three that render
# hundreds of frames to convergence ran without it, to save CI time, but measured it saved little:
# frame_gpu_test took 603 s without it against 630 s with it (docs/d3d12.md).
export LUMINA_SOURCE_DIR="Z:$root"
gi_log=$build/wine-gi-tests.log
gi_logs=$build/wine-gi-tests
gi_filter='*d3d12*:-*Rho099*:*furnace_0_99:*city_medium:*city_high:*sunlit_rooms_high'
gi_filter+=':*StoredReferenceGpu*d3d12_cornell_box_moving:*StoredReferenceGpu*d3d12_two_cylinder_engine'
gi_filter+=':*StoredReferenceGpu*d3d12_atrium*:*StoredReferenceGpu*d3d12_city*:*StoredReferenceGpu*d3d12_door*'
gi_tests="frame/frame_gpu_test frame/frame_stress_test surface_cache/surface_cache_gpu_tests ddgi/ddgi_gpu_test
    frame/real_scenes_gpu_test screen_probes/screen_probes_gpu_test frame/dynamic_scene_gpu_test
    sh_grid/sh_grid_gpu_test surface_cache/sky_radiosity_gpu_test screen_probes/probe_sky_gpu_test
    frame/frame_golden_test frame/real_scene_gpu_test deferred/deferred_gpu_test pathtracer/pathtracer_gpu_tests
    sdf/sdf_scene_gpu_tests deferred/deferred_golden_test sdf/sdf_golden_test sdf/sdf_gpu_tests bvh/bvh_gpu_tests"
rm -rf "$gi_logs" && mkdir -p "$gi_logs"
# run_gi_test TEST: TEST's D3D12 half under Wine into $gi_logs/NAME.log, and "EXIT SECONDS" into
# NAME.status.
run_gi_test() {
    local name=${1//\//_} begin status
    begin=$(date +%s)
    if run_wine "$build/tests/$1.exe" --gtest_filter="$gi_filter" --gtest_output="xml:Z:$gi_logs/$name.xml" \
        >>"$gi_logs/$name.log" 2>&1; then
        status=0
    else
        status=$?
        if killed_at_exit_after_passing "$status" "$gi_logs/$name.xml" >>"$gi_logs/$name.log"; then
            status=0
        fi
    fi
    echo "$status $(($(date +%s) - begin))" >"$gi_logs/$name.status"
}
gi_start=$(date +%s)
running=0
for test in $gi_tests; do
    run_gi_test "$test" &
    # Two Wine processes started in the same second once left one without a device
    # (CreateDXGIFactory2: DXGI_ERROR_UNSUPPORTED, frame_stress_test.exe, 0 s): starts are staggered.
    sleep 10
    running=$((running + 1))
    if [ "$running" -ge "${WINE_JOBS:-2}" ]; then
        wait -n
        running=$((running - 1))
    fi
done
wait
: >"$gi_log"
gi_failed=
for test in $gi_tests; do
    name=${test//\//_}
    cat "$gi_logs/$name.log" >>"$gi_log"
    read -r status seconds <"$gi_logs/$name.status" || { status=1; seconds=?; }
    echo "== wine: $test.exe on D3D12 ($seconds s): $(grep -E '^\[  (PASSED|FAILED) +\] [0-9]' \
        "$gi_logs/$name.log" | tail -n 1 || true)"
    grep -F '(Wine killed it at exit' "$gi_logs/$name.log" || true
    if [ "$status" -ne 0 ]; then
        # `|| true`: an executable can exit non-zero with no failed test in its log (a crash on the
        # way out); grep then finds nothing, and under pipefail that once ended this script with no
        # word of which executable failed.
        grep -E -A4 '^\[  FAILED  \]|Failure$' "$gi_logs/$name.log" | tail -n 60 >&2 || true
        echo "   $test.exe exited $status; the end of its log:" >&2
        tail -n 15 "$gi_logs/$name.log" >&2 || true
        gi_failed="$gi_failed $test.exe (exit $status)"
    fi
done
[ -z "$gi_failed" ] || fail "failed on D3D12 under Wine:$gi_failed; logs: $gi_logs"
echo "== GI tests on D3D12 under Wine: $(($(date +%s) - gi_start)) s"
check_vkd3d_validation "$gi_log" "the GI tests"
echo "== GI tests on D3D12 under Wine: $(grep -c '^\[       OK \]' "$gi_log" || true) passed"

# The deferred frame on D3D12: GBuffer, sun and cube shadow maps, direct light and composite, every
# draw and dispatch from DXBC, against the Vulkan build's frame of the same scene. Both are
# deterministic (no temporal noise in the direct technique), so they must agree to rounding.
# Then the lumen frame (every GI pass from DXBC) against Vulkan's.
linux_lumina=$linux_build/app/lumina
if [ ! -x "$linux_lumina" ]; then
    echo "== skipped: the D3D12 frame against Vulkan needs the Linux build's lumina ($linux_lumina;" \
        "set LUMINA_LINUX_BUILD_DIR)"
    exit 0
fi
frames=$build/wine-render
rm -rf "$frames" && mkdir -p "$frames"

# check_frame NAME BOUND VALIDATION SCENE RENDER-ARGS...: renders SCENE with RENDER-ARGS on D3D12
# under Wine and with the Linux build on Vulkan, and fails when the two images differ by more than
# relMSE BOUND. VALIDATION: "strict" fails on any Vulkan validation message beneath vkd3d, "vkd3d"
# lets through vkd3d's own one (check_vkd3d_validation).
check_frame() {
    local name=$1 bound=$2 validation=$3 scene=$4
    shift 4
    local d3d12=$frames/${name}_d3d12 vulkan=$frames/${name}_vulkan relmse
    echo "== wine: lumina.exe render $scene $* on D3D12, against Vulkan"
    run_wine "$build/app/lumina.exe" render "$scene" --api d3d12 "$@" --out "Z:$d3d12.exr" >"$d3d12.log" 2>&1 ||
        { cat "$d3d12.log" >&2; fail "lumina.exe render ($name) failed under Wine; log: $d3d12.log"; }
    if [ "$validation" = strict ]; then
        if grep -qE 'Validation (Error|Warning)' "$d3d12.log"; then
            grep -E -B2 'Validation (Error|Warning)' "$d3d12.log" >&2
            fail "Vulkan validation reported problems beneath vkd3d while rendering ($name); log: $d3d12.log"
        fi
    else
        check_vkd3d_validation "$d3d12.log" "the $name frame"
    fi
    (unset VK_INSTANCE_LAYERS VK_LAYER_ENABLES VK_ICD_FILENAMES VKD3D_CONFIG LUMINA_SHADER_DIR
     "$linux_lumina" render "$scene" "$@" --out "$vulkan.exr" >"$vulkan.log" 2>&1) ||
        fail "the Vulkan render ($name) failed; log: $vulkan.log"
    relmse=$("$linux_lumina" compare "$vulkan.exr" "$d3d12.exr" | awk '/relMSE/ {print $2; exit}')
    echo "   relMSE of the D3D12 $name frame against the Vulkan one: $relmse (must be at most $bound)"
    awk -v r="$relmse" -v b="$bound" 'BEGIN { exit !(r != "" && r <= b) }' ||
        fail "the D3D12 $name frame differs from the Vulkan frame (relMSE $relmse); images in $frames"
}

check_frame direct 1e-6 strict cornell_box_point --technique direct --size 64x64

# The lumen frame: SDF compose and traces, surface-cache capture, lighting, voxel lighting and
# radiosity, and the 14 screen-probe passes (adaptive probes included), 4 frames. The APIs' float
# rounding differs by an ULP here and there (DXBC from vkd3d-shader against SPIR-V from glslang),
# and the screen probes' importance sampling feeds each frame's radiance into the next frame's ray
# directions, so the frames could drift apart: measured relMSE 3.5e-10 after 4 frames
# (docs/d3d12.md). The bound was 1e-4 while the texel solid angles were miscompiled (8e-6 then); a
# black far field gave 0.0155.
check_frame lumen 1e-6 vkd3d cornell_box --technique lumen --preset low --size 32x32 --frames 4

# The DDGI frame: probe tracing through the SDFs into the surface cache, the irradiance and
# distance blends, relocation, classification and sampling, 4 frames. No importance sampling
# feeds back into the rays, so it must match Vulkan to rounding (it matched bit for bit).
check_frame DDGI 1e-6 vkd3d cornell_box --technique ddgi --preset low --size 32x32 --frames 4

# The SH grid's frame: every probe's six cube faces through the two-pass GBuffer and the shadowed
# direct light, the GPU SH projection and combine, and the trilinear sampling; the whole grid is
# baked within the 8 frames (64 probes a frame). No feedback between frames, so it must match to
# rounding (relMSE 6e-9 when added), with no validation message at all.
check_frame sh-grid 1e-6 strict cornell_box_point --technique sh-grid --preset low --size 32x32 --frames 8 \
    --sh-grid-budget 64
