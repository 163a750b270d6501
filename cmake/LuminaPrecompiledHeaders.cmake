# Precompiled headers for Lumina's own code, GCC only (LUMINA_PRECOMPILED_HEADERS). One header,
# cmake/precompiled/library_headers.h, is compiled once by lumina_library_pch and reused
# (REUSE_FROM) by every library and executable whose name starts with "lumina" under the folders
# handed to lumina_reuse_library_pch, but for those with a header of their own (rhi_d3d12's
# d3d12_headers.h); the tests have their own (tests/precompiled_headers.h,
# compiled with the tests' flags). Measured on the 2-core machine: gi/bench/bench_report.cpp
# 24 s without, 15 s with; surface_cache.cpp 10 s and 6.3 s.
# GCC only: GCC reads a precompiled header made with other flags as absent and parses the header
# itself, where Clang and MSVC stop with an error; the fuzzers' Clang build never sees it.
# Not for the libraries of the MinGW build (its tests, at -O1, have theirs): with it, eight source
# files failed there, and on Linux, on GCC 12's false -Warray-bounds and -Wstringop-overflow
# reports inside char_traits (GCC bug 106199). Those two are off for GCC 12 now
# (cmake/LuminaWarnings.cmake), which the Linux build was checked with; the MinGW build was not.
option(LUMINA_PRECOMPILED_HEADERS "Precompile the common headers (GCC)" ON)
if(LUMINA_PRECOMPILED_HEADERS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  set(LUMINA_USE_PCH ON)
else()
  set(LUMINA_USE_PCH OFF)
endif()
if(LUMINA_USE_PCH AND NOT LUMINA_CROSS_WINDOWS)
  set(LUMINA_USE_LIBRARY_PCH ON)
else()
  set(LUMINA_USE_LIBRARY_PCH OFF)
endif()

# Targets whose sources are not Lumina's (Debian's Dear ImGui, built with its own flags).
set(LUMINA_PCH_EXCLUDED lumina_imgui)

if(LUMINA_USE_LIBRARY_PCH)
  find_package(glm REQUIRED)
  add_library(lumina_library_pch STATIC ${CMAKE_CURRENT_LIST_DIR}/precompiled/library_headers.cpp)
  target_link_libraries(lumina_library_pch PRIVATE glm::glm)
  lumina_target_warnings(lumina_library_pch)
  target_precompile_headers(lumina_library_pch PRIVATE ${CMAKE_CURRENT_LIST_DIR}/precompiled/library_headers.h)
endif()

# lumina_reuse_library_pch(<folder>...): every STATIC library and executable named lumina* defined
# under the folders (recursively) reuses lumina_library_pch.
function(lumina_reuse_library_pch)
  if(NOT LUMINA_USE_LIBRARY_PCH)
    return()
  endif()
  foreach(dir IN LISTS ARGN)
    get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
      get_target_property(type ${target} TYPE)
      get_target_property(own_pch ${target} PRECOMPILE_HEADERS) # rhi_d3d12 has its own
      if(target MATCHES "^lumina" AND NOT target IN_LIST LUMINA_PCH_EXCLUDED AND NOT own_pch
         AND (type STREQUAL "STATIC_LIBRARY" OR type STREQUAL "EXECUTABLE"))
        target_precompile_headers(${target} REUSE_FROM lumina_library_pch)
      endif()
    endforeach()
    get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
    if(subdirs)
      lumina_reuse_library_pch(${subdirs})
    endif()
  endforeach()
endfunction()
