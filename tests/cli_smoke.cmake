# Helpers shared by the command-line smoke tests (tests/*/*_smoke.cmake), which run with
# cmake -P and include this file: LUMINA is the lumina executable.

# run(<expected exit code> <name> args...): runs lumina, leaves its output in OUT and ERR.
function(run expected name)
  execute_process(COMMAND "${LUMINA}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "[${name}] lumina ${ARGN} -> ${rc}\n${out}${err}")
  if(NOT rc EQUAL expected)
    message(FATAL_ERROR "[${name}] exit code ${rc}, expected ${expected}")
  endif()
  set(OUT "${out}" PARENT_SCOPE)
  set(ERR "${err}" PARENT_SCOPE)
endfunction()

function(expect_match name text regex)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "[${name}] output does not match '${regex}'")
  endif()
endfunction()
