# Checks a binary's link line as the dynamic loader sees it: every library it needs, directly or
# through its dependencies (DT_NEEDED, at any depth), found in SEARCH_DIRECTORY or the system's.
# Fails when one of them has a file name that matches FORBIDDEN (a regular expression), or, when
# REQUIRED is given, when none matches REQUIRED (which shows that a FORBIDDEN pattern written like
# it matches real file names). Used to prove the module graph (docs/design.md, "Modules"): no
# OpenGL in the mesh code, an oracle that loads neither the mesh builder nor the GPU mapper, a GPU
# mapper that never loads the oracle, and no AGPL-3+ TetGen outside its own module.
#   cmake -DBINARY=<file> -DFORBIDDEN=<regex> [-DREQUIRED=<regex>] -DSEARCH_DIRECTORY=<dir>
#         -P CheckNotLinked.cmake
if (NOT EXISTS "${BINARY}")
  message(FATAL_ERROR "No such binary: ${BINARY}")
endif ()
file(GET_RUNTIME_DEPENDENCIES
  LIBRARIES                    "${BINARY}"
  RESOLVED_DEPENDENCIES_VAR    resolved
  UNRESOLVED_DEPENDENCIES_VAR  unresolved
  DIRECTORIES                  "${SEARCH_DIRECTORY}")
set(found)
set(required_found)
foreach (dependency IN LISTS resolved unresolved)
  get_filename_component(name "${dependency}" NAME)
  if (name MATCHES "${FORBIDDEN}")
    list(APPEND found "${dependency}")
  endif ()
  if (REQUIRED AND name MATCHES "${REQUIRED}")
    list(APPEND required_found "${name}")
  endif ()
endforeach ()
list(LENGTH resolved count)
if (found)
  message(FATAL_ERROR "${BINARY} needs ${found}")
endif ()
if (REQUIRED AND NOT required_found)
  message(FATAL_ERROR "${BINARY}: none of its ${count} runtime dependencies matches '${REQUIRED}'")
endif ()
message(STATUS "${BINARY}: none of its ${count} runtime dependencies matches '${FORBIDDEN}'")
if (required_found)
  message(STATUS "and it needs ${required_found}")
endif ()
