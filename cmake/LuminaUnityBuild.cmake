# What a unity build (LUMINA_UNITY_BUILD, CMAKE_UNITY_BUILD) cannot batch. A batch is one
# translation unit, so two files of a batch share everything at file scope:
#  - a file that defines a macro before its includes (a single-header library's implementation,
#    NOMINMAX, GLFW_EXPOSE_NATIVE_*) would hand the macro to every file after it in its batch;
#  - two files of a target that each define a file-local name (a constant or helper in an anonymous
#    namespace: a scene generator's kHalfWidth, a test's kSize) would define it twice.
# Such files are compiled on their own: lumina_keep_out_of_unity_build(<file>...) in the
# CMakeLists.txt of the folder whose targets list them. Foreign code (GoogleTest, GLFW and Dear
# ImGui in the MinGW build) is built without batches.

# lumina_keep_out_of_unity_build(<file>...): the files, relative to the calling folder, are
# compiled on their own in every target of that folder.
function(lumina_keep_out_of_unity_build)
  set_source_files_properties(${ARGN} DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
                              PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endfunction()
