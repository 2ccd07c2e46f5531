# Writes and installs TiledRayCastConfig.cmake so that a downstream project can do
#   find_package(TiledRayCast REQUIRED)
#   target_link_libraries(app PRIVATE TiledRayCast::RenderingTiledRayCast)
#   vtk_module_autoinit(TARGETS app MODULES TiledRayCast::RenderingTiledRayCast)
include(CMakePackageConfigHelpers)

set(_trc_cmake_destination "${CMAKE_INSTALL_LIBDIR}/cmake/TiledRayCast")

# Modules found through vtk_module_find_package (EGL for the headless window) are looked up
# again by the config file.
vtk_module_export_find_packages(
  CMAKE_DESTINATION "${_trc_cmake_destination}"
  FILE_NAME         "TiledRayCast-vtk-module-find-packages.cmake"
  MODULES           ${trc_modules})

# Find modules that the exported find-packages file needs (TetGen for the optional
# TiledRayCast::FiltersTetGen), next to the config file, in the build and the install tree; the
# config file puts its own directory on CMAKE_MODULE_PATH while it finds them.
set(_trc_find_modules)
if (TILEDRAYCAST_ENABLE_TETGEN)
  list(APPEND _trc_find_modules "${CMAKE_CURRENT_LIST_DIR}/FindTetGen.cmake")
endif ()
foreach (_trc_find_module IN LISTS _trc_find_modules)
  configure_file("${_trc_find_module}" "${CMAKE_BINARY_DIR}/${_trc_cmake_destination}" COPYONLY)
endforeach ()
if (_trc_find_modules)
  install(
    FILES       ${_trc_find_modules}
    DESTINATION "${_trc_cmake_destination}"
    COMPONENT   development)
endif ()

# The VTK components the config file asks for: those our modules depend on.
set(TILEDRAYCAST_VTK_COMPONENTS
  CommonCore CommonDataModel CommonExecutionModel CommonMath CommonSystem CommonTransforms
  FiltersGeneral RenderingCore RenderingVolume RenderingOpenGL2)
set(TILEDRAYCAST_MODULES ${trc_modules})

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/TiledRayCastConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/${_trc_cmake_destination}/TiledRayCastConfig.cmake"
  INSTALL_DESTINATION "${_trc_cmake_destination}")
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/${_trc_cmake_destination}/TiledRayCastConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)
install(
  FILES
    "${CMAKE_BINARY_DIR}/${_trc_cmake_destination}/TiledRayCastConfig.cmake"
    "${CMAKE_BINARY_DIR}/${_trc_cmake_destination}/TiledRayCastConfigVersion.cmake"
  DESTINATION "${_trc_cmake_destination}"
  COMPONENT   development)
install(
  FILES       "${CMAKE_SOURCE_DIR}/LICENSE" "${CMAKE_SOURCE_DIR}/README.md"
  DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/doc/TiledRayCast"
  COMPONENT   runtime)
