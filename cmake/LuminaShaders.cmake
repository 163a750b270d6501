# The HLSL toolchain. Every kernel under shaders/ declares its entry points in
# a comment line of its own:
#
#   // lumina-kernel: cs main
#   // lumina-kernel: vs vsMain
#   // lumina-kernel: ps psMain
#
# and is compiled at build time to SPIR-V (DXC when found, else glslangValidator
# with --hlsl-iomap and the register shifts of docs/binding.md), then checked with
# spirv-val; to DXIL as well where DXC is found, and to DXBC (shader model 5.1, what Wine's
# vkd3d takes) where vkd3d-compiler (2.1 tested) is found (LUMINA_VKD3D_COMPILER;
# .ci/install-dxbc-tools.sh puts it in /opt/lumina/d3d12-tools/bin). A kernel that fails
# fails the build.
#
# A source whose kernels vkd3d-shader cannot compile says so, with the reason, in a line
#
#   // lumina-no-dxbc: vkd3d-shader has no RWByteAddressBuffer.Load
#
# and gets <name>.dxbc.unavailable (the reason, which the loader and the tests report)
# instead of <name>.dxbc. Everything else differing between compilers lives in
# shaders/common/ behind macros (LUMINA_SPIRV, LUMINA_DXBC; docs/d3d12.md).
#
# Kernel names are the source path under shaders/ without ".hlsl", plus ".<entry>"
# when the entry point is not "main": shaders/rhi_tests/fill.hlsl -> "rhi_tests/fill",
# its vsMain entry -> "rhi_tests/fill.vsMain". Outputs land in ${LUMINA_SHADER_OUTPUT_DIR}
# as <name>.spv, <name>.dxil and <name>.dxbc, where the runtime loads them by name.

#
# -DLUMINA_PREBUILT_KERNELS_DIR=<another build's shaders folder> compiles no kernel and loads that
# folder's instead: kernels are the same whatever compiler builds the C++, so CI's sanitizer and
# MinGW builds take the Linux build's (about three CPU-minutes of glslang and vkd3d-compiler each
# on a 2-core machine). The folder must come from the same sources; CI brings it up to date first.
set(LUMINA_PREBUILT_KERNELS_DIR "" CACHE PATH "Load the kernels of another build of the same sources (empty: compile them)")
if(LUMINA_PREBUILT_KERNELS_DIR)
  if(NOT EXISTS "${LUMINA_PREBUILT_KERNELS_DIR}/rhi_tests/chain_seed.spv")
    message(FATAL_ERROR "LUMINA_PREBUILT_KERNELS_DIR=${LUMINA_PREBUILT_KERNELS_DIR} holds no compiled"
      " kernels (no rhi_tests/chain_seed.spv): build lumina_kernels there first, or leave it empty")
  endif()
  set(LUMINA_SHADER_OUTPUT_DIR ${LUMINA_PREBUILT_KERNELS_DIR} CACHE INTERNAL "compiled kernels")
else()
  set(LUMINA_SHADER_OUTPUT_DIR ${CMAKE_BINARY_DIR}/shaders CACHE INTERNAL "compiled kernels")
endif()
set(_LUMINA_SHADERS_DIR ${CMAKE_CURRENT_LIST_DIR})

find_program(LUMINA_DXC NAMES dxc dxc.exe
  HINTS "$ENV{VULKAN_SDK}/bin" "$ENV{VULKAN_SDK}/Bin" "$ENV{DXC_DIR}")
find_program(LUMINA_GLSLANG NAMES glslangValidator glslang)
find_program(LUMINA_SPIRV_VAL NAMES spirv-val HINTS "$ENV{VULKAN_SDK}/bin")
# vkd3d-compiler for DXBC: the folder of .ci/install-dxbc-tools.sh first. Debian 12's own
# vkd3d-compiler (1.2) cannot read HLSL, so whichever is found must list hlsl as a source.
# -DLUMINA_VKD3D_COMPILER=OFF builds no DXBC.
find_program(LUMINA_VKD3D_COMPILER NAMES vkd3d-compiler
  HINTS "$ENV{LUMINA_D3D12_TOOLS_DIR}/bin" /opt/lumina/d3d12-tools/bin)
set(LUMINA_DXBC_COMPILER "")
if(LUMINA_VKD3D_COMPILER)
  execute_process(COMMAND ${LUMINA_VKD3D_COMPILER} --print-source-types
    OUTPUT_VARIABLE _lumina_vkd3d_sources ERROR_QUIET RESULT_VARIABLE _lumina_vkd3d_result)
  if(NOT _lumina_vkd3d_result EQUAL 0 OR NOT _lumina_vkd3d_sources MATCHES "hlsl")
    message(WARNING "${LUMINA_VKD3D_COMPILER} cannot compile HLSL (Debian 12's vkd3d-compiler is 1.2):"
      " no DXBC. Run .ci/install-dxbc-tools.sh, or set LUMINA_VKD3D_COMPILER to vkd3d-compiler 2.1")
  elseif(NOT LUMINA_GLSLANG)
    message(WARNING "DXBC needs glslangValidator too (it preprocesses for vkd3d-compiler): no DXBC")
  else()
    set(LUMINA_DXBC_COMPILER ${LUMINA_VKD3D_COMPILER})
  endif()
endif()
# Each DXBC kernel's disassembly is checked for vkd3d-shader's merged-cast miscompile
# (cmake/check_dxbc_casts.py, docs/d3d12.md) where Python 3 is found; CI has it.
set(LUMINA_DXBC_CHECK_PYTHON "")
if(LUMINA_DXBC_COMPILER)
  find_package(Python3 COMPONENTS Interpreter QUIET)
  if(Python3_Interpreter_FOUND)
    set(LUMINA_DXBC_CHECK_PYTHON ${Python3_EXECUTABLE})
  else()
    message(WARNING "python3 not found: DXBC kernels are not checked for vkd3d-shader's merged-cast miscompile")
  endif()
endif()

if(NOT LUMINA_DXC AND NOT LUMINA_GLSLANG)
  message(FATAL_ERROR "No HLSL compiler: install glslang-tools (Debian) or DXC")
endif()
if(NOT LUMINA_SPIRV_VAL)
  message(FATAL_ERROR "spirv-val not found: install spirv-tools")
endif()
if(LUMINA_DXBC_COMPILER)
  set(_lumina_dxbc_status "${LUMINA_DXBC_COMPILER}")
else()
  set(_lumina_dxbc_status "none (.ci/install-dxbc-tools.sh)")
endif()
if(NOT LUMINA_PREBUILT_KERNELS_DIR)
  message(STATUS "Lumina kernels: SPIR-V with ${LUMINA_DXC}${LUMINA_GLSLANG}, DXIL ${LUMINA_DXC},"
    " DXBC ${_lumina_dxbc_status}")
endif()

# Register shifts shared by both SPIR-V compilers (docs/binding.md): b -> n, t -> 100+n,
# u -> 200+n, s -> 300+n, in every register space (space N becomes descriptor set N).
set(LUMINA_SHIFT_T 100)
set(LUMINA_SHIFT_U 200)
set(LUMINA_SHIFT_S 300)
set(LUMINA_MAX_SPACES 4)

function(_lumina_stage_profile stage out_glslang out_dxc out_dxbc)
  if(stage STREQUAL "cs")
    set(${out_glslang} comp PARENT_SCOPE)
  elseif(stage STREQUAL "vs")
    set(${out_glslang} vert PARENT_SCOPE)
  elseif(stage STREQUAL "ps")
    set(${out_glslang} frag PARENT_SCOPE)
  else()
    message(FATAL_ERROR "unknown kernel stage '${stage}' (cs, vs or ps)")
  endif()
  set(${out_dxc} ${stage}_6_0 PARENT_SCOPE)
  set(${out_dxbc} ${stage}_5_1 PARENT_SCOPE)
endfunction()

# DXBC: glslangValidator preprocesses (vkd3d-compiler has no -I or -D and resolves includes
# against its working folder only), then vkd3d-compiler compiles the result, kept beside the
# output as <name>.dxbc.hlsl so that error lines can be read. Depending on the .spv reruns it
# whenever an included file changes (the .spv has the depfile).
function(_lumina_add_dxbc_kernel root src name entry glslang_stage profile spv no_dxbc outputs_var)
  set(unavailable "${LUMINA_SHADER_OUTPUT_DIR}/${name}.dxbc.unavailable")
  if(no_dxbc)
    file(WRITE "${unavailable}" "${no_dxbc}\n")
    return()
  endif()
  file(REMOVE "${unavailable}")
  set(dxbc "${LUMINA_SHADER_OUTPUT_DIR}/${name}.dxbc")
  add_custom_command(
    OUTPUT ${dxbc}
    COMMAND ${CMAKE_COMMAND} -DGLSLANG=${LUMINA_GLSLANG} -DVKD3D=${LUMINA_DXBC_COMPILER}
      -DSTAGE=${glslang_stage} -DPROFILE=${profile} -DENTRY=${entry} -DROOT=${root}
      -DSOURCE=${src} -DOUTPUT=${dxbc} -DPYTHON=${LUMINA_DXBC_CHECK_PYTHON}
      -DCHECK=${_LUMINA_SHADERS_DIR}/check_dxbc_casts.py -P ${_LUMINA_SHADERS_DIR}/LuminaCompileDxbc.cmake
    DEPENDS ${src} ${spv} ${_LUMINA_SHADERS_DIR}/LuminaCompileDxbc.cmake ${_LUMINA_SHADERS_DIR}/check_dxbc_casts.py
    COMMENT "HLSL ${name} -> DXBC"
    VERBATIM)
  list(APPEND ${outputs_var} ${dxbc})
  set(${outputs_var} ${${outputs_var}} PARENT_SCOPE)
endfunction()

# lumina_add_kernels(TARGET <custom target> ROOT <shaders dir>)
function(lumina_add_kernels)
  cmake_parse_arguments(ARG "" "TARGET;ROOT" "" ${ARGN})
  if(LUMINA_PREBUILT_KERNELS_DIR)
    message(STATUS "Lumina kernels: compiled by another build, loaded from ${LUMINA_PREBUILT_KERNELS_DIR}")
    add_custom_target(${ARG_TARGET})
    return()
  endif()
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${ARG_ROOT}/*.hlsl")
  set(outputs "")
  foreach(src IN LISTS sources)
    file(RELATIVE_PATH rel "${ARG_ROOT}" "${src}")
    string(REGEX REPLACE "\\.hlsl$" "" stem "${rel}")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${src}")
    file(STRINGS "${src}" decls REGEX "^// lumina-kernel: ")
    file(STRINGS "${src}" no_dxbc REGEX "^// lumina-no-dxbc: ")
    string(REGEX REPLACE "^// lumina-no-dxbc: " "" no_dxbc "${no_dxbc}")
    foreach(decl IN LISTS decls)
      string(REGEX MATCH "^// lumina-kernel: ([a-z][a-z]) ([A-Za-z_][A-Za-z0-9_]*)" _ "${decl}")
      set(stage "${CMAKE_MATCH_1}")
      set(entry "${CMAKE_MATCH_2}")
      if(NOT stage OR NOT entry)
        message(FATAL_ERROR "${src}: malformed kernel declaration '${decl}'")
      endif()
      set(name "${stem}")
      if(NOT entry STREQUAL "main")
        set(name "${stem}.${entry}")
      endif()
      _lumina_stage_profile(${stage} glslang_stage dxc_profile dxbc_profile)
      set(spv "${LUMINA_SHADER_OUTPUT_DIR}/${name}.spv")
      set(dep "${LUMINA_SHADER_OUTPUT_DIR}/${name}.spv.d")
      get_filename_component(outdir "${spv}" DIRECTORY)
      if(LUMINA_DXC)
        set(compile_spv ${LUMINA_DXC} -spirv -fspv-target-env=vulkan1.1 -T ${dxc_profile} -E ${entry}
          -HV 2021 -O3 -I ${ARG_ROOT} -DLUMINA_SPIRV=1
          -fvk-b-shift 0 all -fvk-t-shift ${LUMINA_SHIFT_T} all
          -fvk-u-shift ${LUMINA_SHIFT_U} all -fvk-s-shift ${LUMINA_SHIFT_S} all
          -Fo ${spv} ${src})
        set(depfile_args "")  # DXC writes no Make-style depfile
      else()
        set(compile_spv ${LUMINA_GLSLANG} -D -V --target-env vulkan1.1 --hlsl-iomap -S ${glslang_stage}
          -e ${entry} -I${ARG_ROOT} -DLUMINA_SPIRV=1
          --shift-cbuffer-binding 0 --shift-texture-binding ${LUMINA_SHIFT_T}
          --shift-UAV-binding ${LUMINA_SHIFT_U} --shift-sampler-binding ${LUMINA_SHIFT_S}
          --depfile ${dep} -o ${spv} ${src})
        set(depfile_args DEPFILE ${dep})
      endif()
      add_custom_command(
        OUTPUT ${spv}
        COMMAND ${CMAKE_COMMAND} -E make_directory ${outdir}
        COMMAND ${compile_spv}
        COMMAND ${LUMINA_SPIRV_VAL} --target-env vulkan1.1 ${spv}
        DEPENDS ${src}
        ${depfile_args}
        COMMENT "HLSL ${name} -> SPIR-V"
        VERBATIM)
      list(APPEND outputs ${spv})
      if(LUMINA_DXC)
        set(dxil "${LUMINA_SHADER_OUTPUT_DIR}/${name}.dxil")
        add_custom_command(
          OUTPUT ${dxil}
          COMMAND ${CMAKE_COMMAND} -E make_directory ${outdir}
          COMMAND ${LUMINA_DXC} -T ${dxc_profile} -E ${entry} -HV 2021 -O3 -I ${ARG_ROOT}
            -Fo ${dxil} ${src}
          DEPENDS ${src} ${spv}
          COMMENT "HLSL ${name} -> DXIL"
          VERBATIM)
        list(APPEND outputs ${dxil})
      endif()
      if(LUMINA_DXBC_COMPILER)
        _lumina_add_dxbc_kernel("${ARG_ROOT}" "${src}" "${name}" "${entry}" ${glslang_stage}
          ${dxbc_profile} "${spv}" "${no_dxbc}" outputs)
      endif()
    endforeach()
  endforeach()
  add_custom_target(${ARG_TARGET} ALL DEPENDS ${outputs})
endfunction()
