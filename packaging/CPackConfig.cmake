# The Debian 12 package (README "Install"): `cpack -G DEB` in a built build folder writes
# millexpert_<version>_amd64.deb. Its version is project()'s; its Depends line is what dpkg-shlibdeps
# finds the four programs linked against, plus the Qt plugins they load at run time.
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "millexpert")
set(CPACK_PACKAGE_VENDOR "MillExpert")
set(CPACK_PACKAGE_CONTACT "MillExpert developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "Stability lobes of milling tools (zeroth-order approximation and semi-discretization),\ntime-domain chatter simulation, expert selection of tools and cutting parameters,\nadaptive force and supervisory control. The window (millexpert), the command-line tool\n(millexpert-cli, JSON output), the report writer (millexpert-report), the chart renderer\n(millexpert-plot), and example projects in /usr/share/millexpert/projects.")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Plugins are loaded, not linked, so dpkg-shlibdeps cannot see them: the SQLite driver of the learning
# database (the platform plugins come with libqt6gui6, the SVG ones with libqt6svg6).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6sql6-sqlite")
# The desktop's caches of MIME types, icons and desktop entries; their dpkg triggers pick up our files.
# The PostgreSQL driver of a shop's shared learning database (docs/learning-database.md): recommended,
# as a single computer runs on the SQLite file alone.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "shared-mime-info, hicolor-icon-theme, desktop-file-utils, libqt6sql6-psql")
set(CPACK_STRIP_FILES ON)
# gzip: xz would take most of the package test's time on the 2-core machine (docs/performance.md).
set(CPACK_DEBIAN_COMPRESSION_TYPE "gzip")
# cpack packages what the build made and never starts a build itself (the packaging.deb test runs it
# on the finished build): the install step does not depend on "all".
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
include(CPack)
