# Run by `cmake --install`: installs the public headers and every header they include, directly or
# through each other (`#include "folder/name.hpp"`), read from the sources at install time, so the
# set never lags behind an edit. Set by install.cmake: HOCAV_SOURCE_DIR, HOCAV_PUBLIC_HEADERS
# (paths under src/) and HOCAV_HEADER_DESTINATION (under the prefix).
# `cmake --install` runs this with old policies (no if(IN_LIST)): newer ones, for this file only.
cmake_policy(VERSION 3.22)
set(installed)
set(pending ${HOCAV_PUBLIC_HEADERS})
while(pending)
  list(POP_FRONT pending header)
  if(header IN_LIST installed)
    continue()
  endif()
  list(APPEND installed ${header})
  file(STRINGS ${HOCAV_SOURCE_DIR}/src/${header} includes REGEX "^#include \"[^\"]+\"")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
    list(APPEND pending ${included})
  endforeach()
endwhile()

foreach(header ${installed})
  get_filename_component(folder ${header} DIRECTORY)
  file(INSTALL ${HOCAV_SOURCE_DIR}/src/${header} DESTINATION ${CMAKE_INSTALL_PREFIX}/${HOCAV_HEADER_DESTINATION}/${folder})
endforeach()
