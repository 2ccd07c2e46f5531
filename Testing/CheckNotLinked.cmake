# Fails when a binary needs, directly or through its dependencies, a library whose file name
# matches FORBIDDEN (a regular expression). Used to prove that the rendering module (and its
# Python module) never load TetGen, which is AGPL-3+.
#   cmake -DBINARY=<file> -DFORBIDDEN=<regex> -P CheckNotLinked.cmake
if (NOT EXISTS "${BINARY}")
  message(FATAL_ERROR "No such binary: ${BINARY}")
endif ()
file(GET_RUNTIME_DEPENDENCIES
  LIBRARIES                    "${BINARY}"
  RESOLVED_DEPENDENCIES_VAR    resolved
  UNRESOLVED_DEPENDENCIES_VAR  unresolved
  DIRECTORIES                  "${SEARCH_DIRECTORY}")
set(found)
foreach (dependency IN LISTS resolved unresolved)
  get_filename_component(name "${dependency}" NAME)
  if (name MATCHES "${FORBIDDEN}")
    list(APPEND found "${dependency}")
  endif ()
endforeach ()
list(LENGTH resolved count)
if (found)
  message(FATAL_ERROR "${BINARY} needs ${found}")
endif ()
message(STATUS "${BINARY}: none of its ${count} runtime dependencies matches '${FORBIDDEN}'")
