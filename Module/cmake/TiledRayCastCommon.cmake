# What both builds of the modules share, the top-level CMakeLists.txt and the ParaView plugin's
# (ParaView/CMakeLists.txt), included by each right after project():
#   C++17, and a Release build where none is chosen;
#   tiledraycast_private_classes(<sources variable> <headers variable> <class>...)
#       appends each class's <class>.cxx to the sources and <class>.h to the private headers (the
#       modules' lists of private classes);
#   tiledraycast_exact_arithmetic(<source>...)
#       compiles these sources without fused multiply-add contraction (GCC, Clang): code whose
#       results are bounded to the last bits relies on plain IEEE double operations.
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
if (NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif ()

function (tiledraycast_private_classes sources_variable headers_variable)
  set(_trc_sources ${${sources_variable}})
  set(_trc_headers ${${headers_variable}})
  foreach (_trc_class IN LISTS ARGN)
    list(APPEND _trc_sources "${_trc_class}.cxx")
    list(APPEND _trc_headers "${_trc_class}.h")
  endforeach ()
  set(${sources_variable} ${_trc_sources} PARENT_SCOPE)
  set(${headers_variable} ${_trc_headers} PARENT_SCOPE)
endfunction ()

function (tiledraycast_exact_arithmetic)
  if (CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS "-ffp-contract=off")
  endif ()
endfunction ()
