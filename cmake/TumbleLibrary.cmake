# tumble_library(<target> <folder> [sources...])
# A static library made of the .cpp files directly in <folder> (relative to the source root),
# whose headers, and only those, are visible as "<folder>/name.h" to the library itself and to
# whatever links it. The build enforces the layering this way (docs/architecture.md): each
# library's include root, build/include/<target>/, holds one link, <folder> -> the source folder,
# so a file can include the headers of the libraries it links and nothing else. physics/ including
# "render/x.h", or render/ including "app/...", fails to compile ("No such file or directory");
# tests/house/ keeps a probe that proves it.
function(tumble_library target folder)
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/${folder}/*.cpp)
  add_library(${target} STATIC ${sources} ${ARGN})
  tumble_expose_headers(${target} ${folder})
endfunction()

# tumble_expose_headers(<target> <folder>): the include root described above, for any target.
function(tumble_expose_headers target folder)
  set(root ${CMAKE_BINARY_DIR}/include/${target})
  get_filename_component(parent ${root}/${folder} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  if(NOT EXISTS ${root}/${folder})
    file(CREATE_LINK ${CMAKE_SOURCE_DIR}/${folder} ${root}/${folder} SYMBOLIC)
  endif()
  target_include_directories(${target} PUBLIC ${root})
endfunction()
