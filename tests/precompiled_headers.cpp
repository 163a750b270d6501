// The one source of lumina_test_pch (tests/CMakeLists.txt), a target that exists to build the
// precompiled header of precompiled_headers.h, which every test executable reuses.
