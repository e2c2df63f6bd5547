# Install test (ctest: InstallAndBuildExample), run as a script with cmake -P:
#   1. cmake --install BUILD_DIR into a scratch prefix
#   2. check the headers, libraries (shared: their SONAME, and that libfacet.so needs no
#      assimp, OpenAL or SDL), pkg-config files, man page, CMake package; run the installed
#      `facet --version`, the program's modules (shared: the viewer's, run with SDL's dummy
#      drivers) and the thumbnailer's Exec line
#   3. configure examples/ against the prefix with find_package(facet COMPONENTS core), with
#      assimp and OpenAL made unfindable, build it and check hello_triangle needs neither
#   4. build hello_triangle again with plain g++ $(pkg-config --cflags --libs facet)
#   5. run both; each must write a PNG
#   6. with the Python module built (PYTHON_MODULE): the installed package imports from the
#      prefix's site-packages folder alone and renders a PNG
# A shared install's prefix is where the Python module's pip test (python/tests) builds
# against, needing this test first.
# Any failing step stops the script with FATAL_ERROR, which fails the test.
#
# Inputs (-D): SOURCE_DIR (project root), BUILD_DIR (a built tree), WORK_DIR (scratch, wiped),
#              VERSION (the project's), SHARED (the build's BUILD_SHARED_LIBS), CONFIG (build
#              type), GENERATOR, CXX_COMPILER, EXAMPLE_FLAGS (compile and link flags for the
#              example programs: a sanitizer build's), PYTHON_MODULE (ON: check the installed
#              module), PYTHON_EXECUTABLE.
cmake_minimum_required(VERSION 3.25)

foreach(var SOURCE_DIR BUILD_DIR WORK_DIR VERSION)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "install test: -D${var}=... is required")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()
string(TOUPPER ${CONFIG} config_upper)

set(prefix ${WORK_DIR}/prefix)
set(example_build ${WORK_DIR}/examples-build)
set(libdir ${prefix}/lib)

# Runs a command, echoing it; stops the test with the step's name if it fails.
function(run_step name)
  message(STATUS "install test: ${name}")
  execute_process(COMMAND ${ARGN} COMMAND_ECHO STDOUT RESULT_VARIABLE result)
  if(NOT result STREQUAL "0")
    message(FATAL_ERROR "install test: step '${name}' failed (exit status: ${result})")
  endif()
endfunction()

# Fails unless the file exists.
function(require_file path)
  if(NOT EXISTS ${path})
    message(FATAL_ERROR "install test: ${path} was not installed")
  endif()
endfunction()

# The shared libraries a program or library was linked against (its ELF NEEDED entries).
function(needed_libraries binary out)
  execute_process(COMMAND objdump -p ${binary} OUTPUT_VARIABLE dump RESULT_VARIABLE result)
  if(NOT result STREQUAL "0")
    message(FATAL_ERROR "install test: objdump -p ${binary} failed")
  endif()
  string(REGEX MATCHALL "NEEDED +[^\n]+" needed "${dump}")
  set(${out} "${needed}" PARENT_SCOPE)
endfunction()

# A program of the core alone must not be linked against assimp or OpenAL.
function(require_core_only binary)
  needed_libraries(${binary} needed)
  if(needed MATCHES "assimp|openal")
    message(FATAL_ERROR "install test: ${binary} needs assimp or OpenAL: ${needed}")
  endif()
endfunction()

# Runs hello_triangle and checks that it wrote a PNG.
function(run_hello binary image)
  run_step("run ${binary}" ${CMAKE_COMMAND} -E env LD_LIBRARY_PATH=${libdir} ${binary} ${image})
  if(NOT EXISTS ${image})
    message(FATAL_ERROR "install test: ${binary} did not write ${image}")
  endif()
  file(READ ${image} signature LIMIT 8 HEX)
  if(NOT signature STREQUAL "89504e470d0a1a0a")
    message(FATAL_ERROR "install test: ${image} is not a PNG (starts with ${signature})")
  endif()
endfunction()

# The build's generator and compiler, for every project this test configures.
set(toolchain_args "")
if(GENERATOR)
  list(APPEND toolchain_args -G ${GENERATOR})
endif()
if(CXX_COMPILER)
  list(APPEND toolchain_args -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
endif()
if(EXAMPLE_FLAGS)
  list(APPEND toolchain_args "-DCMAKE_CXX_FLAGS=${EXAMPLE_FLAGS}"
       "-DCMAKE_EXE_LINKER_FLAGS=${EXAMPLE_FLAGS}")
endif()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# 1. Install.
set(layers facet facet-import facet-worlds facet-sound)
run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})

# 2. The files a user relies on.
foreach(file include/facet/facet.hpp include/facet/renderer.hpp include/facet/version.hpp
        include/facet/import.hpp include/facet/worlds.hpp include/facet/sound.hpp
        lib/pkgconfig/facet.pc lib/pkgconfig/facet-all.pc share/man/man1/facet.1
        lib/cmake/facet/facetConfig.cmake lib/cmake/facet/facetConfigVersion.cmake)
  require_file(${prefix}/${file})
endforeach()
foreach(layer ${layers})
  if(SHARED)
    string(REGEX MATCH "^[0-9]+" major "${VERSION}")
    require_file(${libdir}/lib${layer}.so.${VERSION})
    require_file(${libdir}/lib${layer}.so)
    execute_process(COMMAND objdump -p ${libdir}/lib${layer}.so OUTPUT_VARIABLE dump)
    if(NOT dump MATCHES "SONAME +lib${layer}\\.so\\.${major}\n")
      message(FATAL_ERROR "install test: lib${layer}.so has no SONAME lib${layer}.so.${major}")
    endif()
  else()
    require_file(${libdir}/lib${layer}.a)
  endif()
endforeach()
if(SHARED)
  needed_libraries(${libdir}/libfacet.so core_needed)
  if(core_needed MATCHES "assimp|openal|SDL")
    message(FATAL_ERROR "install test: libfacet.so links more than the core needs: ${core_needed}")
  endif()
endif()
require_file(${prefix}/bin/facet)
execute_process(COMMAND ${prefix}/bin/facet --version OUTPUT_VARIABLE version_line
                RESULT_VARIABLE result)
if(NOT result STREQUAL "0" OR NOT version_line STREQUAL "facet ${VERSION}\n")
  message(FATAL_ERROR "install test: facet --version printed '${version_line}', not "
                      "'facet ${VERSION}'")
endif()
# A shared build's program starts without the viewer's libraries; its module, in lib/facet/,
# runs `facet view` (SDL's dummy drivers: no display needed).
if(SHARED)
  require_file(${libdir}/facet/facet-view.so)
  needed_libraries(${prefix}/bin/facet program_needed)
  if(program_needed MATCHES "SDL|openal|EGL|OpenGL|facet-sound")
    message(FATAL_ERROR "install test: bin/facet links the modules' libraries: ${program_needed}")
  endif()
  run_step("run the installed viewer module" ${CMAKE_COMMAND} -E env SDL_VIDEODRIVER=dummy
           SDL_AUDIODRIVER=dummy ${prefix}/bin/facet view --frames 1 --size 16x16 --scene shapes)
endif()
# The thumbnailer's Exec line, run as a file manager would (%s %i %o filled in, `facet` found
# in the prefix), must write a PNG thumbnail of a model.
set(thumbnailer ${prefix}/share/thumbnailers/facet.thumbnailer)
require_file(${thumbnailer})
file(STRINGS ${thumbnailer} exec_line REGEX "^Exec=facet ")
if(NOT exec_line MATCHES "%s" OR NOT exec_line MATCHES "%i" OR NOT exec_line MATCHES "%o")
  message(FATAL_ERROR "install test: ${thumbnailer} has no Exec=facet line with %s %i %o")
endif()
set(model ${WORK_DIR}/tetrahedron.obj)
file(WRITE ${model} "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
set(thumbnail ${WORK_DIR}/thumbnail.png)
string(REGEX REPLACE "^Exec=facet " "" exec_args "${exec_line}")
string(REPLACE "%s" "64" exec_args "${exec_args}")
string(REPLACE "%i" "${model}" exec_args "${exec_args}")
string(REPLACE "%o" "${thumbnail}" exec_args "${exec_args}")
separate_arguments(exec_args UNIX_COMMAND "${exec_args}")
run_step("run the thumbnailer's Exec line" ${prefix}/bin/facet ${exec_args})
file(READ ${thumbnail} signature LIMIT 8 HEX)
if(NOT signature STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "install test: the thumbnailer wrote no PNG to ${thumbnail}")
endif()

# 3. Build the example against the installed package only (no package registry, no build tree),
#    with assimp and OpenAL unfindable: the core must not need them.
set(configure_args
  -S ${SOURCE_DIR}/examples -B ${example_build}
  -DCMAKE_PREFIX_PATH=${prefix}
  -DCMAKE_BUILD_TYPE=${CONFIG}
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_DISABLE_FIND_PACKAGE_assimp=ON
  -DCMAKE_DISABLE_FIND_PACKAGE_OpenAL=ON
  ${toolchain_args})
run_step("configure examples/ with find_package(facet COMPONENTS core)" ${CMAKE_COMMAND}
         ${configure_args})

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
find_program(hello hello_triangle PATHS ${example_build} ${example_build}/${CONFIG}
             NO_DEFAULT_PATH REQUIRED)
require_core_only(${hello})

# 4. The same program with plain g++ and pkg-config.
if(NOT CXX_COMPILER)
  set(CXX_COMPILER g++)
endif()
set(hello_pc ${WORK_DIR}/hello_triangle_pkg_config)
run_step("build hello_triangle with pkg-config" sh -c
  "PKG_CONFIG_PATH='${libdir}/pkgconfig' && export PKG_CONFIG_PATH && \
   '${CXX_COMPILER}' -O1 ${EXAMPLE_FLAGS} '${SOURCE_DIR}/examples/hello_triangle.cpp' \
   -o '${hello_pc}' $(pkg-config --cflags --libs facet)")
require_core_only(${hello_pc})

# 5. Run them.
run_hello(${hello} ${WORK_DIR}/hello_triangle.png)
run_hello(${hello_pc} ${WORK_DIR}/hello_triangle_pkg_config.png)

# 6. The Python module, installed with the rest, imports from the prefix alone.
if(PYTHON_MODULE)
  file(GLOB_RECURSE python_package LIST_DIRECTORIES false ${prefix}/__init__.py)
  list(FILTER python_package INCLUDE REGEX "/facet/__init__\\.py$")
  list(LENGTH python_package found)
  if(NOT found EQUAL 1)
    message(FATAL_ERROR "install test: expected one facet/__init__.py in ${prefix}, got "
                        "'${python_package}'")
  endif()
  get_filename_component(python_package ${python_package} DIRECTORY)
  get_filename_component(site_packages ${python_package} DIRECTORY)
  set(python_image ${WORK_DIR}/python_triangle.png)
  run_step("render with the installed Python module" ${CMAKE_COMMAND} -E env
    PYTHONPATH=${site_packages} PYTHONDONTWRITEBYTECODE=1
    ${PYTHON_EXECUTABLE} -c "import facet, sys
assert facet.__file__.startswith(sys.argv[1]), facet.__file__
scene = facet.Scene()
scene.add_mesh([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[0, 1, 2]])
frame = facet.Renderer(64, 48).render(scene, facet.Camera.look_at((0, 0, 3), (0, 0, 0)))
facet.write_png(sys.argv[2], frame['color'])" ${site_packages} ${python_image})
  if(NOT EXISTS ${python_image})
    message(FATAL_ERROR "install test: the installed Python module did not write ${python_image}")
  endif()
endif()
message(STATUS "install test: ok")
