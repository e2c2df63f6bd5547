# The library, in layers (see the README's layout): each is its own target and folder and links
# only what it uses. Includes flow downward only (tools/check_layers.py, run by ctest).
#
#   facet::core    src/core, src/shading, src/pipeline   glm, zlib, oneTBB, Highway (stb inside)
#   facet::import  src/import                            core, assimp, tinygltf, Draco, meshopt, oneTBB
#   facet::worlds  src/worlds                            core, oneTBB
#   facet::sound   src/sound                             OpenAL Soft
#   facet::gl      src/gl (optional: FACET_BUILD_GL)     core, OpenGL, EGL
#   facet::facet   all four (an interface target: the umbrella for users who want everything)
#
# Libraries are shared unless BUILD_SHARED_LIBS is off (CMakeLists.txt); shared ones carry a
# SONAME of the major version (libfacet.so.0).

configure_file(${PROJECT_SOURCE_DIR}/cmake/version.hpp.in
               ${PROJECT_BINARY_DIR}/include/facet/version.hpp @ONLY)

# Standard and glm headers that most of facet's files include, parsed once per target instead of
# in each file (they are about half of a small file's compile; facet's own headers are not in
# it, so a file must still include what it uses of facet). Highway's headers stay out: its
# kernels include themselves once per SIMD target.
set(FACET_PRECOMPILED_HEADERS <algorithm> <cmath> <cstdint> <memory> <string> <vector>
    <glm/glm.hpp>)

# facet_layer(NAME EXPORT_NAME OUTPUT_NAME SOURCES...): one layer's library target.
function(facet_layer name export_name output_name)
  add_library(${name} ${ARGN})
  add_library(facet::${export_name} ALIAS ${name})
  target_include_directories(${name}
    PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
           $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>
           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${PROJECT_SOURCE_DIR}/src)
  # A shared layer's own calls bind to its own functions (nothing interposes them), so GCC may
  # call them directly and inline them, not through the PLT.
  target_compile_options(${name} PRIVATE ${FACET_WARNINGS} -fno-semantic-interposition)
  target_precompile_headers(${name} PRIVATE ${FACET_PRECOMPILED_HEADERS})
  target_compile_features(${name} PUBLIC cxx_std_20)
  set_target_properties(${name} PROPERTIES
    EXPORT_NAME ${export_name}
    OUTPUT_NAME ${output_name}
    POSITION_INDEPENDENT_CODE ON
    VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}
    # Installed shared layers find each other in their own folder, wherever the prefix.
    INSTALL_RPATH "$ORIGIN")
endfunction()

# The reference rasterizer (src/pipeline/reference.cpp) is the tests' oracle, not part of the
# library: tests/CMakeLists.txt compiles it.
file(GLOB_RECURSE FACET_CORE_SOURCES CONFIGURE_DEPENDS
     ${PROJECT_SOURCE_DIR}/src/core/*.cpp ${PROJECT_SOURCE_DIR}/src/shading/*.cpp
     ${PROJECT_SOURCE_DIR}/src/pipeline/*.cpp)
list(REMOVE_ITEM FACET_CORE_SOURCES ${PROJECT_SOURCE_DIR}/src/pipeline/reference.cpp)
facet_layer(facet_core core facet ${FACET_CORE_SOURCES})
target_link_libraries(facet_core PUBLIC glm::glm PRIVATE ZLIB::ZLIB TBB::tbb hwy::hwy)

file(GLOB FACET_IMPORT_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/import/*.cpp)
facet_layer(facet_import import facet-import ${FACET_IMPORT_SOURCES})
target_link_libraries(facet_import PUBLIC facet_core PRIVATE assimp::assimp TBB::tbb
                      nlohmann_json::nlohmann_json draco::draco meshoptimizer::meshoptimizer)
target_include_directories(facet_import PRIVATE ${TINYGLTF_INCLUDE_DIR})
# No stb in tinygltf (facet decodes images itself); every file including the header agrees.
target_compile_definitions(facet_import PRIVATE TINYGLTF_NO_STB_IMAGE TINYGLTF_NO_STB_IMAGE_WRITE)
# Debian's header, not facet's code: its warnings are not ours to read.
set_source_files_properties(${PROJECT_SOURCE_DIR}/src/import/gltf_tinygltf.cpp
                            PROPERTIES COMPILE_OPTIONS -w)

file(GLOB_RECURSE FACET_WORLDS_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/worlds/*.cpp)
facet_layer(facet_worlds worlds facet-worlds ${FACET_WORLDS_SOURCES})
target_link_libraries(facet_worlds PUBLIC facet_core PRIVATE TBB::tbb)

file(GLOB FACET_SOUND_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/sound/*.cpp)
facet_layer(facet_sound sound facet-sound ${FACET_SOUND_SOURCES})
target_link_libraries(facet_sound PUBLIC facet_core PRIVATE OpenAL::OpenAL)

# The OpenGL twin: not in the umbrella, so nothing but the program and the tests links OpenGL.
# Not installed (its header neither: cmake/Install.cmake), so static even in a shared build: the
# installed program carries it.
if(FACET_BUILD_GL)
  file(GLOB FACET_GL_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/gl/*.cpp)
  facet_layer(facet_gl gl facet-gl STATIC ${FACET_GL_SOURCES})
  target_link_libraries(facet_gl PUBLIC facet_core PRIVATE OpenGL::OpenGL OpenGL::EGL)
endif()

add_library(facet_all INTERFACE)
add_library(facet::facet ALIAS facet_all)
set_target_properties(facet_all PROPERTIES EXPORT_NAME facet)
target_link_libraries(facet_all INTERFACE facet_core facet_import facet_worlds facet_sound)

# The benchmark scenes (bench/scenes: the glmark2 equivalents, bunny-close, million, ...) are not
# part of the library: the facet program and the tests link them. They plug their own shading
# models into the pipeline (src/pipeline/record/custom_draw.hpp), so they see its headers.
if(FACET_BUILD_PROGRAM OR FACET_BUILD_TESTS)
  file(GLOB FACET_BENCH_SCENE_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/bench/scenes/*.cpp)
  add_library(facet_bench_scenes STATIC ${FACET_BENCH_SCENE_SOURCES})
  target_include_directories(facet_bench_scenes
    PUBLIC ${PROJECT_SOURCE_DIR}/bench PRIVATE ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(facet_bench_scenes PUBLIC facet_core PRIVATE facet_import facet_worlds
                        hwy::hwy)
  target_compile_options(facet_bench_scenes PRIVATE ${FACET_WARNINGS})
  target_precompile_headers(facet_bench_scenes PRIVATE ${FACET_PRECOMPILED_HEADERS})
  set_target_properties(facet_bench_scenes PROPERTIES POSITION_INDEPENDENT_CODE ON)
endif()

# The classic rasterizers (src/classic, docs/classic/): three short fills for learners, not part
# of the library (nothing installs them). The tests and apps/classic's demo link them; they see
# the core's public headers only (tools/check_layers.py).
if(FACET_BUILD_PROGRAM OR FACET_BUILD_TESTS)
  file(GLOB FACET_CLASSIC_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/classic/*.cpp)
  add_library(facet_classic STATIC ${FACET_CLASSIC_SOURCES})
  target_include_directories(facet_classic PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(facet_classic PUBLIC facet_core)
  target_compile_options(facet_classic PRIVATE ${FACET_WARNINGS})
  target_precompile_headers(facet_classic PRIVATE ${FACET_PRECOMPILED_HEADERS})
endif()
