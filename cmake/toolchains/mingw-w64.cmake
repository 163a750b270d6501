# Cross-compiling Lumina for 64-bit Windows with MinGW-w64 (Debian: g++-mingw-w64-x86-64):
#
#   cmake -S . -B build-mingw -G Ninja -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/mingw-w64.cmake \
#         -DLUMINA_D3D12=ON -DLUMINA_VULKAN=OFF
#
# The POSIX-thread variant of the compiler is used: the win32-thread one has no std::thread or
# std::mutex in GCC 12. Executables link libstdc++, libgcc and winpthread statically so that
# they run under Wine (or on Windows) without DLLs beside them.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(LUMINA_MINGW_TRIPLE x86_64-w64-mingw32)

find_program(CMAKE_C_COMPILER NAMES ${LUMINA_MINGW_TRIPLE}-gcc-posix ${LUMINA_MINGW_TRIPLE}-gcc REQUIRED)
find_program(CMAKE_CXX_COMPILER NAMES ${LUMINA_MINGW_TRIPLE}-g++-posix ${LUMINA_MINGW_TRIPLE}-g++ REQUIRED)
find_program(CMAKE_RC_COMPILER NAMES ${LUMINA_MINGW_TRIPLE}-windres)

set(CMAKE_FIND_ROOT_PATH /usr/${LUMINA_MINGW_TRIPLE})
# Build tools (glslangValidator, spirv-val) come from the host; libraries and headers from
# the MinGW sysroot only.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")

# ctest runs the cross-compiled tests through Wine when it is installed.
find_program(LUMINA_WINE NAMES wine64 wine PATHS /usr/lib/wine NO_CMAKE_FIND_ROOT_PATH)
if(LUMINA_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${LUMINA_WINE})
endif()
