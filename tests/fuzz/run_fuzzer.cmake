# Builds tests/fuzz/project with clang and runs the glTF loader fuzzer for SECONDS on a seed
# corpus: the built-in scenes' files plus the small glTF files of assimp-testmodels. Fails
# when the fuzzer reports a crash, a sanitizer error, a timeout or an out-of-memory; the
# input that did it is left in WORK_DIR as crash-*, timeout-* or oom-*, and can be replayed
# with `WORK_DIR/build/gltf_loader_fuzzer FILE`.
#
#   cmake -DLUMINA_SOURCE_DIR=... -DWORK_DIR=... -DCLANGXX=clang++ -DSECONDS=60
#         [-DGENERATOR=Ninja] -P run_fuzzer.cmake
foreach(var LUMINA_SOURCE_DIR WORK_DIR CLANGXX SECONDS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzzer.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT DEFINED GENERATOR)
  set(GENERATOR Ninja)
endif()

set(build ${WORK_DIR}/build)
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${LUMINA_SOURCE_DIR}/tests/fuzz/project -B ${build} -G ${GENERATOR}
          -DCMAKE_CXX_COMPILER=${CLANGXX} -DCMAKE_BUILD_TYPE=RelWithDebInfo
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "fuzz: configuring the fuzzer project failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${build} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "fuzz: building the fuzzer failed")
endif()

# A fresh corpus each run (libFuzzer adds what it finds to it), seeds of at most 64 KiB so
# that mutations stay fast. tests/fuzz/regressions/ holds inputs that once failed: each run
# replays them first.
set(corpus ${WORK_DIR}/corpus)
file(REMOVE_RECURSE ${corpus})
file(MAKE_DIRECTORY ${corpus})
file(GLOB seeds ${LUMINA_SOURCE_DIR}/scenes/*/*.gltf ${LUMINA_SOURCE_DIR}/scenes/*/*.json
     ${LUMINA_SOURCE_DIR}/tests/fuzz/regressions/*)
file(GLOB_RECURSE assimp /usr/share/assimp/models/glTF2/*.gltf /usr/share/assimp/models/glTF2/*.glb
     /usr/share/assimp/models/glTF/*.gltf /usr/share/assimp/models/glTF/*.glb)
set(count 0)
foreach(seed IN LISTS seeds assimp)
  file(SIZE ${seed} size)
  if(size LESS_EQUAL 65536)
    get_filename_component(name ${seed} NAME)
    file(COPY_FILE ${seed} ${corpus}/${count}_${name})
    math(EXPR count "${count} + 1")
  endif()
endforeach()
message(STATUS "fuzz: ${count} seed files, ${SECONDS} s")

# Leak detection is off: LeakSanitizer needs ptrace, which CI containers often forbid.
execute_process(
  COMMAND ${build}/gltf_loader_fuzzer -max_total_time=${SECONDS} -max_len=65536 -timeout=20
          -dict=${LUMINA_SOURCE_DIR}/tests/fuzz/gltf.dict
          -rss_limit_mb=2048 -detect_leaks=0 -print_final_stats=1 -artifact_prefix=${WORK_DIR}/ ${corpus}
  WORKING_DIRECTORY ${WORK_DIR}
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  file(GLOB artifacts ${WORK_DIR}/crash-* ${WORK_DIR}/timeout-* ${WORK_DIR}/oom-* ${WORK_DIR}/leak-*)
  message(FATAL_ERROR "fuzz: the fuzzer failed (exit ${result}); input: ${artifacts}")
endif()
message(STATUS "fuzz: no crash in ${SECONDS} s")
