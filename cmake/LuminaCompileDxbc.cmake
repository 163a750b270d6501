# One kernel to DXBC (cmake/LuminaShaders.cmake runs this with cmake -P):
#   GLSLANG VKD3D STAGE (comp/vert/frag) PROFILE (cs_5_1...) ENTRY ROOT SOURCE OUTPUT
# 1. glslangValidator -E expands includes (relative to the including file and to ROOT, as
#    for SPIR-V) and defines LUMINA_DXBC=1: vkd3d-compiler takes neither -I nor -D.
#    Every loop not marked otherwise gets [loop]: vkd3d-shader 2.1 otherwise tries to unroll
#    every loop it can, which took minutes and gigabytes per kernel (bvh/bvh_raycast_test: 5 s
#    of CPU, 0.04 s with [loop]; screen_probes/probe_ray_shading: over 3 minutes). Loops the
#    source marks [unroll] stay unrolled. DXC and glslang never see this (their SPIR-V and
#    DXIL are unchanged). The kernels have no do-while loops, whose `while` this would break.
# 2. vkd3d-compiler compiles the expanded source to a DXBC container (shader model 5.1).
# 3. Where PYTHON is given, the container's disassembly (<name>.dxbc.asm) goes through CHECK
#    (check_dxbc_casts.py): vkd3d-shader 2.1 silently miscompiles one value cast to two types,
#    and a kernel where it did fails the build, naming the instructions (docs/d3d12.md).
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
file(READ "${expanded}" text)
string(REGEX REPLACE "(^|[^A-Za-z0-9_])(for|while)([ \t]*\\()" "\\1[loop] \\2\\3" text "${text}")
string(REGEX REPLACE "\\]([ \t\n]*)\\[loop\\] " "]\\1" text "${text}") # keep [unroll] for
file(WRITE "${expanded}" "${text}")
execute_process(
  COMMAND ${VKD3D} -x hlsl -p ${PROFILE} -b dxbc-tpf -e ${ENTRY} -o ${OUTPUT}.tmp ${expanded}
  OUTPUT_VARIABLE messages ERROR_VARIABLE messages RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  file(REMOVE "${OUTPUT}.tmp")
  message(FATAL_ERROR "${SOURCE} (${ENTRY}): vkd3d-compiler failed (line numbers are those of "
    "${expanded}):\n${messages}")
endif()
if(PYTHON)
  execute_process(
    COMMAND ${VKD3D} -x dxbc-tpf -b d3d-asm -o ${OUTPUT}.asm ${OUTPUT}.tmp
    OUTPUT_VARIABLE messages ERROR_VARIABLE messages RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    file(REMOVE "${OUTPUT}.tmp")
    message(FATAL_ERROR "${SOURCE} (${ENTRY}): vkd3d-compiler could not disassemble its DXBC:\n${messages}")
  endif()
  execute_process(
    COMMAND ${PYTHON} ${CHECK} ${OUTPUT}.asm ${SOURCE}
    OUTPUT_VARIABLE messages ERROR_VARIABLE messages RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    file(REMOVE "${OUTPUT}.tmp")
    message(FATAL_ERROR "${SOURCE} (${ENTRY}): its DXBC would compute wrong results on D3D12 "
      "(line numbers are those of ${OUTPUT}.asm); cast the value once and derive the other type "
      "from that cast:\n${messages}")
  endif()
endif()
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
