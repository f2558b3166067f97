# `cmake --install` layout: bin/edsc, share/edsc/templates/ (the built-in
# templates, for reference and as a starting point for --template-dir) and a
# CMake package (lib/cmake/edsc/) so firmware builds can call edsc_add_header().
include(CMakePackageConfigHelpers)
set(EDSC_PACKAGE_DIR lib/cmake/edsc)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/templates/ DESTINATION share/edsc/templates
        FILES_MATCHING PATTERN "*.mustache")
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/edscConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_SOURCE_DIR}/cmake/edscConfig.cmake
              ${PROJECT_SOURCE_DIR}/cmake/edscHeader.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/edscConfigVersion.cmake
        DESTINATION ${EDSC_PACKAGE_DIR})
# The user documentation, where diagnostics' help links point (EDSC_DOCS_URI).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
