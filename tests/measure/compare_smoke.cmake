# Smoke test of `lumina compare` on real files: cmake -DLUMINA=... -DMAKER=... -DDIR=... -P this.
# Checks exit codes (0 ok, 1 NaN/Inf or I/O, 2 usage), printed figures, the heat map and JSON.
foreach(var LUMINA MAKER DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "compare_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")

execute_process(COMMAND "${MAKER}" "${DIR}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "make_compare_inputs failed: ${rc}")
endif()

include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

set(num "[0-9]+(\\.[0-9]+)?(e[-+][0-9]+)?")

# 1. A real difference: sane, non-zero figures, a heat map and a JSON file.
run(0 differ compare "${DIR}/ref.exr" "${DIR}/test.exr" --heatmap "${DIR}/diff.png" --json "${DIR}/out.json")
expect_match(differ "${OUT}" "relMSE +${num}")
expect_match(differ "${OUT}" "RMSE +${num}")
expect_match(differ "${OUT}" "PSNR +${num} dB")
expect_match(differ "${OUT}" "max error +relMSE ${num} at \\([0-9]+, [0-9]+\\)")
expect_match(differ "${OUT}" "FLIP +mean 0\\.[0-9]+")
expect_match(differ "${OUT}" "NaN/Inf +reference 0 NaN \\+ 0 Inf pixels, test 0 NaN \\+ 0 Inf pixels")
string(REGEX MATCH "relMSE +(${num})" _ "${OUT}")
set(relmse "${CMAKE_MATCH_1}")
if(relmse LESS_EQUAL 0 OR relmse GREATER 1)
  message(FATAL_ERROR "[differ] relMSE ${relmse} is not in (0, 1]")
endif()
string(REGEX MATCH "PSNR +(${num})" _ "${OUT}")
if(CMAKE_MATCH_1 LESS 10 OR CMAKE_MATCH_1 GREATER 80)
  message(FATAL_ERROR "[differ] PSNR ${CMAKE_MATCH_1} dB is not plausible")
endif()
string(REGEX MATCH "max error +relMSE [^ ]+ at \\(([0-9]+), ([0-9]+)\\)" _ "${OUT}")
if(CMAKE_MATCH_1 LESS 8 OR CMAKE_MATCH_1 GREATER 23 OR CMAKE_MATCH_2 LESS 8 OR CMAKE_MATCH_2 GREATER 23)
  message(FATAL_ERROR "[differ] worst pixel (${CMAKE_MATCH_1}, ${CMAKE_MATCH_2}) is outside the changed patch")
endif()
foreach(file diff.png out.json)
  if(NOT EXISTS "${DIR}/${file}")
    message(FATAL_ERROR "[differ] ${file} was not written")
  endif()
endforeach()
file(READ "${DIR}/diff.png" png_head LIMIT 8 HEX)
if(NOT png_head STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "[differ] diff.png is not a PNG (${png_head})")
endif()
file(READ "${DIR}/out.json" json)
string(JSON json_relmse GET "${json}" relmse)
string(JSON json_flip GET "${json}" flip mean)
string(JSON json_ok GET "${json}" ok)
if(json_relmse LESS_EQUAL 0 OR json_flip LESS_EQUAL 0 OR json_flip GREATER 1 OR NOT json_ok)
  message(FATAL_ERROR "[differ] JSON figures relmse=${json_relmse} flip=${json_flip} ok=${json_ok}")
endif()

# 2. An image against itself: zero error, infinite PSNR.
run(0 same compare "${DIR}/ref.exr" "${DIR}/ref.exr")
expect_match(same "${OUT}" "relMSE +0 ")
expect_match(same "${OUT}" "PSNR +inf dB")
expect_match(same "${OUT}" "FLIP +mean 0,")

# 3. NaN/Inf: exit 1, named file and counts.
run(1 nan compare "${DIR}/ref.exr" "${DIR}/nan.exr")
expect_match(nan "${ERR}" "nan\\.exr: 1 NaN \\+ 1 Inf pixels")

# 4. I/O errors name the file: exit 1.
run(1 missing compare "${DIR}/ref.exr" "${DIR}/missing.exr")
expect_match(missing "${ERR}" "missing\\.exr: file not found")
run(1 size compare "${DIR}/ref.exr" "${DIR}/small.exr")
expect_match(size "${ERR}" "small\\.exr is 32x24")
run(1 unwritable compare "${DIR}/ref.exr" "${DIR}/test.exr" --heatmap "${DIR}/no/such/dir/diff.png")
expect_match(unwritable "${ERR}" "diff\\.png")

# 5. --exact V: the reference is constant radiance V. Against its own value a flat image is exact;
# against 2.5 every channel is off by 0.5: relMSE 0.25 / (6.25 + 0.01).
run(0 exact_same compare --exact 2 "${DIR}/flat.exr")
expect_match(exact_same "${OUT}" "relMSE +0 ")
expect_match(exact_same "${OUT}" "exact 2 \\(reference\\)")
run(0 exact_off compare --exact 2.5 "${DIR}/flat.exr")
expect_match(exact_off "${OUT}" "relMSE +0\\.039936")
expect_match(exact_off "${OUT}" "mean +reference \\(2\\.5, 2\\.5, 2\\.5\\), test \\(2, 2, 2\\)")
run(2 exact_two_images compare --exact 2 "${DIR}/ref.exr" "${DIR}/flat.exr")
expect_match(exact_two_images "${ERR}" "takes one image")
run(2 exact_negative compare --exact -1 "${DIR}/flat.exr")
expect_match(exact_negative "${ERR}" "--exact: -1")
run(2 exact_nan compare --exact nan "${DIR}/flat.exr")

# 6. Usage errors: exit 2.
run(2 one_arg compare "${DIR}/ref.exr")
run(2 bad_ppd compare "${DIR}/ref.exr" "${DIR}/test.exr" --ppd 0)
run(2 bad_flag compare "${DIR}/ref.exr" "${DIR}/test.exr" --heat)
message(STATUS "compare smoke test: all checks passed")
