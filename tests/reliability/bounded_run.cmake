# bounded_run(<expected exit code> <name> <seconds> program args...): cli_smoke.cmake's run() for
# any program, under coreutils' timeout: a run that hangs is killed after <seconds> and fails
# with exit code 124 and its name, instead of holding the test until ctest's TIMEOUT. OUT and ERR
# as run() leaves them; expect_match() from cli_smoke.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake)
find_program(LUMINA_TIMEOUT timeout REQUIRED)

function(bounded_run expected name seconds)
  set(LUMINA "${LUMINA_TIMEOUT}")
  run(${expected} ${name} --kill-after=10 ${seconds} ${ARGN})
  set(OUT "${OUT}" PARENT_SCOPE)
  set(ERR "${ERR}" PARENT_SCOPE)
endfunction()
