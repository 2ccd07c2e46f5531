# A downstream user's round trip, run by ctest: install this build into a fresh prefix, configure
# and build Examples/Cxx against it with find_package(TiledRayCast), render a mesh with the
# example program, and render it again from Python with the installed 'tiledraycast' package.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DPYTHON_DESTINATION=... -P this file
foreach (_var IN ITEMS BUILD_DIR SOURCE_DIR WORK_DIR PYTHON_DESTINATION MESH)
  if (NOT DEFINED ${_var})
    message(FATAL_ERROR "${_var} is not set")
  endif ()
endforeach ()

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc)
  if (NOT _rc EQUAL 0)
    string(REPLACE ";" " " _cmd "${ARGN}")
    message(FATAL_ERROR "failed (${_rc}): ${_cmd}")
  endif ()
endfunction ()

file(REMOVE_RECURSE "${WORK_DIR}")
set(_prefix "${WORK_DIR}/prefix")
run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${_prefix}")
run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}/Examples/Cxx" -B "${WORK_DIR}/example" -G Ninja
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${_prefix}")
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/example")
run("${WORK_DIR}/example/RenderMesh" "${MESH}" "${WORK_DIR}/example.png" 128)
if (NOT EXISTS "${WORK_DIR}/example.png")
  message(FATAL_ERROR "RenderMesh wrote no image")
endif ()

# Python from the install prefix, not the build tree.
run("${CMAKE_COMMAND}" -E env "PYTHONPATH=${_prefix}/${PYTHON_DESTINATION}"
  /usr/bin/python3 -c
  # (newlines, not semicolons: CMake would split the argument at them)
  "import os, tiledraycast as t\np = os.path.realpath(t.__file__)\nassert p.startswith(os.path.realpath('${_prefix}')), p\nprint('tiledraycast from', p)")
run("${CMAKE_COMMAND}" -E env "PYTHONPATH=${_prefix}/${PYTHON_DESTINATION}"
  /usr/bin/python3 "${SOURCE_DIR}/Examples/Python/render_mesh.py" "${MESH}"
  --output "${WORK_DIR}/python.png" --size 128)
message(STATUS "downstream build and both renderings succeeded")
