# Cross builds only (CMakeLists.txt puts cmake/cross/ on CMAKE_MODULE_PATH): glm is header-only,
# taken from the host through the build's host-headers folder, never from /usr/include itself.
if(NOT TARGET glm::glm)
  add_library(glm::glm INTERFACE IMPORTED)
  set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${CMAKE_BINARY_DIR}/host-headers
                                            INTERFACE_SYSTEM_INCLUDE_DIRECTORIES ${CMAKE_BINARY_DIR}/host-headers)
endif()
set(glm_FOUND TRUE)
