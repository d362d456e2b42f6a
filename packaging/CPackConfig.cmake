# Debian package of the filmdyn executable with desktop integration: `cpack -G DEB` in the build
# directory writes filmdyn_<version>_amd64.deb. Dependencies are computed by dpkg-shlibdeps.
install(FILES "${PROJECT_SOURCE_DIR}/packaging/filmdyn.desktop" DESTINATION share/applications)
install(FILES "${PROJECT_SOURCE_DIR}/resources/icons/filmdyn.svg"
        DESTINATION share/icons/hicolor/scalable/apps)
set(CPACK_PACKAGE_NAME "filmdyn")
set(CPACK_PACKAGE_VENDOR "FilmDyn")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_CONTACT "FilmDyn developers <dev@filmdyn.invalid>")
set(CPACK_GENERATOR "DEB")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
include(CPack)
