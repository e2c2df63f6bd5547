# Install rules: `cmake --install build --prefix P` puts
#   P/include/facet/*.hpp                        public headers (version.hpp generated)
#   P/lib/libfacet{,-import,-worlds,-sound}.a    the layers (.so with a SONAME when shared)
#   P/bin/facet                                  the command-line program
#   P/lib/facet/facet-{view,gl}.so               its modules, in a shared build: the viewer and
#                                                the OpenGL twin's backend
#   P/lib/cmake/facet/facet*.cmake               the package: find_package(facet) gives
#                                                facet::core, ::import, ::worlds, ::sound and
#                                                the umbrella facet::facet
#   P/lib/pkgconfig/facet.pc, facet-all.pc       the core's and the umbrella's link lines
#   P/share/man/man1/facet.1                     the manual page
#   P/share/thumbnailers/facet.thumbnailer       model thumbnails for file managers (with the
#                                                program)
# tests/install/install_and_build_example.cmake checks all of it by building examples/.

include(CMakePackageConfigHelpers)

set(FACET_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/facet
    CACHE STRING "Where the facet CMake package files are installed, relative to the prefix")

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/facet
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp"
        PATTERN "gl.hpp" EXCLUDE)  # the OpenGL twin's library is not installed
install(FILES ${PROJECT_BINARY_DIR}/include/facet/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/facet)

install(TARGETS facet_core facet_import facet_worlds facet_sound facet_all EXPORT facetTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
if(FACET_BUILD_PROGRAM)
  install(TARGETS facet_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # The program's modules (apps/facet/modules.hpp), where it looks for them.
  foreach(module facet_view_module facet_gl_module)
    if(TARGET ${module})
      install(TARGETS ${module} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/facet)
    endif()
  endforeach()
  install(FILES ${PROJECT_SOURCE_DIR}/data/facet.thumbnailer
          DESTINATION ${CMAKE_INSTALL_DATADIR}/thumbnailers)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/docs/facet.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

install(EXPORT facetTargets
        NAMESPACE facet::
        FILE facetTargets.cmake
        DESTINATION ${FACET_INSTALL_CMAKEDIR})

if(BUILD_SHARED_LIBS)
  set(FACET_PACKAGE_SHARED TRUE)
else()
  set(FACET_PACKAGE_SHARED FALSE)
endif()
configure_package_config_file(
  ${PROJECT_SOURCE_DIR}/cmake/facetConfig.cmake.in
  ${PROJECT_BINARY_DIR}/facetConfig.cmake
  INSTALL_DESTINATION ${FACET_INSTALL_CMAKEDIR})
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/facetConfigVersion.cmake
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/facetConfig.cmake ${PROJECT_BINARY_DIR}/facetConfigVersion.cmake
        DESTINATION ${FACET_INSTALL_CMAKEDIR})

# pkg-config. A static library's own dependencies must be on the program's link line, so for
# static builds they are in Libs (plain `pkg-config --libs facet` links); a shared library
# carries them itself, so they go to Libs.private.
set(FACET_PC_CORE_DEPS "-lz -ltbb -lhwy")
set(FACET_PC_ALL_DEPS "${FACET_PC_CORE_DEPS} -lassimp -ldraco -lmeshoptimizer -lopenal")
if(BUILD_SHARED_LIBS)
  set(FACET_PC_CORE_LIBS "")
  set(FACET_PC_CORE_PRIVATE "${FACET_PC_CORE_DEPS}")
  set(FACET_PC_ALL_LIBS "")
  set(FACET_PC_ALL_PRIVATE "${FACET_PC_ALL_DEPS}")
else()
  set(FACET_PC_CORE_LIBS "${FACET_PC_CORE_DEPS}")
  set(FACET_PC_CORE_PRIVATE "")
  set(FACET_PC_ALL_LIBS "${FACET_PC_ALL_DEPS}")
  set(FACET_PC_ALL_PRIVATE "")
endif()
file(RELATIVE_PATH FACET_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
foreach(pc facet facet-all)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/${pc}.pc.in ${PROJECT_BINARY_DIR}/${pc}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/${pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endforeach()
