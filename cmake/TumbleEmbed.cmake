# tumble_embed(<out.cpp> <namespace> <file>... [ROOTS <dir>...])
# Generates a C++ source that holds each file's bytes, so the binary needs no asset files at run
# time, looked up by name (cmake/embed_files.cmake). A file's name is its path relative to the
# first of ROOTS that contains it ("lessons/intermediate_axis.json" under assets/scenes), else its
# file name. Regenerated when an input changes.
function(tumble_embed out namespace)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "ROOTS")
  set(inputs ${arg_UNPARSED_ARGUMENTS})
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DNAMESPACE=${namespace} "-DINPUTS=${inputs}"
            "-DROOTS=${arg_ROOTS}" -P ${CMAKE_SOURCE_DIR}/cmake/embed_files.cmake
    DEPENDS ${inputs} ${CMAKE_SOURCE_DIR}/cmake/embed_files.cmake
    COMMENT "Embedding ${namespace} assets"
    VERBATIM)
endfunction()
