// The one source of lumina_library_pch (cmake/LuminaPrecompiledHeaders.cmake), a target that exists
// to build the precompiled header of library_headers.h, which Lumina's libraries and executables reuse.
