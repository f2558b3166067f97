# `cpack -G DEB` in a build configured with CMAKE_INSTALL_PREFIX=/usr
# (scripts/package does both): edsc_<version>_<arch>.deb holding what
# `cmake --install` installs, with its runtime dependencies read from the
# binary by dpkg-shlibdeps, not from the build dependencies.
include(GNUInstallDirs)
file(READ ${PROJECT_SOURCE_DIR}/packaging/description.txt _edsc_description)
# Line 1 is the summary; the rest the long description, which CPack puts
# below it and indents. (REGEX REPLACE would apply ^ at every match.)
string(FIND "${_edsc_description}" "\n" _edsc_eol)
string(SUBSTRING "${_edsc_description}" 0 ${_edsc_eol} CPACK_PACKAGE_DESCRIPTION_SUMMARY)
math(EXPR _edsc_eol "${_edsc_eol} + 1")
string(SUBSTRING "${_edsc_description}" ${_edsc_eol} -1 CPACK_PACKAGE_DESCRIPTION)
string(REPLACE "\n " "\n" CPACK_PACKAGE_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION}")
string(STRIP "${CPACK_PACKAGE_DESCRIPTION}" CPACK_PACKAGE_DESCRIPTION)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME edsc)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "edsc developers <edsc@example.org>")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Lintian wants the folders a package creates owned by root, modes 0755.
set(CPACK_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
    OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

# Debian asks every package for its copyright and a changelog in its doc folder.
install(FILES ${PROJECT_SOURCE_DIR}/packaging/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})
string(TIMESTAMP _edsc_date "%a, %d %b %Y %H:%M:%S +0000" UTC)
file(WRITE ${CMAKE_BINARY_DIR}/packaging/changelog
     "edsc (${PROJECT_VERSION}) unstable; urgency=medium\n\n"
     "  * Release ${PROJECT_VERSION}; docs/ holds what it does.\n\n"
     " -- ${CPACK_PACKAGE_CONTACT}  ${_edsc_date}\n")
add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/packaging/changelog.gz
  COMMAND gzip -9nkf ${CMAKE_BINARY_DIR}/packaging/changelog
  DEPENDS ${CMAKE_BINARY_DIR}/packaging/changelog VERBATIM)
add_custom_target(edsc_changelog ALL DEPENDS ${CMAKE_BINARY_DIR}/packaging/changelog.gz)
install(FILES ${CMAKE_BINARY_DIR}/packaging/changelog.gz DESTINATION ${CMAKE_INSTALL_DOCDIR})
include(CPack)
