# LUMINA_SANITIZE=ON: AddressSanitizer, UndefinedBehaviorSanitizer and LeakSanitizer (part of
# ASan on Linux) on every target of the build, for .ci/sanitizers.sh and debugging by hand.
# Use a build folder of its own (build-asan): objects built with and without sanitizers do not
# link together. Runtime options and the suppressions of system libraries are not set here but
# in the environment (tests/sanitizers/*.supp, read by .ci/sanitizers.sh; docs/gi_tests.md).
option(LUMINA_SANITIZE "Build with ASan + UBSan + LeakSanitizer (GCC or Clang)" OFF)
if(NOT LUMINA_SANITIZE)
  return()
endif()
if(MSVC OR LUMINA_CROSS_WINDOWS)
  message(FATAL_ERROR "LUMINA_SANITIZE is for GCC or Clang on Linux")
endif()
# -O0 by default: the GPU tests' time is lavapipe's (not instrumented), and -O0 compiles in
# about 60% of -O1's CPU time, which is what bounds the CI step on 2 cores (docs/gi_tests.md).
# -g1 gives file:line in every report; frame pointers give whole stacks. Undefined behaviour
# aborts (no recovery), so a report cannot scroll past a passing test.
set(LUMINA_SANITIZE_OPTIMIZE -O0 CACHE STRING "Optimisation level of the sanitizer build")
add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer ${LUMINA_SANITIZE_OPTIMIZE} -g1)
add_link_options(-fsanitize=address,undefined)
# GCC's flow-sensitive warnings (-Wmaybe-uninitialized, -Wstringop-*) misfire on sanitizer
# instrumentation; the ordinary build is where warnings are errors.
set(LUMINA_WERROR OFF CACHE BOOL "Treat compiler warnings as errors" FORCE)
message(STATUS "Lumina: ASan + UBSan + LeakSanitizer build (warnings are not errors here)")
