# Cross builds only (CMakeLists.txt puts cmake/cross/ on CMAKE_MODULE_PATH): nlohmann-json is
# header-only, taken from the host through the build's host-headers folder.
if(NOT TARGET nlohmann_json::nlohmann_json)
  add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
  set_target_properties(nlohmann_json::nlohmann_json PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES ${CMAKE_BINARY_DIR}/host-headers
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${CMAKE_BINARY_DIR}/host-headers)
endif()
set(nlohmann_json_FOUND TRUE)
