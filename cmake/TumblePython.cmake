# TUMBLE_WITH_PYTHON: the Python module `tumble` (python/, docs/python.md), built with Debian's
# pybind11-dev for Debian's /usr/bin/python3.
#   AUTO (default): built when pybind11 and Python's headers are found (scripts/setup.sh's test
#         group installs them; the demo's group does not), except with sanitizers or fuzzing (an
#         ASan module cannot be imported by an uninstrumented interpreter);
#   ON:   required (configuring fails without pybind11);  OFF: not built.
# Sets TUMBLE_PYTHON (ON or OFF) and says at configure which it is and why.
set(TUMBLE_WITH_PYTHON AUTO CACHE STRING
    "Build the Python module tumble: AUTO (when pybind11-dev is installed), ON or OFF")
set_property(CACHE TUMBLE_WITH_PYTHON PROPERTY STRINGS AUTO ON OFF)

set(TUMBLE_PYTHON OFF)
set(why "TUMBLE_WITH_PYTHON=OFF")
if(NOT TUMBLE_WITH_APP)
  set(why "no app (TUMBLE_WITH_APP=OFF)")
elseif(TUMBLE_WITH_PYTHON STREQUAL "AUTO" AND (TUMBLE_SANITIZE OR TUMBLE_FUZZ))
  set(why "sanitizers or fuzzing are on (-DTUMBLE_WITH_PYTHON=ON to build it anyway)")
elseif(NOT TUMBLE_WITH_PYTHON STREQUAL "OFF")
  # Debian's interpreter, not a pyenv or venv python3 earlier on PATH: the module is built for
  # the Python that the .deb installs it for (/usr/lib/python3/dist-packages).
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "The Python the module is built for")
  endif()
  find_package(Python 3.9 COMPONENTS Interpreter Development.Module)
  set(PYBIND11_FINDPYTHON ON)
  if(Python_FOUND)
    find_package(pybind11 2.10 CONFIG QUIET)
  endif()
  if(Python_FOUND AND pybind11_FOUND)
    set(TUMBLE_PYTHON ON)
    set(why "pybind11 ${pybind11_VERSION}, ${Python_EXECUTABLE} ${Python_VERSION}")
  elseif(TUMBLE_WITH_PYTHON STREQUAL "ON")
    message(FATAL_ERROR "TUMBLE_WITH_PYTHON=ON needs Debian's pybind11-dev and python3-dev "
                        "(scripts/setup.sh installs them)")
  else()
    set(why "pybind11-dev or python3-dev not installed (scripts/setup.sh installs them)")
  endif()
endif()
if(TUMBLE_PYTHON)
  message(STATUS "Python module tumble: yes (${why}) -> ${CMAKE_BINARY_DIR}/python")
  # The libraries the module holds: each is compiled a second time, position-independent, for it
  # (cmake/TumbleLibrary.cmake); `tumble` keeps its own objects.
  set(TUMBLE_PYTHON_LIBRARIES tumble_io tumble_physics tumble_render tumble_scene tumble_view
      tumble_run)
else()
  message(STATUS "Python module tumble: no (${why})")
endif()
