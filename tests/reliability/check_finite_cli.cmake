# `lumina render --check-finite` (docs/gi_tests.md#poison): a clean lumen run passes it, saying
# how many pass outputs it checked; and a glTF with a NaN vertex never reaches the GPU: the loader
# refuses it with an error naming the accessor, exit code 1.
include(${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake)

run(0 clean render cornell_box --size 32x32 --preset low --frames 3 --check-finite --out ${DIR}/clean.png)
expect_match(clean "${OUT}" "check-finite: 3 frame\\(s\\), [1-9][0-9]* pass outputs checked in the last; no NaN or Inf")

run(1 nan_vertex render ${CMAKE_CURRENT_LIST_DIR}/data/nan_vertex.gltf --size 32x32 --frames 1 --check-finite
    --out ${DIR}/nan.png)
expect_match(nan_vertex "${ERR}" "lumina: error: .*POSITION.*not finite")
