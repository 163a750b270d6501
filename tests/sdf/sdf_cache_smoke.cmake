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

# One fresh cache for every run: lumina reads LUMINA_CACHE_DIR from its environment.
set(ENV{LUMINA_CACHE_DIR} "${DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

run(0 first sdf cornell_box --resolution 16 --build-only)
expect_match(first "${OUT}" "mesh SDFs: 8 meshes, 8 built \\([1-9][0-9]* voxels\\), 0 loaded from cache \\(0 voxels\\)")
file(GLOB cached "${DIR}/sdf/*.lsdf")
list(LENGTH cached count)
if(NOT count EQUAL 8)
  message(FATAL_ERROR "[first] ${count} cache files in ${DIR}/sdf, expected 8")
endif()

run(0 second sdf cornell_box --resolution 16 --build-only)
expect_match(second "${OUT}" "mesh SDFs: 8 meshes, 0 built \\(0 voxels\\), 8 loaded from cache \\([1-9][0-9]* voxels\\)")
expect_match(second "${OUT}" "loaded from cache, 0 voxels built")

# Another resolution is another cache key: built again.
run(0 third sdf cornell_box --resolution 20 --build-only)
expect_match(third "${OUT}" "8 built")
file(REMOVE_RECURSE "${DIR}")
