# lumina-viewer when the GPU is lost or out of memory (docs/gi_tests.md#device-loss), on a virtual X
# display (DISPLAY_WRAPPER: scripts/with_virtual_display.sh). VIEWER: the viewer; WORK: a scratch
# folder. Every run is bounded in time: a hang fails the test.
# 1. The device reports itself lost on the 21st submission (some frames in) (LUMINA_FAULT_INJECT,
#    rhi/fault_injection.h): the viewer exits 1 with the loss named, after saving its settings
#    (the technique, preset and exposure it ran with, and the camera) to --settings.
# 2. The next start reads them back: same technique, preset and exposure without any flag.
# 3. A render size whose images cannot be allocated (16384x16384: 4 GiB a float4 image, more
#    than lavapipe allocates at once) exits 1 naming the resource and what to make smaller, and
#    leaves the settings file as it was (a start that fails saves nothing).
include(${CMAKE_CURRENT_LIST_DIR}/bounded_run.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(settings "${WORK}/viewer.json")

set(ENV{LUMINA_FAULT_INJECT} "device-lost-after-submits:20")
bounded_run(1 lost 180 "${DISPLAY_WRAPPER}" "${VIEWER}" cornell_box --size 32x32 --technique direct
            --exposure 1.5 --frames 40 --settings "${settings}")
expect_match(lost "${ERR}" "lumina-viewer: error: the GPU device was lost: vkQueueSubmit2 failed: VK_ERROR_DEVICE_LOST \\(-4\\) \\[[a-z]+ queue, value [0-9]+; injected by LUMINA_FAULT_INJECT=device-lost-after-submits:20\\]")
expect_match(lost "${OUT}" "views: [0-9]+.*settings: saved to [^\n]*viewer.json")
if(OUT MATCHES "frames: ")
  message(FATAL_ERROR "[lost] the viewer ran to its last frame: the injected loss did not end it")
endif()
file(READ "${settings}" json)
string(JSON technique GET "${json}" technique)
string(JSON exposure GET "${json}" exposureEv)
string(JSON scene GET "${json}" scene)
string(JSON position LENGTH "${json}" camera position)
if(NOT technique STREQUAL "direct" OR NOT exposure STREQUAL "1.5" OR NOT scene STREQUAL "cornell_box" OR NOT position EQUAL 3)
  message(FATAL_ERROR "[lost] saved settings are not the run's:\n${json}")
endif()

unset(ENV{LUMINA_FAULT_INJECT})
bounded_run(0 restored 180 "${DISPLAY_WRAPPER}" "${VIEWER}" cornell_box --size 32x32 --frames 2 --settings "${settings}")
expect_match(restored "${OUT}" "settings: read from [^\n]*viewer.json")
expect_match(restored "${OUT}" "technique: direct, preset [a-z]+, exposure 1.5 EV")

file(READ "${settings}" before)
bounded_run(1 out-of-memory 180 "${DISPLAY_WRAPPER}" "${VIEWER}" cornell_box --size 16384x16384 --technique lumen
            --frames 2 --settings "${settings}")
expect_match(out-of-memory "${ERR}" "lumina-viewer: error: out of GPU memory: '[^']+' needs [0-9]+ MiB")
expect_match(out-of-memory "${ERR}" "a smaller --size, a lower --preset or a smaller scene")
file(READ "${settings}" after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "[out-of-memory] a start that failed changed the settings:\n${after}")
endif()
