# `lumina render --technique ddgi` end to end (docs/ddgi.md): cmake -DLUMINA=... -DDIR=... -P this.
# It renders with its passes timed and its probes counted; bad DDGI flags are usage errors
# (exit 2) that name the flag or the value.
foreach(var LUMINA DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "ddgi_cli_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")

include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

run(0 render render cornell_box --technique ddgi --preset low --size 32x32 --frames 3 --ddgi-probes 4,3,4
    --ddgi-rays 48 --timings --validation --out "${DIR}/ddgi.png")
expect_match(render "${OUT}" "technique: ddgi, preset low \\(one volume of 4x3x4 probes fitted to the scene, 48 rays")
expect_match(render "${OUT}" "ddgi: trace")
expect_match(render "${OUT}" "ddgi probes: 48, [0-9]+ inactive")
if(NOT EXISTS "${DIR}/ddgi.png")
  message(FATAL_ERROR "[render] wrote no image")
endif()

run(2 probes render cornell_box --technique ddgi --ddgi-probes 1)
expect_match(probes "${ERR}" "--ddgi-probes: '1'")
run(2 rays render cornell_box --technique ddgi --ddgi-rays 8)
expect_match(rays "${ERR}" "rays per probe 8")
run(2 hysteresis render cornell_box --technique ddgi --ddgi-hysteresis 1.5)
expect_match(hysteresis "${ERR}" "hysteresis 1.5")
run(2 spacing render cornell_box --technique ddgi --ddgi-spacing -3)
expect_match(spacing "${ERR}" "--ddgi-spacing must be a positive length")
