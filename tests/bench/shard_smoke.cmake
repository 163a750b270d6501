# Sharded batch runs end to end on lavapipe (docs/batch.md): cmake -DLUMINA=... -DCHECK=...
# -DCOMPARE=... -DDIR=... -P this.
# 1. A reference as 4 shards, merged, is byte for byte the file one unsharded run writes: a
#    pixel's random numbers depend on (seed, its index in the whole image, sample index), never
#    on the rows a run traces, so the merge is exact, not just within the variance.
# 2. A bench as 2 shards, merged, has one run's rows in one run's order, with the same error
#    figures where they do not depend on timing (check_bench_merge.py).
# 3. Bad input: a clear message and a non-zero exit code.
foreach(var LUMINA CHECK COMPARE DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "shard_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

# 1. Reference: 4 shards against one run (an odd height: bands of 5, 4, 5, 4 rows).
set(ref reference cornell_box_point --size 20x18 --spp 4 --aovs --validation)
run(0 whole ${ref} --out "${DIR}/whole.exr")
set(parts "")
foreach(i 0 1 2 3)
  run(0 shard${i} ${ref} --shard ${i}/4 --out "${DIR}/part${i}.exr")
  expect_match(shard${i} "${ERR}" "shard ${i}/4: rows")
  list(APPEND parts "${DIR}/part${i}.exr")
endforeach()
run(0 merge merge "${DIR}/merged.exr" ${parts} --png "${DIR}/merged.png")
expect_match(merge "${OUT}" "merged 4 shards of cornell_box_point \\(20x18, 4 spp")
file(SHA256 "${DIR}/whole.exr" whole_hash)
file(SHA256 "${DIR}/merged.exr" merged_hash)
if(NOT whole_hash STREQUAL merged_hash)
  message(FATAL_ERROR "[merge] the merged reference differs from one run's file")
endif()

# 2. Bench: two scenes, direct at two presets and the path tracer at one budget: 2 units.
set(bench bench --scenes cornell_box_point,open_top_box --techniques direct,pathtracer --presets low,high
          --pt-budgets 1 --size 16x16 --frames 2 --reference-spp 8 --cache "${DIR}/cache" --validation)
run(0 bench-whole ${bench} --out "${DIR}/bench_whole")
run(0 bench-shard1 ${bench} --shard 1/2 --out "${DIR}/bench1")
run(0 bench-shard0 ${bench} --shard 0/2 --out "${DIR}/bench0")
run(0 bench-merge merge "${DIR}/bench_merged" "${DIR}/bench1" "${DIR}/bench0")
expect_match(bench-merge "${OUT}" "merged 2 bench shards: 6 rows")
execute_process(COMMAND python3 "${COMPARE}" "${DIR}/bench_whole" "${DIR}/bench_merged" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "[bench-merge] the merged bench differs from one run's")
endif()
execute_process(COMMAND python3 "${CHECK}" "${DIR}/bench_merged" 6 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "[bench-merge] the merged bench failed the bench's output checks")
endif()

# 3. Bad input.
run(2 malformed reference cornell_box --shard 1-4)
expect_match(malformed "${ERR}" "--shard: expected i/n")
run(2 index-too-large reference cornell_box --shard 4/4)
expect_match(index-too-large "${ERR}" "below the count")
run(2 zero-shards reference cornell_box --shard 0/0)
run(2 more-shards-than-rows reference cornell_box --size 8x3 --shard 0/4)
expect_match(more-shards-than-rows "${ERR}" "3 rows cannot be split into 4")
run(2 with-target-error reference cornell_box --shard 0/2 --target-error 0.1)
run(2 too-many-bench-shards ${bench} --shard 2/3 --out "${DIR}/bad")
expect_match(too-many-bench-shards "${ERR}" "use at most 2 shards")
run(1 missing-shard merge "${DIR}/bad.exr" "${DIR}/part0.exr" "${DIR}/part1.exr" "${DIR}/part3.exr")
expect_match(missing-shard "${ERR}" "shard 2/4 is missing")
run(1 twice merge "${DIR}/bad.exr" ${parts} "${DIR}/part1.exr")
expect_match(twice "${ERR}" "both shard 1/4")
run(0 other-run ${ref} --spp 2 --shard 2/4 --out "${DIR}/other2.exr")
run(1 different-runs merge "${DIR}/bad.exr" "${DIR}/part0.exr" "${DIR}/part1.exr" "${DIR}/other2.exr"
    "${DIR}/part3.exr")
expect_match(different-runs "${ERR}" "shards of different runs: spp 2 against 4")
run(1 not-a-shard merge "${DIR}/bad.exr" "${DIR}/whole.exr")
expect_match(not-a-shard "${ERR}" "is not a reference shard")
run(2 no-such-file merge "${DIR}/bad.exr" "${DIR}/nothing.exr")
run(1 bench-missing merge "${DIR}/bad" "${DIR}/bench0")
expect_match(bench-missing "${ERR}" "shard 1/2 is missing")
run(1 bench-not-a-shard merge "${DIR}/bad" "${DIR}/bench0" "${DIR}/bench_whole")
expect_match(bench-not-a-shard "${ERR}" "is not a bench shard")
run(2 mixed merge "${DIR}/bad" "${DIR}/bench0" "${DIR}/part0.exr")
if(EXISTS "${DIR}/bad.exr")
  message(FATAL_ERROR "a failed merge wrote its output")
endif()
