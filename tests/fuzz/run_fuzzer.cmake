# Builds the fuzzers of tests/fuzz/project with clang (MODE=build), or runs one of them for
# SECONDS on its seed corpus (MODE=run). A run fails when the fuzzer reports a crash, a
# sanitizer error, a timeout or an out-of-memory; the input that did it is left in WORK_DIR
# as crash-*, timeout-* or oom-*, and can be replayed with `BUILD_DIR/FUZZER FILE`.
#
#   cmake -DMODE=build -DLUMINA_SOURCE_DIR=... -DBUILD_DIR=... -DCLANGXX=clang++
#         [-DGENERATOR=Ninja] -P run_fuzzer.cmake
#   cmake -DMODE=run -DLUMINA_SOURCE_DIR=... -DBUILD_DIR=... -DFUZZER=png_reader_fuzzer
#         -DWORK_DIR=... -DSECONDS=30 "-DSEEDS=glob;glob" [-DDICT=file] -P run_fuzzer.cmake
# SEEDS are globs; relative ones are under LUMINA_SOURCE_DIR.
foreach(var MODE LUMINA_SOURCE_DIR BUILD_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzzer.cmake: -D${var}=... is required")
  endif()
endforeach()

if(MODE STREQUAL "build")
  if(NOT DEFINED GENERATOR)
    set(GENERATOR Ninja)
  endif()
  execute_process(
    COMMAND ${CMAKE_COMMAND} -S ${LUMINA_SOURCE_DIR}/tests/fuzz/project -B ${BUILD_DIR} -G ${GENERATOR}
            -DCMAKE_CXX_COMPILER=${CLANGXX} -DCMAKE_BUILD_TYPE=RelWithDebInfo
    RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "fuzz: configuring the fuzzer project failed")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "fuzz: building the fuzzers failed")
  endif()
  return()
endif()

foreach(var FUZZER WORK_DIR SECONDS SEEDS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzzer.cmake: -D${var}=... is required")
  endif()
endforeach()

# A fresh corpus each run (libFuzzer adds what it finds to it), seeds of at most 64 KiB so
# that mutations stay fast. tests/fuzz/regressions/<fuzzer>/ holds inputs that once failed:
# they are seeds too, so each run replays them first.
set(corpus ${WORK_DIR}/corpus)
file(REMOVE_RECURSE ${corpus})
file(MAKE_DIRECTORY ${corpus})
set(globs)
foreach(glob IN LISTS SEEDS)
  if(NOT IS_ABSOLUTE ${glob})
    set(glob ${LUMINA_SOURCE_DIR}/${glob})
  endif()
  list(APPEND globs ${glob})
endforeach()
file(GLOB_RECURSE seeds ${globs})
set(count 0)
foreach(seed IN LISTS seeds)
  file(SIZE ${seed} size)
  if(size LESS_EQUAL 65536)
    get_filename_component(name ${seed} NAME)
    file(COPY_FILE ${seed} ${corpus}/${count}_${name})
    math(EXPR count "${count} + 1")
  endif()
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "fuzz: no seed file matches ${SEEDS}")
endif()
message(STATUS "fuzz: ${FUZZER}, ${count} seed files, ${SECONDS} s")

set(dict_flag)
if(DEFINED DICT AND NOT DICT STREQUAL "")
  set(dict_flag -dict=${LUMINA_SOURCE_DIR}/${DICT})
endif()
# Leaks are reported too (LeakSanitizer; it needs ptrace, which some containers forbid: set
# LUMINA_FUZZ_DETECT_LEAKS=0 in the environment there).
set(detect_leaks 1)
if(DEFINED ENV{LUMINA_FUZZ_DETECT_LEAKS})
  set(detect_leaks $ENV{LUMINA_FUZZ_DETECT_LEAKS})
endif()
execute_process(
  COMMAND ${BUILD_DIR}/${FUZZER} -max_total_time=${SECONDS} -max_len=65536 -timeout=20 ${dict_flag}
          -rss_limit_mb=2048 -detect_leaks=${detect_leaks} -print_final_stats=1
          -artifact_prefix=${WORK_DIR}/ ${corpus}
  WORKING_DIRECTORY ${WORK_DIR}
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  file(GLOB artifacts ${WORK_DIR}/crash-* ${WORK_DIR}/timeout-* ${WORK_DIR}/oom-* ${WORK_DIR}/leak-*)
  message(FATAL_ERROR "fuzz: ${FUZZER} failed (exit ${result}); input: ${artifacts}")
endif()
message(STATUS "fuzz: ${FUZZER}: no crash in ${SECONDS} s")
