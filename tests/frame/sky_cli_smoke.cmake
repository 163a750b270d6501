# The default light and sky flags end to end (docs/scenes.md): cmake -DLUMINA=... -DDIR=... -P this.
# A glTF without light is lit by default and says so, stays dark with --no-default-light; --sky
# takes an EXR (one `lumina render` writes) and refuses a missing one (exit 1); --sky-intensity
# without --sky is a usage error (exit 2); the real-asset scene renders by name.
foreach(var LUMINA DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "sky_cli_smoke: -D${var}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")

include("${CMAKE_CURRENT_LIST_DIR}/../cli_smoke.cmake")

set(box /usr/share/assimp/models/glTF2/BoxTextured-glTF/BoxTextured.gltf)
if(NOT EXISTS "${box}")
  message(STATUS "assimp-testmodels is not installed: skipping")
  return()
endif()

run(0 default-light info "${box}")
expect_match(default-light "${OUT}" "lights: none in the file; added the default sun and sky \\(--no-default-light turns this off\\)")
run(0 no-default-light info "${box}" --no-default-light)
expect_match(no-default-light "${OUT}" "the default light is off: the image is black")

run(1 missing-sky info cornell_box --sky "${DIR}/missing.exr")
expect_match(missing-sky "${ERR}" "missing.exr: sky environment: no such file")
run(2 intensity-alone info cornell_box --sky-intensity 2)
expect_match(intensity-alone "${ERR}" "--sky-intensity: applies to a --sky environment")

run(0 make-environment render cornell_box_point --technique direct --size 8x4 --frames 1 --out "${DIR}/env.exr")
run(0 render-under-sky render "${box}" --technique direct --size 16x16 --frames 1 --validation
    --sky "${DIR}/env.exr" --sky-intensity 2 --out "${DIR}/box.png")
expect_match(render-under-sky "${OUT}" "sky environment .*env.exr \\(8x4\\)")

run(0 real-asset render two_cylinder_engine --technique direct --size 32x24 --frames 1 --validation
    --out "${DIR}/engine.png")
