# Python wrapping: the package 'tiledraycast' sits next to VTK's own 'vtkmodules'
# (lib/python3/dist-packages, the layout Debian uses), in the build tree and in the install tree.
vtk_module_wrap_python(
  MODULES             ${trc_modules}
  TARGET              TiledRayCast::Python
  INSTALL_EXPORT      TiledRayCastPython
  PYTHON_PACKAGE      "tiledraycast"
  MODULE_DESTINATION  "${TILEDRAYCAST_PYTHON_DESTINATION}"
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/TiledRayCast"
  INSTALL_HEADERS     OFF
  BUILD_STATIC        OFF)

# The package's __init__.py imports vtkmodules first (so that VTK's own wrapped base classes are
# registered) and then every wrapped module of ours, except the TetGen one: it links AGPL-3+
# TetGen, so `import tiledraycast` must not load it. Import it by name:
#   from tiledraycast.vtkFiltersTetGen import vtkTetGenMesher
set(_trc_python_imports "")
foreach (_trc_module IN LISTS trc_modules)
  if (_trc_module STREQUAL "TiledRayCast::FiltersTetGen")
    continue ()
  endif ()
  get_property(_trc_library_name GLOBAL PROPERTY "_vtk_module_${_trc_module}_library_name")
  string(APPEND _trc_python_imports "from .${_trc_library_name} import *\n")
endforeach ()
set(_trc_init "${CMAKE_BINARY_DIR}/${TILEDRAYCAST_PYTHON_DESTINATION}/tiledraycast/__init__.py")
configure_file("${CMAKE_SOURCE_DIR}/Module/python/__init__.py.in" "${_trc_init}" @ONLY)
install(
  FILES       "${_trc_init}"
  DESTINATION "${TILEDRAYCAST_PYTHON_DESTINATION}/tiledraycast"
  COMPONENT   python)
