# Unity builds (issue 27.2): each library's .cpp files compiled in batches of
# TUMBLE_UNITY_BATCH, one translation unit per batch (CMake's UNITY_BUILD). Most of a file's compile
# time is the templates its headers instantiate (Eigen, nlohmann-json, CLI11, glm), not parsing
# them; a batch instantiates each once. Measured with scripts/bench-build.sh (docs/engineering.md:
# clean Release `tumble`, 2 cores): this is what took the build below 200 s; precompiled headers,
# tried first, bought nothing (432 s against 424 and 470 s without) and are not used. Batches of
# 16 against 8, one sitting: 129.5 s against 180.1 s (median of 2). The price is paid in
# incremental builds: an edit recompiles its batch of up to 16 files (the debug preset: one).
# A batch is one translation unit, so two files of a library may not define the same name in an
# anonymous namespace (the build fails if they do: share it in a header instead). It also means a
# file may compile only because a file before it in the batch included what it forgot:
# `-DTUMBLE_UNITY_BUILD=OFF` (the debug preset) compiles each file alone and catches that.
# What a file compiles to does not change: the same code, the same flags (-ffp-contract=off); the
# pinned hashes and goldens of the suite hold in both.
option(TUMBLE_UNITY_BUILD "Compile each library's files in batches (faster clean builds)" ON)
set(TUMBLE_UNITY_BATCH 16 CACHE STRING "Files per unity batch (TUMBLE_UNITY_BUILD)")

function(tumble_unity target)
  if(TUMBLE_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON
                          UNITY_BUILD_BATCH_SIZE ${TUMBLE_UNITY_BATCH})
  endif()
endfunction()

# tumble_cold(<level> <target>...): libraries whose code runs around the hot loops, compiled at
# <level> in Release instead of CMake's -O3. physics/ (every step) and render/ (every frame's
# pixels) keep -O3. What -O3 adds over -O2 (more inlining, loop vectorisation and unrolling) pays in
# loops that run millions of times and costs compile time in code that is mostly templates
# instantiated once (nlohmann-json, CLI11, Eigen); -O1 drops most inlining across the templates
# too, for code that runs once per run (reading the scene, parsing options, writing reports).
# Measured with scripts/bench-build.sh, docs/engineering.md. The same bits at every level: none
# changes floating-point results (-ffp-contract=off, no -ffast-math), and the suite's pinned hashes
# and goldens hold.
function(tumble_cold level)
  foreach(target ${ARGN})
    target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:${level}>)
  endforeach()
endfunction()

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
  tumble_unity(${target})
  tumble_expose_headers(${target} ${folder})
  # The Python module's copy (cmake/TumblePython.cmake, app/python/CMakeLists.txt links it).
  if(TUMBLE_PYTHON AND target IN_LIST TUMBLE_PYTHON_LIBRARIES)
    add_library(${target}_pic STATIC EXCLUDE_FROM_ALL ${sources} ${ARGN})
    tumble_unity(${target}_pic)
    set_target_properties(${target}_pic PROPERTIES POSITION_INDEPENDENT_CODE ON
                          CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
    # Its flags and links are the library's, known once the folder's CMakeLists.txt has run.
    # (EVAL: a deferred call expands its arguments when it runs; the name is needed now.)
    cmake_language(EVAL CODE "cmake_language(DEFER CALL tumble_pic_copy_usage [[${target}]])")
  endif()
endfunction()

# The <target>_pic copy takes <target>'s definitions, options, include folders and links, the
# libraries among TUMBLE_PYTHON_LIBRARIES replaced by their copies.
function(tumble_pic_copy_usage target)
  foreach(property COMPILE_DEFINITIONS COMPILE_OPTIONS INCLUDE_DIRECTORIES
                   INTERFACE_INCLUDE_DIRECTORIES)
    get_target_property(value ${target} ${property})
    if(value)
      set_property(TARGET ${target}_pic PROPERTY ${property} ${value})
    endif()
  endforeach()
  get_target_property(links ${target} LINK_LIBRARIES)
  set(pic_links)
  foreach(link ${links})
    if(link IN_LIST TUMBLE_PYTHON_LIBRARIES)
      list(APPEND pic_links ${link}_pic)
    elseif(link)
      list(APPEND pic_links ${link})
    endif()
  endforeach()
  target_link_libraries(${target}_pic PUBLIC ${pic_links})
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
