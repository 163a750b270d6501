# `lumina render --technique sh-grid` end to end (docs/sh_grid.md): cmake -DLUMINA=... -DDIR=... -P this.
# It bakes a small grid with its passes timed, then renders on with nothing left to bake (the bake
# reported skipped, with its reason), saves the grid and renders from the saved grid; bad SH grid
# flags and files are errors that name the flag, value or file.
foreach(var LUMINA DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "sh_grid_cli_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")

include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

# 2^3 probes (the flag sets the largest side's count), 8 a frame, 3 sweeps: baked after 3 frames.
run(0 render render cornell_box_point --technique sh-grid --preset low --size 32x32 --frames 5 --sh-grid-probes 2
    --sh-grid-face 8 --timings --validation --out "${DIR}/sh.png" --sh-grid-save "${DIR}/grid.shgrid")
expect_match(render "${OUT}" "technique: sh-grid, preset low \\(2x2x2 probes, 8\\^2 cube faces, 8 probes baked per frame")
expect_match(render "${OUT}" "sh grid: bake direct light")
expect_match(render "${OUT}" "sh grid: bake: skipped in 2 frame\\(s\\), no probe dirty or owed a bake")
expect_match(render "${OUT}" "wrote .*grid.shgrid")
if(NOT EXISTS "${DIR}/sh.png")
  message(FATAL_ERROR "[render] wrote no image")
endif()

run(0 load render cornell_box_point --technique sh-grid --preset low --size 32x32 --frames 2 --sh-grid-probes 2
    --sh-grid-face 8 --timings --validation --out "${DIR}/loaded.png" --sh-grid-load "${DIR}/grid.shgrid")
expect_match(load "${OUT}" "sh grid: bake: skipped in 2 frame\\(s\\)")

run(1 other render cornell_box_point --technique sh-grid --preset low --size 32x32 --frames 1 --sh-grid-probes 3
    --sh-grid-face 8 --sh-grid-load "${DIR}/grid.shgrid")
expect_match(other "${ERR}" "baked for another grid")
run(2 probes render cornell_box --technique sh-grid --sh-grid-probes 1)
expect_match(probes "${ERR}" "sh-grid-probes")
run(2 window render cornell_box --technique sh-grid --sh-grid-window 1)
expect_match(window "${ERR}" "ringing window 1")
