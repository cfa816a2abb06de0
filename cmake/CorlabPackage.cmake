# `make deb` (cpack -G DEB in the build folder): one Debian package of everything `make install`
# installs, for prefix /usr. Runtime libraries come from dpkg-shlibdeps; the Python side is listed.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME corlab)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "coefficient of restitution of elastic-plastic impacts: models, FE solver, DEM inputs")
set(CPACK_PACKAGE_DESCRIPTION
  "corlab gives the coefficient of restitution e(v) of a sphere on a substrate from analytic
models and an explicit axisymmetric FE solver (with a discretisation error bar), reproduces
Ma et al. 2023, and writes DEM inputs for LAMMPS, LIGGGHTS and YADE. This package holds the
corlab program, the C++ library libcorlab and the DEM C library libcorlab_dem with their headers,
CMake and pkg-config files, the Python package corlab, the material database, the study specs
and the FE restitution dataset.")
set(CPACK_PACKAGE_CONTACT "corlab maintainers <maintainers@users.noreply.h-seed-ee181e80.example>")
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/package)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
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
# Byte-compile the Python package at install and remove the caches before removal (py3compile,
# py3clean from python3-minimal, as dh_python3 does), so that `dpkg -r` leaves nothing behind.
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
  ${PROJECT_SOURCE_DIR}/packaging/debian/postinst ${PROJECT_SOURCE_DIR}/packaging/debian/prerm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
