# No light through a wall (docs/gi.md, energy 29.): cmake -DLUMINA=... -DSCENE=... -DDIR=... -P this.
# The sealed box (tests/frame/data/sealed_box/) is six separate zero-thickness quads lit only from
# outside, seen from inside: its direct light is black there, and so must be its GI. Lumen at the
# low preset may bring in at most 1e-3 of mean radiance per channel, under a sky of 1.2 to 2.8
# and a 150 lux sun (the shipped tracer: 0; a trace that let rays pass where two of the quads
# meet: 0.005 to 0.016, sky blue).
foreach(var LUMINA SCENE DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "sealed_box_leak_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")

include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

run(0 direct render "${SCENE}" --technique direct --size 64x64 --frames 1 --validation
    --out "${DIR}/direct.exr")
run(0 lumen render "${SCENE}" --preset low --size 64x64 --validation --out "${DIR}/lumen.exr")
run(0 compare compare "${DIR}/direct.exr" "${DIR}/lumen.exr")

# "mean       reference (r, g, b), test (r, g, b)": the direct image must be black, the GI image
# nearly so.
set(number "[-+0-9.eE]+")
if(NOT OUT MATCHES "reference \\((${number}), (${number}), (${number})\\), test \\((${number}), (${number}), (${number})\\)")
  message(FATAL_ERROR "[compare] no mean line in its output")
endif()
set(direct "${CMAKE_MATCH_1};${CMAKE_MATCH_2};${CMAKE_MATCH_3}")
set(lumen "${CMAKE_MATCH_4};${CMAKE_MATCH_5};${CMAKE_MATCH_6}")
string(REPLACE ";" ", " shown_direct "${direct}")
string(REPLACE ";" ", " shown_lumen "${lumen}")
foreach(value IN LISTS direct)
  if(NOT value EQUAL 0)
    message(FATAL_ERROR "the direct light inside the sealed box is not black (${shown_direct}): the scene leaks before GI")
  endif()
endforeach()
foreach(value IN LISTS lumen)
  # CMake compares numbers as doubles; a mean written in exponent form is read as one too.
  if(value GREATER 0.001)
    message(FATAL_ERROR "lumen brings light into the sealed box: mean radiance ${shown_lumen} (at most 0.001 per channel)")
  endif()
endforeach()
message(STATUS "sealed box: direct ${shown_direct}, lumen ${shown_lumen}")
