# tumble_embed(<out.cpp> <namespace> <file>...)
# Generates a C++ source that holds each file's bytes, so the binary needs no asset files at run
# time. Each file becomes `std::string_view <namespace>::<symbol>()`, where <symbol> is the file
# name with every non-alphanumeric character replaced by '_'. Regenerated when an input changes.
function(tumble_embed out namespace)
  set(inputs ${ARGN})
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DNAMESPACE=${namespace} "-DINPUTS=${inputs}"
            -P ${CMAKE_SOURCE_DIR}/cmake/embed_files.cmake
    DEPENDS ${inputs} ${CMAKE_SOURCE_DIR}/cmake/embed_files.cmake
    COMMENT "Embedding ${namespace} assets"
    VERBATIM)
endfunction()
