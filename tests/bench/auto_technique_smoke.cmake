# `lumina render --technique auto --error-budget E` checked against an explicit bench run of the
# same matrix (docs/measurement.md): cmake -DLUMINA=... -DCHECK_AUTO=... -DDIR=... -P this, with
# LUMINA_CACHE_DIR=DIR/cache so both share one reference and the calibration cache is fresh.
# The bench runs first; its errors give three budgets: one every candidate meets, one that only a
# candidate more accurate than the clearly cheaper ones meets, one none meets (exit 1). The second
# render with a budget must reuse the cached calibration.
foreach(var LUMINA CHECK_AUTO DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "auto_technique_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

set(scene cornell_box)
run(0 matrix bench --scenes ${scene} --techniques direct,sh-grid --presets low,medium --size 16x16 --frames 4
    --reference-spp 16 --pt-budgets 1 --cache "${DIR}/cache/references" --out "${DIR}/matrix" --no-plot --validation)
execute_process(COMMAND python3 "${CHECK_AUTO}" budgets "${DIR}/matrix/bench.csv" OUTPUT_VARIABLE budgets
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check_auto_choice.py budgets failed")
endif()
list(GET budgets 0 all_meet)
list(GET budgets 1 split)
list(GET budgets 2 none_meet)
message(STATUS "budgets: every candidate ${all_meet}, some ${split}, none ${none_meet}")

set(auto render ${scene} --technique auto --auto-techniques direct,sh-grid --auto-presets low,medium
    --calibration-size 16x16 --calibration-frames 4 --calibration-spp 16 --size 16x16 --frames 1 --validation)
set(pass 0)
foreach(budget ${all_meet} ${split})
  math(EXPR pass "${pass} + 1")
  run(0 auto${pass} ${auto} --error-budget ${budget} --out "${DIR}/auto${pass}.png")
  expect_match(auto${pass} "${OUT}" "auto: chose ([a-z-]+) ([a-z]+): relMSE")
  string(REGEX MATCH "auto: chose ([a-z-]+) ([a-z]+):" chose "${OUT}")
  expect_match(auto${pass} "${OUT}" "technique: ${CMAKE_MATCH_1}")
  file(WRITE "${DIR}/auto${pass}.txt" "${OUT}")
  execute_process(COMMAND python3 "${CHECK_AUTO}" check "${DIR}/matrix/bench.csv" "${DIR}/auto${pass}.txt"
                  ${budget} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[auto${pass}] the choice disagrees with the matrix")
  endif()
endforeach()
expect_match(auto2 "${OUT}" "calibration at 16x16, 4 frames per candidate, against a 16-spp path-traced reference \\(reused")

# The bench's own check: the same matrix with --check-auto at the split budget (the calibration is
# the cached one, so auto must agree with the matrix: the SH grid at low).
run(0 bench-check bench --scenes ${scene} --techniques direct,sh-grid --presets low,medium --size 16x16 --frames 4
    --reference-spp 16 --pt-budgets 1 --cache "${DIR}/cache/references" --out "${DIR}/check" --no-plot
    --check-auto ${split} --calibration-size 16x16 --calibration-frames 4 --calibration-spp 16 --validation)
expect_match(bench-check "${OUT}" "auto check ${scene}, relMSE <= [0-9.]+: auto \\(calibrated at 16x16, 4 frames\\) chooses sh-grid low, the matrix's cheapest under the budget is sh-grid low: agrees")
if(NOT EXISTS "${DIR}/check/auto_check.csv")
  message(FATAL_ERROR "[bench-check] no auto_check.csv")
endif()
run(2 check-auto-sharded bench --scenes ${scene} --check-auto 0.1 --shard 0/2 --out "${DIR}/bad")

run(1 none-meets ${auto} --error-budget ${none_meet} --out "${DIR}/none.png")
expect_match(none-meets "${ERR}" "no candidate has relMSE <=")
run(2 no-budget render ${scene} --technique auto)
expect_match(no-budget "${ERR}" "needs --error-budget")
run(2 bad-budget render ${scene} --technique auto --error-budget -1)
run(2 preset-with-auto render ${scene} --technique auto --error-budget 1 --preset low)
run(2 budget-without-auto render ${scene} --technique direct --error-budget 1)
run(2 pathtracer-candidate render ${scene} --technique auto --error-budget 1 --auto-techniques pathtracer)
