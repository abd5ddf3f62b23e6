# HOCAV_GIT_COMMIT: the short hash of the commit the build was configured from, for
# `hocav --version`; "unknown" outside a git checkout or without git.
find_package(Git QUIET)
set(HOCAV_GIT_COMMIT unknown)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short HEAD
                  WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                  OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE
                  RESULT_VARIABLE status ERROR_QUIET)
  if(status EQUAL 0 AND commit)
    set(HOCAV_GIT_COMMIT ${commit})
  endif()
endif()
