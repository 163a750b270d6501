# `lumina bench` end to end at a small size (not a timed test): run it twice on one fresh cache
# folder, check the files and figures (check_bench_output.py), and that the second run reused
# the references instead of rendering them again; then once with lumen (low preset, a few frames:
# on lavapipe its surface-cache radiosity costs about a second a frame until it converges).
# cmake -DLUMINA=... -DCHECK=... -DDIR=... -P this
foreach(var LUMINA CHECK DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "bench_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
set(args bench --scenes cornell_box_point,open_top_box --size 24x24 --frames 4 --reference-spp 16
         --presets low,high --pt-budgets 1,4 --cache "${DIR}/cache" --out "${DIR}/out" --validation)
# Two scenes x (2 direct presets + 2 path-tracer budgets).
set(expected_runs 8)

foreach(pass first second)
  execute_process(COMMAND "${LUMINA}" ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "[${pass}] lumina bench -> ${rc}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[${pass}] lumina bench exited with ${rc}")
  endif()
  execute_process(COMMAND python3 "${CHECK}" "${DIR}/out" ${expected_runs} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[${pass}] the bench's output failed its checks")
  endif()
  set(${pass}_out "${out}")
endforeach()
if(NOT first_out MATCHES "reference cornell_box_point: rendered")
  message(FATAL_ERROR "the first run did not render its reference")
endif()
if(NOT second_out MATCHES "reference cornell_box_point: reused" OR NOT second_out MATCHES "reference open_top_box: reused")
  message(FATAL_ERROR "the second run rendered its references again instead of reusing them")
endif()

# Lumen, DDGI and the SH grid beside direct, and the path tracer at lumen's frame time.
set(lumen_args bench --scenes cornell_box_point --techniques direct,lumen,ddgi,sh-grid,pathtracer --presets low
                --size 32x32 --frames 3 --reference-spp 16 --pt-budgets 1 --cache "${DIR}/cache"
                --out "${DIR}/lumen" --validation)
execute_process(COMMAND "${LUMINA}" ${lumen_args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "[lumen] lumina bench -> ${rc}\n${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "[lumen] lumina bench exited with ${rc}")
endif()
# One scene x (direct low + lumen low + ddgi low + sh-grid low + one path-tracer budget).
execute_process(COMMAND python3 "${CHECK}" "${DIR}/lumen" 5 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "[lumen] the bench's output failed its checks")
endif()

# Bad input: a clear message and exit code 2.
foreach(bad "--techniques;magic" "--presets;ultra" "--pt-budgets;0" "--scenes;,")
  execute_process(COMMAND "${LUMINA}" bench ${bad} --out "${DIR}/bad" RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "lumina bench ${bad} exited with ${rc}, expected 2: ${err}")
  endif()
endforeach()
