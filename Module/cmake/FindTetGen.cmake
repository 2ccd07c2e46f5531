#[==[
Finds TetGen 1.5 built as a library (Debian: libtet1.5-dev, which installs tetgen.h and
libtet.so). TetGen is distributed under the AGPL-3+ (or a commercial licence from WIAS): only the
optional TiledRayCast::FiltersTetGen module links it.

Provides the imported target TetGen::TetGen and sets TetGen_FOUND, TetGen_INCLUDE_DIR,
TetGen_LIBRARY and TetGen_VERSION (read from tetgen.h when it says so).

TetGen's header declares the library interface (tetrahedralize(char*, ...)) and makes its error
handler throw instead of calling exit() only when TETLIBRARY is defined. The library is built
that way, and its terminatetetgen() is an inline function that a client's copy can interpose, so
every translation unit that includes tetgen.h must define TETLIBRARY too: the target carries it.
#]==]

find_path(TetGen_INCLUDE_DIR
  NAMES tetgen.h
  PATH_SUFFIXES tetgen
  DOC "Directory holding tetgen.h")
mark_as_advanced(TetGen_INCLUDE_DIR)

find_library(TetGen_LIBRARY
  NAMES tet tetgen
  DOC "The TetGen library (libtet)")
mark_as_advanced(TetGen_LIBRARY)

if (TetGen_INCLUDE_DIR AND EXISTS "${TetGen_INCLUDE_DIR}/tetgen.h")
  file(STRINGS "${TetGen_INCLUDE_DIR}/tetgen.h" _tetgen_version_line
    REGEX "^// Version [0-9]+\\.[0-9]+" LIMIT_COUNT 1)
  if (_tetgen_version_line MATCHES "Version ([0-9]+\\.[0-9]+(\\.[0-9]+)?)")
    set(TetGen_VERSION "${CMAKE_MATCH_1}")
  endif ()
  unset(_tetgen_version_line)
endif ()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(TetGen
  REQUIRED_VARS TetGen_LIBRARY TetGen_INCLUDE_DIR
  VERSION_VAR   TetGen_VERSION)

if (TetGen_FOUND AND NOT TARGET TetGen::TetGen)
  add_library(TetGen::TetGen UNKNOWN IMPORTED)
  set_target_properties(TetGen::TetGen PROPERTIES
    IMPORTED_LOCATION             "${TetGen_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${TetGen_INCLUDE_DIR}"
    INTERFACE_COMPILE_DEFINITIONS "TETLIBRARY")
endif ()
