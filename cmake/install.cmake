# `cmake --install`: the command, the library `hocav::hocav` (hocav_lib, which needs no gmsh), its
# public headers with every header they include, a CMake package (find_package(hocav)) and a
# pkg-config file. docs/library.md documents the public headers.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(HOCAV_INCLUDE_DIR ${CMAKE_INSTALL_INCLUDEDIR}/hocav)
set(HOCAV_PUBLIC_HEADERS
    mesh/mesh.hpp mesh/consistency.hpp mesh/measure.hpp io/mesh_file.hpp metric/analytic_metric.hpp
    metric/metric_field.hpp adapt/adaptation_metric.hpp adapt/adaptation_loop.hpp adapt/adaptation_driver.hpp
    adapt/curving_run.hpp surface/p3_surrogate.hpp)
install(CODE "set(HOCAV_SOURCE_DIR [[${PROJECT_SOURCE_DIR}]])
              set(HOCAV_PUBLIC_HEADERS [[${HOCAV_PUBLIC_HEADERS}]])
              set(HOCAV_HEADER_DESTINATION [[${HOCAV_INCLUDE_DIR}]])")
install(SCRIPT cmake/install_headers.cmake)

# The headers include each other as "mesh/mesh.hpp", so include/hocav is on the include path; with
# include/ too, users may write <hocav/mesh/mesh.hpp>.
target_include_directories(hocav_lib PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
                                            $<INSTALL_INTERFACE:${HOCAV_INCLUDE_DIR}>)
install(TARGETS hocav_lib EXPORT hocavTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS hocav RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(HOCAV_WITH_GMSH)
  install(TARGETS hocav_gmsh_module LIBRARY DESTINATION ${HOCAV_GMSH_MODULE_DIR})
endif()

set(HOCAV_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/hocav)
install(EXPORT hocavTargets NAMESPACE hocav:: DESTINATION ${HOCAV_CMAKE_DIR})
configure_package_config_file(cmake/hocavConfig.cmake.in ${PROJECT_BINARY_DIR}/hocavConfig.cmake
                              INSTALL_DESTINATION ${HOCAV_CMAKE_DIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/hocavConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/hocavConfig.cmake ${PROJECT_BINARY_DIR}/hocavConfigVersion.cmake
        DESTINATION ${HOCAV_CMAKE_DIR})

# Relocatable: the prefix is found from the .pc file's place (cmake --install --prefix DIR).
file(RELATIVE_PATH HOCAV_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)  # "../../"
string(REGEX REPLACE "/$" "" HOCAV_PC_TO_PREFIX ${HOCAV_PC_TO_PREFIX})
configure_file(cmake/hocav.pc.in ${PROJECT_BINARY_DIR}/hocav.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/hocav.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
