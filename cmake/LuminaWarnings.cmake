# lumina_target_warnings(target): the project's warning level on one target.
function(lumina_target_warnings target)
  if(MSVC)
    target_compile_options(${target} PRIVATE /W4 /permissive-)
    if(LUMINA_WERROR)
      target_compile_options(${target} PRIVATE /WX)
    endif()
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
      # GCC 12 at -O3 reports std::string copies as overlapping memcpy (GCC bug 105329), and,
      # with the precompiled header (cmake/LuminaPrecompiledHeaders.cmake) changing what it
      # inlines, a char_traits copy in eight source files as a bound beyond the largest object
      # and as a pointer overflow (the same family of false reports, GCC bug 106199).
      target_compile_options(${target} PRIVATE -Wno-restrict -Wno-stringop-overflow -Wno-array-bounds)
    endif()
    if(LUMINA_WERROR)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  endif()
endfunction()
