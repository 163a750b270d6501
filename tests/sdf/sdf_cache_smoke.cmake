# `lumina sdf` end to end on the mesh SDF cache: cmake -DLUMINA=... -DDIR=... -P this.
# Two runs on one fresh LUMINA_CACHE_DIR: the first builds every mesh SDF, the second loads
# them all and reports that it built nothing (the cache provably skips rebuilds).
foreach(var LUMINA DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "sdf_cache_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")

function(run name)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env "LUMINA_CACHE_DIR=${DIR}" "${LUMINA}" ${ARGN}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "[${name}] lumina ${ARGN} -> ${rc}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "[${name}] exit code ${rc}")
  endif()
  set(OUT "${out}" PARENT_SCOPE)
endfunction()

function(expect_match name text regex)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "[${name}] output does not match '${regex}'")
  endif()
endfunction()

run(first sdf cornell_box --resolution 16 --build-only)
expect_match(first "${OUT}" "mesh SDFs: 8 meshes, 8 built \\([1-9][0-9]* voxels\\), 0 loaded from cache \\(0 voxels\\)")
file(GLOB cached "${DIR}/sdf/*.lsdf")
list(LENGTH cached count)
if(NOT count EQUAL 8)
  message(FATAL_ERROR "[first] ${count} cache files in ${DIR}/sdf, expected 8")
endif()

run(second sdf cornell_box --resolution 16 --build-only)
expect_match(second "${OUT}" "mesh SDFs: 8 meshes, 0 built \\(0 voxels\\), 8 loaded from cache \\([1-9][0-9]* voxels\\)")
expect_match(second "${OUT}" "loaded from cache, 0 voxels built")

# Another resolution is another cache key: built again.
run(third sdf cornell_box --resolution 20 --build-only)
expect_match(third "${OUT}" "8 built")
file(REMOVE_RECURSE "${DIR}")
