# `make deb` (cpack -G DEB in the build folder): one Debian package of everything `make install`
# installs, for prefix /usr, laid out as Debian's policy asks: libraries in the multiarch folder,
# the Python package in /usr/lib/python3/dist-packages, the copyright file, a Debian changelog,
# a manual page, an ldconfig trigger (packaging/debian/). One package rather than a library, a
# -dev, a CLI, a python3- and a data package: corlab is released as one version of all of them and
# the CLI, the Python package and both libraries read the same data; lintian's two warnings on
# that (package-name-doesnt-match-sonames, link-to-shared-library-in-wrong-package) are the cost.
# Runtime libraries come from dpkg-shlibdeps; the Python side is listed.
# SPDX-License-Identifier: BSD-3-Clause
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME corlab)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "coefficient of restitution of elastic-plastic impacts")
# Debian's description: lines of at most 80 characters.
set(CPACK_PACKAGE_DESCRIPTION "\
corlab gives the coefficient of restitution e(v) of a sphere on a substrate, or
of two particles, from analytic models and an explicit FE solver with a
discretisation error bar; it reproduces Ma et al. 2023 and writes DEM inputs
for LAMMPS, LIGGGHTS and YADE.
This package holds the corlab program, the C++ library libcorlab, the DEM C
library libcorlab_dem with their headers, CMake and pkg-config files, the
Python package corlab, the material database, the study specs and the FE
restitution datasets.")
set(CPACK_PACKAGE_CONTACT "${CORLAB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CORLAB_MAINTAINER}")
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/package)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
# The components `cmake --install` installs, less `python` (lib/python3.X) and plus `python_deb`
# (lib/python3/dist-packages) and `deb` (the Debian changelog), in one package.
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_GROUPING ALL_COMPONENTS_IN_ONE)
set(CPACK_COMPONENTS_ALL cli cxx dem data deb)
if(TARGET _core)
  list(APPEND CPACK_COMPONENTS_ALL python_deb)
endif()
# The extension module is built for one Python 3.X (as dh_python3 would say it).
if(DEFINED PYTHON_VERSION_MINOR)
  math(EXPR corlab_next_minor "${PYTHON_VERSION_MINOR} + 1")
  set(corlab_deb_python "python3 (>= ${PYTHON_VERSION_MAJOR}.${PYTHON_VERSION_MINOR}~), \
python3 (<< ${PYTHON_VERSION_MAJOR}.${corlab_next_minor})")
else()
  set(corlab_deb_python python3)
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "${corlab_deb_python}, python3-numpy, python3-matplotlib, python3-scipy")
# What building C++ against corlab::corlab / corlab-cxx needs (header-only dependencies).
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libeigen3-dev, nlohmann-json3-dev, cmake, pkg-config")
# postinst byte-compiles the Python package and prerm removes the caches (py3compile, py3clean
# from python3-minimal, as dh_python3 does), so that `dpkg -r` leaves nothing behind; the
# triggers file runs ldconfig; postrm has nothing to do (it replaces CPack's ldconfig call, and
# packaging/debian/lintian-overrides says so).
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/packaging/debian/postinst
  ${PROJECT_SOURCE_DIR}/packaging/debian/prerm ${PROJECT_SOURCE_DIR}/packaging/debian/postrm
  ${PROJECT_SOURCE_DIR}/packaging/debian/triggers)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

# The Debian changelog of this native package (usr/share/doc/corlab/changelog.gz), one entry for
# this version; its date follows SOURCE_DATE_EPOCH when set. The changes are in CHANGELOG.md.
string(TIMESTAMP corlab_changelog_date "%a, %d %b %Y %H:%M:%S +0000" UTC)
file(WRITE ${CMAKE_BINARY_DIR}/debian/changelog "\
corlab (${PROJECT_VERSION}) unstable; urgency=medium

  * corlab ${PROJECT_VERSION}; the changes are listed in the source's CHANGELOG.md.

 -- ${CORLAB_MAINTAINER}  ${corlab_changelog_date}
")
execute_process(COMMAND gzip -9nkf ${CMAKE_BINARY_DIR}/debian/changelog COMMAND_ERROR_IS_FATAL ANY)
install(FILES ${CMAKE_BINARY_DIR}/debian/changelog.gz DESTINATION ${CMAKE_INSTALL_DOCDIR}
  COMPONENT deb EXCLUDE_FROM_ALL)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/debian/lintian-overrides
  DESTINATION ${CMAKE_INSTALL_DATADIR}/lintian/overrides RENAME corlab COMPONENT deb EXCLUDE_FROM_ALL)
include(CPack)
