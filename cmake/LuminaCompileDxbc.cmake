# One kernel to DXBC (cmake/LuminaShaders.cmake runs this with cmake -P):
#   GLSLANG VKD3D STAGE (comp/vert/frag) PROFILE (cs_5_1...) ENTRY ROOT SOURCE OUTPUT
# 1. glslangValidator -E expands includes (relative to the including file and to ROOT, as
#    for SPIR-V) and defines LUMINA_DXBC=1: vkd3d-compiler takes neither -I nor -D.
# 2. vkd3d-compiler compiles the expanded source to a DXBC container (shader model 5.1).
# Any failure stops the build with the compiler's messages.
set(expanded "${OUTPUT}.hlsl")
get_filename_component(outdir "${OUTPUT}" DIRECTORY)
file(MAKE_DIRECTORY "${outdir}")
execute_process(
  COMMAND ${GLSLANG} -D -E -S ${STAGE} -e ${ENTRY} -I${ROOT} -DLUMINA_DXBC=1 ${SOURCE}
  OUTPUT_FILE "${expanded}" ERROR_VARIABLE errors RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${SOURCE}: preprocessing for DXBC failed:\n${errors}")
endif()
execute_process(
  COMMAND ${VKD3D} -x hlsl -p ${PROFILE} -b dxbc-tpf -e ${ENTRY} -o ${OUTPUT}.tmp ${expanded}
  OUTPUT_VARIABLE messages ERROR_VARIABLE messages RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  file(REMOVE "${OUTPUT}.tmp")
  message(FATAL_ERROR "${SOURCE} (${ENTRY}): vkd3d-compiler failed (line numbers are those of "
    "${expanded}):\n${messages}")
endif()
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
