# Pip install test (ctest: PipInstall, after InstallAndBuildExample, whose prefix it
# uses), run as a script with cmake -P:
#   1. a virtual environment that sees the system's packages (NumPy), without pip of its own:
#      python3 -m venv --system-site-packages --without-pip (the system's pip runs in it)
#   2. pip install --no-index --no-build-isolation SOURCE_DIR with FACET_PREFIX=PREFIX: setup.py
#      builds the module against the installed shared facet, offline
#   3. check that only the module was built (it needs libfacet.so.0; no facet library was
#      compiled), that it was installed into the environment, and that the source tree gained
#      nothing
#   4. import it from elsewhere and render a PNG
# Any failing step stops the script with FATAL_ERROR, which fails the test.
#
# Inputs (-D): SOURCE_DIR (project root), WORK_DIR (scratch, wiped), PREFIX (an installed
#              shared facet), PYTHON_EXECUTABLE, optional GENERATOR, CXX_COMPILER,
#              CXX_LAUNCHER (e.g. ccache).
cmake_minimum_required(VERSION 3.25)

foreach(var SOURCE_DIR WORK_DIR PREFIX PYTHON_EXECUTABLE)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "pip install test: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXISTS ${PREFIX}/lib/cmake/facet/facetConfig.cmake)
  message(FATAL_ERROR "pip install test: no facet installed in ${PREFIX} (run "
                      "InstallAndBuildExample first; ctest does, as a fixture)")
endif()

function(run_step name)
  message(STATUS "pip install test: ${name}")
  execute_process(COMMAND ${ARGN} COMMAND_ECHO STDOUT WORKING_DIRECTORY ${WORK_DIR}
                  RESULT_VARIABLE result)
  if(NOT result STREQUAL "0")
    message(FATAL_ERROR "pip install test: step '${name}' failed (exit status: ${result})")
  endif()
endfunction()

# What git sees in the source tree (untracked files included), to compare after the install.
function(source_status out)
  execute_process(COMMAND git -C ${SOURCE_DIR} status --porcelain --untracked-files=all
                  OUTPUT_VARIABLE status RESULT_VARIABLE result ERROR_QUIET)
  if(NOT result STREQUAL "0")
    set(status "(not a git tree)")
  endif()
  set(${out} "${status}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(venv ${WORK_DIR}/venv)
set(python ${venv}/bin/python)

# 1. The environment.
run_step("make a virtual environment" ${PYTHON_EXECUTABLE} -m venv --system-site-packages
         --without-pip ${venv})

# 2. pip install, offline, against the installed facet. The environment is the build's: its
#    compiler, generator and launcher; PYTHONPATH is cleared so nothing else is imported.
set(build_env FACET_PREFIX=${PREFIX} FACET_PYTHON_BUILD_DIR=${WORK_DIR}/build
    CMAKE_BUILD_PARALLEL_LEVEL=2 PIP_NO_CACHE_DIR=1 PIP_DISABLE_PIP_VERSION_CHECK=1)
if(GENERATOR)
  list(APPEND build_env CMAKE_GENERATOR=${GENERATOR})
endif()
if(CXX_COMPILER)
  list(APPEND build_env CXX=${CXX_COMPILER})
endif()
if(CXX_LAUNCHER)
  list(APPEND build_env CMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
source_status(status_before)
run_step("pip install" ${CMAKE_COMMAND} -E env --unset=PYTHONPATH ${build_env}
         ${python} -m pip install --no-index --no-build-isolation ${SOURCE_DIR})
source_status(status_after)
if(NOT status_before STREQUAL status_after)
  message(FATAL_ERROR "pip install test: pip install changed the source tree:\n${status_after}")
endif()

# 3. Only the module was compiled, against the installed libraries, and it is in the venv.
file(GLOB_RECURSE facet_libraries ${WORK_DIR}/build/libfacet*)
if(facet_libraries)
  message(FATAL_ERROR "pip install test: facet's libraries were built from source, not found "
                      "in ${PREFIX}: ${facet_libraries}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=PYTHONPATH
                        ${python} -c "import facet._facet as m; print(m.__file__, end='')"
                WORKING_DIRECTORY ${WORK_DIR} OUTPUT_VARIABLE module RESULT_VARIABLE result)
if(NOT result STREQUAL "0")
  message(FATAL_ERROR "pip install test: the installed module does not import")
endif()
string(FIND "${module}" "${venv}/lib/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "pip install test: facet imports from ${module}, not from ${venv}")
endif()
execute_process(COMMAND objdump -p ${module} OUTPUT_VARIABLE dump)
if(NOT dump MATCHES "NEEDED +libfacet\\.so\\.[0-9]+")
  message(FATAL_ERROR "pip install test: ${module} does not use the installed libfacet.so")
endif()

# 4. Use it.
set(image ${WORK_DIR}/pip_triangle.png)
run_step("render with the pip-installed module" ${CMAKE_COMMAND} -E env --unset=PYTHONPATH
  ${python} -c "import facet, sys
scene = facet.Scene()
scene.add_mesh([[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[0, 1, 2]])
frame = facet.Renderer(64, 48).render(scene, facet.Camera.look_at((0, 0, 3), (0, 0, 0)))
assert frame['color'].shape == (48, 64, 4) and frame['depth'].max() > 0
facet.write_png(sys.argv[1], frame['color'])" ${image})
if(NOT EXISTS ${image})
  message(FATAL_ERROR "pip install test: the pip-installed module did not write ${image}")
endif()
message(STATUS "pip install test: ok")
