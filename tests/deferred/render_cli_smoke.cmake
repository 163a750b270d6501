# `lumina render` output names, end to end: cmake -DLUMINA=... -DDIR=... -P this.
# --out picks the format from its extension: .png the display image, .exr the linear one (which
# `lumina compare` must read back); any other extension is a usage error (exit 2) before rendering.
foreach(var LUMINA DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "render_cli_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")

include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

run(0 exr render cornell_box_point --technique direct --size 16x16 --frames 1 --validation --out "${DIR}/a/linear.exr")
expect_match(exr "${OUT}" "linear.exr \\(linear HDR radiance\\)")
run(0 exr-reads-back compare "${DIR}/a/linear.exr" "${DIR}/a/linear.exr")

run(2 bad-extension render cornell_box_point --technique direct --size 16x16 --frames 1 --out "${DIR}/image.jpg")
expect_match(bad-extension "${ERR}" "image.jpg: the image is written as .png \\(display\\) or .exr \\(linear HDR\\)")
if(EXISTS "${DIR}/image.jpg")
  message(FATAL_ERROR "[bad-extension] a file was written")
endif()

# --async-compute: auto, on or off (docs/performance.md, change 3); anything else is a usage
# error before the scene loads. `on` on lavapipe (whose compute queue shares the graphics one)
# still splits the frame and says so.
run(2 bad-async-mode render cornell_box_point --technique direct --size 16x16 --frames 1 --async-compute maybe)
expect_match(bad-async-mode "${ERR}" "--async-compute: 'maybe' is not auto, on or off")
run(0 async-on render cornell_box_point --technique ddgi --preset low --size 16x16 --frames 3 --validation
    --async-compute on --out "${DIR}/async.png")
expect_match(async-on "${OUT}" "async compute: 2 of 3 frame\\(s\\) ran GI passes on the compute queue")

# --mesh-sdf-resolution and --global-sdf-resolution (docs/gi.md, energy 48.): out of range, or
# given to a technique that traces no SDF, is a usage error; in range, the SDFs are built at it.
run(2 mesh-sdf-range render cornell_box_point --size 16x16 --frames 1 --mesh-sdf-resolution 1000)
expect_match(mesh-sdf-range "${ERR}" "--mesh-sdf-resolution: 1000 is out of range \\[8, 512\\]")
run(2 global-sdf-direct render cornell_box_point --technique direct --size 16x16 --frames 1
    --global-sdf-resolution 32)
expect_match(global-sdf-direct "${ERR}" "--global-sdf-resolution applies only to the techniques that trace SDFs")
run(0 sdf-resolutions render cornell_box_point --preset low --size 16x16 --frames 2 --validation
    --mesh-sdf-resolution 24 --global-sdf-resolution 32 --out "${DIR}/sdf.png")
expect_match(sdf-resolutions "${OUT}" "SDFs 0\\.5 MiB") # 3.7 MiB at the presets' 64 and 64
