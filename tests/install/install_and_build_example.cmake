# Install test (ctest: InstallAndBuildExample), run as a script with cmake -P:
#   1. cmake --install BUILD_DIR --prefix WORK_DIR/prefix
#   2. check the headers, library, program and package files are there; run `facet --help`
#   3. configure examples/ with CMAKE_PREFIX_PATH=WORK_DIR/prefix (find_package(facet)), build
#   4. run hello_triangle, which must write a non-empty PNG into WORK_DIR
# Any failing step stops the script with FATAL_ERROR, which fails the test.
#
# Inputs (-D): SOURCE_DIR (project root), BUILD_DIR (a built tree), WORK_DIR (scratch, wiped),
#              optional CONFIG (build type), GENERATOR, CXX_COMPILER.
cmake_minimum_required(VERSION 3.25)

foreach(var SOURCE_DIR BUILD_DIR WORK_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "install test: -D${var}=... is required")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()

set(prefix ${WORK_DIR}/prefix)
set(example_build ${WORK_DIR}/examples-build)
set(image ${WORK_DIR}/hello_triangle.png)

# Runs a command, echoing it; stops the test with the step's name if it fails.
function(run_step name)
  message(STATUS "install test: ${name}")
  execute_process(COMMAND ${ARGN} COMMAND_ECHO STDOUT RESULT_VARIABLE result)
  if(NOT result STREQUAL "0")
    message(FATAL_ERROR "install test: step '${name}' failed (exit status: ${result})")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# 1. Install.
run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})

# 2. The files a user relies on.
foreach(file include/facet/facet.hpp include/facet/renderer.hpp bin/facet)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "install test: ${prefix}/${file} was not installed")
  endif()
endforeach()
file(GLOB_RECURSE library ${prefix}/libfacet.a)
file(GLOB_RECURSE package_config ${prefix}/facetConfig.cmake)
file(GLOB_RECURSE package_version ${prefix}/facetConfigVersion.cmake)
if(NOT library OR NOT package_config OR NOT package_version)
  message(FATAL_ERROR "install test: missing under ${prefix}: "
                      "libfacet.a='${library}' facetConfig.cmake='${package_config}' "
                      "facetConfigVersion.cmake='${package_version}'")
endif()
run_step("installed program runs" ${prefix}/bin/facet --help)

# 3. Build the example against the installed package only (no package registry, no build tree).
set(configure_args
  -S ${SOURCE_DIR}/examples -B ${example_build}
  -DCMAKE_PREFIX_PATH=${prefix}
  -DCMAKE_BUILD_TYPE=${CONFIG}
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
if(GENERATOR)
  list(APPEND configure_args -G ${GENERATOR})
endif()
if(CXX_COMPILER)
  list(APPEND configure_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
run_step("configure examples/ with find_package(facet)" ${CMAKE_COMMAND} ${configure_args})

# The package must have come from the scratch prefix, not from a facet installed elsewhere.
file(STRINGS ${example_build}/CMakeCache.txt facet_dir_line REGEX "^facet_DIR:")
string(REGEX REPLACE "^facet_DIR:[A-Z]+=" "" facet_dir "${facet_dir_line}")
file(REAL_PATH "${facet_dir}" facet_dir)
file(REAL_PATH "${prefix}" real_prefix)
string(FIND "${facet_dir}/" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "install test: find_package(facet) used '${facet_dir}', not ${prefix}")
endif()

run_step("build examples/" ${CMAKE_COMMAND} --build ${example_build} --config ${CONFIG})

# 4. Run it and check the image.
find_program(hello hello_triangle PATHS ${example_build} ${example_build}/${CONFIG}
             NO_DEFAULT_PATH REQUIRED)
run_step("run hello_triangle" ${hello} ${image})
if(NOT EXISTS ${image})
  message(FATAL_ERROR "install test: hello_triangle did not write ${image}")
endif()
file(SIZE ${image} image_size)
if(image_size EQUAL 0)
  message(FATAL_ERROR "install test: ${image} is empty")
endif()
file(READ ${image} signature LIMIT 8 HEX)
if(NOT signature STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "install test: ${image} is not a PNG (starts with ${signature})")
endif()
message(STATUS "install test: ok, ${image} (${image_size} bytes)")
