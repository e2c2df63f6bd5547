# Install rules: `cmake --install build --prefix P` puts
#   P/include/facet/*.hpp                 public headers
#   P/lib/libfacet.a                      the library
#   P/bin/facet                           the command-line program
#   P/lib/cmake/facet/facet*.cmake        the package, so find_package(facet) gives facet::facet
# tests/install/install_and_build_example.cmake checks all of it by building examples/.

include(CMakePackageConfigHelpers)

set(FACET_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/facet
    CACHE STRING "Where the facet CMake package files are installed, relative to the prefix")

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/facet
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")

install(TARGETS facet EXPORT facetTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS facet_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(EXPORT facetTargets
        NAMESPACE facet::
        FILE facetTargets.cmake
        DESTINATION ${FACET_INSTALL_CMAKEDIR})

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
