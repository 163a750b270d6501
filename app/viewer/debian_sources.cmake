# GLFW and Dear ImGui for the MinGW-w64 cross build, compiled from Debian's source packages
# (Debian ships them built for Linux only). .ci/fetch-debian-sources.sh unpacks them into
# LUMINA_DEBIAN_SOURCES_DIR: glfw3/ (built by its own CMakeLists.txt, Win32 platform code) and
# imgui/ (the same 1.86 as libimgui-dev, with its GLFW backend). Third-party code: compiled
# without our warning flags, included as SYSTEM headers.
set(GLFW_BUILD_EXAMPLES OFF CACHE BOOL "" FORCE)
set(GLFW_BUILD_TESTS OFF CACHE BOOL "" FORCE)
set(GLFW_BUILD_DOCS OFF CACHE BOOL "" FORCE)
set(GLFW_INSTALL OFF CACHE BOOL "" FORCE)
set(BUILD_SHARED_LIBS OFF)
set(CMAKE_UNITY_BUILD OFF) # foreign code, built as its authors build it (restored at the end)
add_subdirectory(${LUMINA_DEBIAN_SOURCES_DIR}/glfw3 ${CMAKE_BINARY_DIR}/debian-sources/glfw3 EXCLUDE_FROM_ALL)
# glfw's include directory as SYSTEM for its users.
get_target_property(glfw_includes glfw INTERFACE_INCLUDE_DIRECTORIES)
set_target_properties(glfw PROPERTIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${glfw_includes}")

set(imgui_dir ${LUMINA_DEBIAN_SOURCES_DIR}/imgui)
add_library(lumina_imgui STATIC
  ${imgui_dir}/imgui.cpp ${imgui_dir}/imgui_demo.cpp ${imgui_dir}/imgui_draw.cpp ${imgui_dir}/imgui_tables.cpp
  ${imgui_dir}/imgui_widgets.cpp ${imgui_dir}/backends/imgui_impl_glfw.cpp)
target_include_directories(lumina_imgui SYSTEM PUBLIC ${imgui_dir})
target_link_libraries(lumina_imgui PUBLIC glfw PRIVATE imm32)
add_library(imgui::imgui ALIAS lumina_imgui)
set(CMAKE_UNITY_BUILD ${LUMINA_UNITY_BUILD})
