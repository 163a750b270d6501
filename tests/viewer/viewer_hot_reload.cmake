# Shader hot reload of lumina-viewer under a virtual X display (scripts/with_virtual_display.sh) on lavapipe
# with the validation layer, run with cmake -P: VIEWER the executable; DISPLAY_WRAPPER that script;
# WORK a scratch folder.
# --test-hot-reload copies the kernels' sources and the build's SPIR-V under WORK, edits the
# debug view kernel (shaders/viewer/visualise.hlsl) to invert its colours and checks that the
# next frame shows exactly the inverted image, then adds a syntax error and checks that the
# compiler's error is reported and the inverted image stays (app/viewer/hot_reload_test.h). The
# viewer exits 1 when a step fails or does not happen within its timeout, or on any validation
# message.
include(${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake)

file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

set(LUMINA "${DISPLAY_WRAPPER}")
run(0 hot-reload "${VIEWER}" cornell_box --size 32x32 --validation
    --test-hot-reload "${WORK}/kernels")
expect_match(hot-reload "${OUT}" "hot reload: watching .*/kernels/src")
expect_match(hot-reload "${OUT}" "hot reload: reloaded viewer/visualise.hlsl")
expect_match(hot-reload "${OUT}" "hot reload test: the reloaded kernel inverted the image")
expect_match(hot-reload "${OUT}" "previous kernel kept running for [0-9]+ frames: passed")
# The compiler's output, as the UI shows it: the file, and glslang's error.
expect_match(hot-reload "${ERR}" "hot reload: viewer/visualise.hlsl .*ERROR: .*visualise.hlsl")
if(ERR MATCHES "validation")
  message(FATAL_ERROR "[hot-reload] validation messages:\n${ERR}")
endif()
