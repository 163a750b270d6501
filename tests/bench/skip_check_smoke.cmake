# `lumina bench --verify-skips` on lavapipe (docs/measurement.md#skips): every skip of unchanged
# work forced off in turn must run its pass (no skip of it left in the forced run) and leave the
# image within relMSE 0.001 of the run with the skip. cornell_box_point: its point light's cube
# shadow map is reused by direct, the SH grid's bake stops once every probe has its bakes (by
# frame 24 at low), and lumen reuses its global SDF and its surface cache's capture, direct light,
# combine and voxel lighting, and stops radiosity once converged. Times are printed, never checked.
# cmake -DLUMINA=... -DDIR=... -P this.
foreach(var LUMINA DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "skip_check_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

run(0 skips bench --scenes cornell_box_point --techniques direct,sh-grid,lumen --presets low --size 16x16
    --frames 48 --reference-spp 16 --pt-budgets 1 --cache "${DIR}/references" --out "${DIR}/out" --no-plot
    --verify-skips --validation)
expect_match(skips "${OUT}" "skip check cornell_box_point / direct / low: 'point shadows' \\(unchanged since frame [0-9]+, 47 frame\\(s\\)\\): saves")
expect_match(skips "${OUT}" "wrote .*skips.csv")
if(NOT EXISTS "${DIR}/out/skips.csv")
  message(FATAL_ERROR "[skips] no skips.csv")
endif()
# Each forced group ran its pass in every forced frame and kept the image.
file(STRINGS "${DIR}/out/skips.csv" rows)
set(forced "")
foreach(row IN LISTS rows)
  # scene,technique,preset,pass,"reason",frames_skipped,forceable,frames_skipped_forced,...,within
  string(REGEX MATCH "^[^,]+,([^,]+),[^,]+,([^,]+),\"[^\"]*\",[0-9]+,1,([0-9]+),[^,]*,[^,]*,[^,]*,([^,]*),[^,]*,([01])$"
         match "${row}")
  if(match)
    list(APPEND forced "${CMAKE_MATCH_1}: ${CMAKE_MATCH_2}")
    if(NOT CMAKE_MATCH_3 EQUAL 0)
      message(FATAL_ERROR "[skips] forcing '${CMAKE_MATCH_2}' off left ${CMAKE_MATCH_3} skipped frame(s): ${row}")
    endif()
    if(NOT CMAKE_MATCH_5 EQUAL 1)
      message(FATAL_ERROR "[skips] '${CMAKE_MATCH_2}' changes the image by relMSE ${CMAKE_MATCH_4}: ${row}")
    endif()
  endif()
endforeach()
message(STATUS "forced: ${forced}")
foreach(expected "direct: point shadows" "sh-grid: sh grid: bake" "lumen: surface cache: radiosity trace"
                 "lumen: surface cache: direct light" "lumen: surface cache: combine"
                 "lumen: surface cache: card capture" "lumen: sdf: global compose")
  list(FIND forced "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "[skips] no forced check of ${expected} (forced: ${forced})")
  endif()
endforeach()
