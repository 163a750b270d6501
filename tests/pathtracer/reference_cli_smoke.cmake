# Smoke test of `lumina reference` end to end: cmake -DLUMINA=... -DDIR=... -P this.
# A tiny render with AOVs and a PNG, a --target-error stop, and bad input (exit codes 1 and 2).
foreach(var LUMINA DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "reference_cli_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")

include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

set(num "[0-9]+(\\.[0-9]+)?(e[-+][0-9]+)?")

# 1. A render: figures printed, progress on stderr, the EXR (with AOV channels) and the PNG written.
run(0 render reference cornell_box --size 16x16 --spp 4 --aovs --validation
    --out "${DIR}/ref.exr" --png "${DIR}/ref.png")
expect_match(render "${OUT}" "cornell_box: 16x16, 4 spp in")
expect_match(render "${OUT}" "${num} samples/s, ${num} rays/s")
expect_match(render "${ERR}" "4/4 spp")
foreach(file ref.exr ref.png)
  if(NOT EXISTS "${DIR}/${file}")
    message(FATAL_ERROR "[render] ${file} was not written")
  endif()
endforeach()
file(READ "${DIR}/ref.exr" header LIMIT 4096 HEX)
foreach(channel R variance.R albedo.R normal.X direct.R indirect.R)
  string(HEX "${channel}" hexName)
  if(NOT header MATCHES "00${hexName}00")
    message(FATAL_ERROR "[render] channel ${channel} missing from ref.exr")
  endif()
endforeach()

# 2. --target-error stops early: far fewer than the cap.
run(0 target reference furnace_0.5 --size 16x16 --target-error 0.2 --out "${DIR}/target.exr")
expect_match(target "${OUT}" "16x16, ([0-9]|[1-9][0-9]) spp in")

# 3. Bad input: a clear message and a non-zero exit code.
run(1 unknown-scene reference no_such_scene --out "${DIR}/x.exr")
expect_match(unknown-scene "${ERR}" "no_such_scene")
run(2 zero-spp reference cornell_box --spp 0)
run(2 bad-target reference cornell_box --target-error nope)
run(2 no-scene reference)
run(2 bad-out-dir reference cornell_box --out "${DIR}/missing/dir/x.exr")
expect_match(bad-out-dir "${ERR}" "no directory")
run(2 no-animation reference cornell_box --spp 1 --animation-frame 3 --out "${DIR}/x.exr")
expect_match(no-animation "${ERR}" "--animation-frame: scene 'cornell_box' has no animation")

# 4. --animation-frame poses an animated scene: `door` open (frame 240) is not `door` shut, whose
# dark room then takes the lamp's light through the doorway.
run(0 shut reference door --size 16x16 --spp 4 --out "${DIR}/door_shut.exr")
run(0 open reference door --size 16x16 --spp 4 --animation-frame 240 --out "${DIR}/door_open.exr")
run(0 open-differs compare "${DIR}/door_shut.exr" "${DIR}/door_open.exr")
set(n "[0-9.e+-]+")
if(NOT OUT MATCHES "reference \\(${n}, (${n}), ${n}\\), test \\(${n}, (${n}), ${n}\\)")
  message(FATAL_ERROR "[open-differs] no mean in the comparison:\n${OUT}")
endif()
# The green means.
set(shut "${CMAKE_MATCH_1}")
set(open "${CMAKE_MATCH_2}")
if(NOT open GREATER 0.001 OR NOT open GREATER shut)
  message(FATAL_ERROR "[open-differs] the door posed open is no brighter than shut (green ${open} against ${shut}):\n${OUT}")
endif()
