# lumina-viewer under a virtual X display (scripts/with_virtual_display.sh) on lavapipe, run with
# cmake -P: VIEWER, LUMINA: the executables; DISPLAY_WRAPPER: that script; WORK: a scratch folder.
# 1. flags: --help exits 0 and lists the keys; bad flags, and a --view the technique does not
#    have, exit 2 with the problem named.
# 2. cornell_box at 96x96 with the validation layer (synchronization validation on): the window
#    is resized, minimised and restored while it renders (--test-resize), and after FRAMES
#    frames the viewer writes the frame as EXR and exits 0. Any validation message exits 1.
#    Then every debug view of the view menu once, one per frame (--cycle-views), with the
#    technique, preset, a light and the slice axis changed on the way (--test-edits).
# 3. `lumina render` of the same scene, size and frame count writes the same view; the two
#    EXRs must agree within relMSE 1e-4 (the viewer renders exactly the frames `lumina render`
#    does, plus its own passes after the composite; measured on lavapipe: relMSE 0).
include(${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake)

set(FRAMES 12)
set(SIZE 96x96)
set(TOLERANCE 1e-4)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# viewer(<expected exit code> <name> args...): lumina-viewer on a fresh virtual X display, through
# cli_smoke.cmake's run() with the display wrapper as the program; OUT and ERR as run() leaves them.
function(viewer expected name)
  set(LUMINA "${DISPLAY_WRAPPER}")
  run(${expected} ${name} "${VIEWER}" ${ARGN})
  set(OUT "${OUT}" PARENT_SCOPE)
  set(ERR "${ERR}" PARENT_SCOPE)
endfunction()

viewer(0 help --help)
expect_match(help "${OUT}" "usage: lumina-viewer SCENE")
expect_match(help "${OUT}" "--screenshot-after N PATH")
viewer(2 unknown-flag cornell_box --no-such-flag)
expect_match(unknown-flag "${ERR}" "unknown flag '--no-such-flag' \\(see lumina-viewer --help\\)")
viewer(2 screenshot-needs-path cornell_box --screenshot-after 3)
expect_match(screenshot-needs-path "${ERR}" "--screenshot-after needs two values")
viewer(2 not-a-viewer-flag cornell_box --seed 3)
expect_match(not-a-viewer-flag "${ERR}" "--seed is not a lumina-viewer flag")
viewer(2 bad-frames-in-flight cornell_box --frames-in-flight 5)
viewer(2 hot-reload-test-without-hot-reload cornell_box --test-hot-reload "${WORK}/x" --no-hot-reload)
expect_match(hot-reload-test-without-hot-reload "${ERR}" "--test-hot-reload .*cannot run with --no-hot-reload")
# A view name is checked against the list the first frame completes (direct: no GI views).
viewer(2 no-such-view cornell_box --size 16x16 --technique direct --view "sdf: global SDF slice" --frames 3)
expect_match(no-such-view "${ERR}" "--view 'sdf: global SDF slice': no such view for this technique")

# --technique auto (docs/measurement.md): the calibration lumina render runs, before the window
# opens. A budget every candidate meets picks the cheapest: direct (a frame) over the SH grid (its
# bake), and the viewer starts with it. The flags of auto without it, and auto without a budget,
# are usage errors.
set(ENV{LUMINA_CACHE_DIR} "${WORK}/cache")
set(auto --technique auto --auto-techniques direct,sh-grid --auto-presets low --calibration-size 16x16
    --calibration-frames 4 --calibration-spp 16)
viewer(0 auto cornell_box --size 16x16 ${auto} --error-budget 10 --frames 3 --validation)
expect_match(auto "${OUT}" "auto: chose direct low: relMSE [0-9.e-]+ <= 10")
expect_match(auto "${OUT}" "technique: direct, preset low")
viewer(2 auto-flag-without-auto cornell_box --error-budget 0.1)
expect_match(auto-flag-without-auto "${ERR}" "--error-budget goes with --technique auto")
viewer(2 auto-without-budget cornell_box --technique auto --frames 1)
expect_match(auto-without-budget "${ERR}" "needs --error-budget")
viewer(1 auto-none-meets cornell_box --size 16x16 ${auto} --error-budget 1e-9 --frames 1)
expect_match(auto-none-meets "${ERR}" "no candidate has relMSE <= 1e-09")

viewer(0 render cornell_box --size ${SIZE} --validation --test-resize --screenshot-after ${FRAMES}
       "${WORK}/viewer.exr")
expect_match(render "${OUT}" "wrote .*viewer.exr")
# The window's sizes as the swapchain took them: larger, smaller, minimised (0x0), restored.
expect_match(render "${OUT}" "swapchain: 144x113.*swapchain: 51x53.*swapchain: 0x0.*swapchain: 96x96")
if(ERR MATCHES "validation")
  message(FATAL_ERROR "[render] validation messages:\n${ERR}")
endif()

# Every debug view once, on a scene with a point light (cube shadow maps), under validation, while
# the technique is switched to direct and back to lumen (preset low) and the light is edited. The
# last rebuild is at frame 6; from there --cycle-views shows view (frame mod views) each frame,
# so 6 + VIEW_FRAMES frames show every view of the lumen renderer at least once. The slice views
# are turned to the x axis at frame 12 and to y at frame 24.
set(VIEW_FRAMES 44)
math(EXPR frames "6 + ${VIEW_FRAMES}")
viewer(0 views cornell_box_point --size 32x32 --validation --cycle-views --test-edits --frames ${frames})
expect_match(views "${OUT}" "renderer rebuilt: direct.*renderer rebuilt: lumen, preset low")
expect_match(views "${OUT}" "slice axis: x.*slice axis: y")
string(REGEX MATCH "views: ([0-9]+)" _ "${OUT}")
if(NOT CMAKE_MATCH_1 OR CMAKE_MATCH_1 GREATER VIEW_FRAMES)
  message(FATAL_ERROR "[views] expected at most ${VIEW_FRAMES} views, got '${CMAKE_MATCH_1}'")
endif()
# The GI views of the lumen renderer, each shown (printed as "view: NAME" when it is).
foreach(name "sdf: global SDF slice" "sdf: traced normals, near field" "sdf: traced normals, far field"
             "sdf: traced normals, cone" "surface cache: card outlines over the final image"
             "surface cache: card outlines over the atlas albedo"
             "surface cache: card outlines over the atlas final lighting"
             "surface cache: radiosity probes, irradiance \\(filtered\\)"
             "surface cache: radiosity probes, irradiance \\(traced\\)" "surface cache: radiosity probes, normal"
             "surface cache: voxel lighting slice" "screen probes: ray directions"
             "screen probes: SH radiance \\(the low-pass\\)" "shadows: first point light, face -z")
  expect_match(views "${OUT}" "view: ${name}\n")
endforeach()
if(ERR MATCHES "validation")
  message(FATAL_ERROR "[views] validation messages:\n${ERR}")
endif()

# The DDGI technique's views (GiTechniqueRenderer::debugTextures), each shown once.
viewer(0 ddgi-views cornell_box --technique ddgi --preset low --size 32x32 --validation --cycle-views --frames 24)
foreach(name "ddgi: irradiance E" "ddgi: irradiance atlas \\(E\\^\\(1/5\\)\\)" "ddgi: distance atlas \\(cells\\)")
  expect_match(ddgi-views "${OUT}" "view: ${name}\n")
endforeach()
if(ERR MATCHES "validation")
  message(FATAL_ERROR "[ddgi-views] validation messages:\n${ERR}")
endif()

# The SH grid's view.
viewer(0 sh-grid-views cornell_box --technique sh-grid --preset low --size 32x32 --validation --cycle-views --frames 16)
expect_match(sh-grid-views "${OUT}" "view: sh grid: irradiance E\n")
if(ERR MATCHES "validation")
  message(FATAL_ERROR "[sh-grid-views] validation messages:\n${ERR}")
endif()

run(0 reference render cornell_box --size ${SIZE} --frames ${FRAMES} --out "${WORK}/render.exr")
run(0 compare compare "${WORK}/render.exr" "${WORK}/viewer.exr" --json "${WORK}/compare.json")
file(READ "${WORK}/compare.json" json)
string(JSON relmse GET "${json}" relmse)
message(STATUS "viewer vs lumina render: relMSE ${relmse} (tolerance ${TOLERANCE})")
if(relmse GREATER ${TOLERANCE})
  message(FATAL_ERROR "the viewer's frame differs from lumina render's: relMSE ${relmse} > ${TOLERANCE}")
endif()
