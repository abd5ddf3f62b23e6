# The installed library as another project uses it: `cmake --install` of the build into a scratch
# prefix, then tests/install_consumer configured with find_package(hocav), built and run on a mesh
# the installed `hocav` generates, its output checked by the installed `hocav stats`; then the
# same program compiled with the flags of the installed hocav.pc, and run; and the installed Python
# module imported.
# WITH_GMSH (true or false): whether the build has gmsh, whose module the installed command then opens.
#   cmake -DBUILD_DIR=... -DCONSUMER_DIR=... -DWORK_DIR=... -DCXX=... -P run_consumer.cmake
foreach(variable BUILD_DIR CONSUMER_DIR WORK_DIR CXX)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "run_consumer.cmake: -D${variable}=... is missing")
  endif()
endforeach()

# Runs a command; stops the test with its output when it fails.
function(step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${name} failed (${status}):\n${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${name}: ok\n${out}")
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
step("configure the consumer" ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/build -DCMAKE_PREFIX_PATH=${prefix}
     -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release)
step("build the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)

set(hocav ${prefix}/bin/hocav)
step("generate" ${hocav} generate polar-annulus --target-triangles 1000 -o ${WORK_DIR}/annulus.meshb)
step("run the consumer" ${WORK_DIR}/build/hocav_consumer ${WORK_DIR}/annulus.meshb ${WORK_DIR}/adapted.meshb)
step("check its output" ${hocav} stats ${WORK_DIR}/adapted.meshb)
# Given WITH_GMSH true: the installed command finds its gmsh module (lib/hocav) for a gmsh-meshed case.
if(WITH_GMSH)
  step("generate with gmsh" ${hocav} generate annulus --h 0.2 -o ${WORK_DIR}/gmsh-annulus.meshb)
endif()

file(GLOB_RECURSE pc_files ${prefix}/*/hocav.pc)
get_filename_component(pc_dir "${pc_files}" DIRECTORY)
set(ENV{PKG_CONFIG_PATH} ${pc_dir})
execute_process(COMMAND pkg-config --cflags --libs hocav OUTPUT_VARIABLE flags OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "pkg-config does not find hocav.pc in ${prefix}")
endif()
separate_arguments(flags UNIX_COMMAND "${flags}")
step("build with pkg-config" ${CXX} -O1 ${CONSUMER_DIR}/main.cpp ${flags} -o ${WORK_DIR}/pkg_config_consumer)
step("run the pkg-config build" ${WORK_DIR}/pkg_config_consumer ${WORK_DIR}/annulus.meshb ${WORK_DIR}/adapted-again.meshb)

# The installed Python module (given PYTHON_INSTALL_DIR, the package's folder under the prefix, when
# the build has it): Debian's Python imports it from there and reads a mesh with it.
if(DEFINED PYTHON_INSTALL_DIR)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_INSTALL_DIR})
  step("import the installed Python module" /usr/bin/python3 -c "import hocav, sys; print(hocav.read(sys.argv[1]))"
       ${WORK_DIR}/annulus.meshb)
endif()
