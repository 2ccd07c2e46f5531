# What the tests of every module share (each module's Testing/ uses these; included by the top
# CMakeLists.txt before the modules are built):
#   tiledraycast_add_x_test(<driver> <test> [args...])
#       a test of a C++ test driver that needs VTK's X render window, run under xvfb-run
#   tiledraycast_add_python_test(<script> [NO_DISPLAY] [X] [DATA <dir>] [ARGS <arg>...])
#       a Python test run by Debian's /usr/bin/python3 with the build tree's 'tiledraycast'
# and the helpers every C++ test may include: ${TILEDRAYCAST_TEST_HELPERS_DIRECTORY}
# (Testing/Cxx: the shared scenes, TRC_CHECK and the brute-force integrator). Every Python test
# may import tiledraycast_testing (Testing/Python, on its PYTHONPATH).
set(TILEDRAYCAST_TEST_HELPERS_DIRECTORY "${CMAKE_CURRENT_LIST_DIR}/../../Testing/Cxx")
get_filename_component(TILEDRAYCAST_TEST_HELPERS_DIRECTORY
  "${TILEDRAYCAST_TEST_HELPERS_DIRECTORY}" ABSOLUTE)

# Tests that need VTK's X render window run in their driver through xvfb-run, labelled "X";
# Module/test.sh runs the rest of the suite with no DISPLAY at all.
find_program(TILEDRAYCAST_XVFB_RUN xvfb-run)
mark_as_advanced(TILEDRAYCAST_XVFB_RUN)

# Called from a module's Testing/Cxx (it names its tests as vtk_add_test_cxx does).
function (tiledraycast_add_x_test driver test)
  if (NOT TILEDRAYCAST_XVFB_RUN)
    message(STATUS "xvfb-run not found: ${test} is not added")
    return ()
  endif ()
  set(_trc_x_test_name "${_vtk_build_test}Cxx-${test}")
  add_test(
    NAME    "${_trc_x_test_name}"
    COMMAND "${TILEDRAYCAST_XVFB_RUN}" -a -s "-screen 0 1280x1024x24"
            "$<TARGET_FILE:${driver}>" "${test}"
            -D "${_vtk_build_TEST_OUTPUT_DATA_DIRECTORY}"
            -T "${TILEDRAYCAST_TEST_OUTPUT_DIRECTORY}"
            ${ARGN})
  set_tests_properties("${_trc_x_test_name}"
    PROPERTIES
      LABELS "X"
      # Two xvfb-run -a started at once may pick the same display number.
      RESOURCE_LOCK xvfb
      FAIL_REGULAR_EXPRESSION "(\n|^)ERROR: ;ERR\\|;Failed Image Test;DartMeasurement name=.ImageNotFound"
      SKIP_RETURN_CODE 125)
endfunction ()

# make sanitize (Module/sanitize.sh) preloads the AddressSanitizer runtime into the uninstrumented
# /usr/bin/python3 of the Python tests: the library's path, empty for a normal build.
set(TILEDRAYCAST_PYTHON_TEST_PRELOAD "" CACHE FILEPATH
  "A library to LD_PRELOAD into the Python tests (libasan.so for a sanitizer build)")
mark_as_advanced(TILEDRAYCAST_PYTHON_TEST_PRELOAD)

# Python tests run with Debian's /usr/bin/python3 (the interpreter VTK's vtkmodules belong to),
# importing the 'tiledraycast' package from the build tree, and are named
# TiledRayCastPython-<script>. They get -D <data> -T <temporary directory>; the data directory
# is Testing/Data (the meshes) unless DATA names another; ARGS follow them. NO_DISPLAY runs the
# test with DISPLAY unset; X runs it under xvfb-run (label X), with neither -D nor -T. Their
# PYTHONPATH, in either case, holds the package and Testing/Python: the tests' shared helpers,
# tiledraycast_testing.py.
function (tiledraycast_add_python_test script)
  cmake_parse_arguments(PARSE_ARGV 1 _trc "NO_DISPLAY;X" "DATA" "ARGS")
  if (NOT TILEDRAYCAST_WRAP_PYTHON)
    return ()
  endif ()
  if (NOT _trc_DATA)
    set(_trc_DATA "${PROJECT_SOURCE_DIR}/Testing/Data")
  endif ()
  set(_trc_environment
    "PYTHONPATH=${CMAKE_BINARY_DIR}/${TILEDRAYCAST_PYTHON_DESTINATION}:${PROJECT_SOURCE_DIR}/Testing/Python")
  if (TILEDRAYCAST_PYTHON_TEST_PRELOAD)
    list(APPEND _trc_environment "LD_PRELOAD=${TILEDRAYCAST_PYTHON_TEST_PRELOAD}")
  endif ()
  set(_trc_name "TiledRayCastPython-${script}")
  set(_trc_script "${CMAKE_CURRENT_SOURCE_DIR}/${script}.py")
  if (_trc_X)
    if (NOT TILEDRAYCAST_XVFB_RUN)
      message(STATUS "xvfb-run not found: ${_trc_name} is not added")
      return ()
    endif ()
    add_test(
      NAME    "${_trc_name}"
      COMMAND "${TILEDRAYCAST_XVFB_RUN}" -a -s "-screen 0 1280x1024x24"
              /usr/bin/python3 "${_trc_script}")
    set_tests_properties("${_trc_name}"
      PROPERTIES
        LABELS "X"
        RESOURCE_LOCK xvfb)
  else ()
    add_test(
      NAME    "${_trc_name}"
      COMMAND /usr/bin/python3 "${_trc_script}"
              -D "${_trc_DATA}"
              -T "${TILEDRAYCAST_TEST_OUTPUT_DIRECTORY}"
              ${_trc_ARGS})
  endif ()
  set_tests_properties("${_trc_name}"
    PROPERTIES
      ENVIRONMENT "${_trc_environment}"
      SKIP_RETURN_CODE 125)
  if (_trc_NO_DISPLAY)
    set_tests_properties("${_trc_name}"
      PROPERTIES
        ENVIRONMENT_MODIFICATION "DISPLAY=unset:")
  endif ()
endfunction ()
