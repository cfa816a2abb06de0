# `make install PREFIX=...` (cmake --install) and `make deb` (CPack): the corlab program, the C++
# library libcorlab with its headers, the DEM C library (CorlabDemInstall.cmake), the data, the
# Python package, find_package(corlab) and pkg-config (corlab, corlab-cxx). Every path is relative
# to the prefix, so one build installs to any prefix; the installed code finds its data from where
# it was loaded (corlab::installed_data_directory()), with no environment variable.
# SPDX-License-Identifier: BSD-3-Clause
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(CORLAB_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/corlab)
set(CORLAB_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/corlab)
# The Python package, with no pip: Debian's /usr/bin/python3 searches
# /usr/local/lib/python3.X/dist-packages (make install, default prefix) and
# /usr/lib/python3/dist-packages (the .deb; Debian's place for python3 packages). The extension is
# built for that one 3.X. `cmake --install` uses CORLAB_INSTALL_PYTHONDIR (component python); the
# .deb uses CORLAB_DEB_PYTHONDIR (component python_deb, installed only when asked for by name).
if(DEFINED PYTHON_VERSION_MAJOR AND DEFINED PYTHON_VERSION_MINOR)
  set(corlab_python_default lib/python${PYTHON_VERSION_MAJOR}.${PYTHON_VERSION_MINOR}/dist-packages)
else()
  set(corlab_python_default lib/python3/dist-packages)
endif()
set(CORLAB_INSTALL_PYTHONDIR ${corlab_python_default} CACHE STRING
  "Where the Python package corlab is installed, relative to the prefix")
set(CORLAB_DEB_PYTHONDIR lib/python3/dist-packages)

# The data directory as seen from each directory code is installed to (bin/, lib/, the Python
# package): compiled into corlab::installed_data_directory() and the CLI's report step.
set(corlab_data_from_code "")
foreach(code_dir ${CMAKE_INSTALL_BINDIR} ${CMAKE_INSTALL_LIBDIR} ${CORLAB_INSTALL_PYTHONDIR}/corlab
    ${CORLAB_DEB_PYTHONDIR}/corlab)
  file(RELATIVE_PATH rel /prefix/${code_dir} /prefix/${CORLAB_INSTALL_DATADIR})
  list(APPEND corlab_data_from_code ${rel})
endforeach()
list(REMOVE_DUPLICATES corlab_data_from_code)
list(JOIN corlab_data_from_code ":" corlab_data_from_code)
set_property(SOURCE ${PROJECT_SOURCE_DIR}/src/materials/data_directory.cpp
  TARGET_DIRECTORY corlab_materials APPEND PROPERTY
  COMPILE_DEFINITIONS CORLAB_INSTALL_DATA_FROM_CODE="${corlab_data_from_code}")
set(corlab_python_from_bin "")
foreach(python_dir ${CORLAB_INSTALL_PYTHONDIR} ${CORLAB_DEB_PYTHONDIR})
  file(RELATIVE_PATH rel /prefix/${CMAKE_INSTALL_BINDIR} /prefix/${python_dir})
  list(APPEND corlab_python_from_bin ${rel})
endforeach()
list(REMOVE_DUPLICATES corlab_python_from_bin)
list(JOIN corlab_python_from_bin ":" corlab_python_from_bin)
target_compile_definitions(corlab PRIVATE CORLAB_INSTALL_PYTHON_FROM_BIN="${corlab_python_from_bin}")

# libcorlab: every static module in one shared library (no second compile), for C++ programs
# built against an installed corlab. Its own dependencies stay private (DT_NEEDED); the headers
# need Eigen and nlohmann_json (header-only).
set(corlab_module_objects "")
foreach(module core materials restitution fem fit study paper dataset dem)
  list(APPEND corlab_module_objects $<TARGET_OBJECTS:corlab_${module}>)
endforeach()
add_library(corlab_shared SHARED ${corlab_module_objects})
# corlab::all brings the modules' own dependencies (its archives add nothing: every object is in).
target_link_libraries(corlab_shared PRIVATE corlab::all
  PUBLIC Eigen3::Eigen nlohmann_json::nlohmann_json)
target_include_directories(corlab_shared INTERFACE
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
target_compile_features(corlab_shared INTERFACE cxx_std_20)
# 0.x: every minor version may change the ABI.
set_target_properties(corlab_shared PROPERTIES OUTPUT_NAME corlab EXPORT_NAME corlab
  VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR}
  LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/lib)
add_library(corlab::corlab ALIAS corlab_shared)

install(TARGETS corlab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)
install(TARGETS corlab_shared EXPORT corlabCxxTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT cxx NAMELINK_COMPONENT cxx)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/corlab DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  COMPONENT cxx FILES_MATCHING PATTERN "*.hpp")
# The datasets and tables the report and users read: the FE datasets (sphere on flat, particle
# pairs), Kharaz et al.'s measured points with corlab's FE and DEM tables, the oblique studies.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/fe_restitution
  ${PROJECT_SOURCE_DIR}/data/fe_restitution_pairs ${PROJECT_SOURCE_DIR}/data/kharaz2001
  ${PROJECT_SOURCE_DIR}/data/oblique_studies ${PROJECT_SOURCE_DIR}/studies
  DESTINATION ${CORLAB_INSTALL_DATADIR} COMPONENT data)

if(TARGET _core)
  foreach(python_component python python_deb)
    if(python_component STREQUAL "python")
      set(python_dir ${CORLAB_INSTALL_PYTHONDIR})
      set(python_all "")
    else()
      set(python_dir ${CORLAB_DEB_PYTHONDIR})
      set(python_all EXCLUDE_FROM_ALL)
    endif()
    install(TARGETS _core LIBRARY DESTINATION ${python_dir}/corlab
      COMPONENT ${python_component} ${python_all})
    install(DIRECTORY ${CMAKE_BINARY_DIR}/python/corlab/ DESTINATION ${python_dir}/corlab
      COMPONENT ${python_component} ${python_all} FILES_MATCHING PATTERN "*.py" PATTERN "*.pyi"
      PATTERN "py.typed" PATTERN "__pycache__" EXCLUDE)
  endforeach()
endif()

# The licence with every binary (BSD-3-Clause asks for it), as Debian's machine-readable copyright
# file. The manual page: apps/CMakeLists.txt.
install(FILES ${PROJECT_SOURCE_DIR}/packaging/debian/copyright
  DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT cli)

# find_package(corlab): corlab::corlab_dem always, corlab::corlab (component cxx) when installed
# and its header-only dependencies are found.
install(EXPORT corlabTargets NAMESPACE corlab:: FILE corlabTargets.cmake
  DESTINATION ${CORLAB_INSTALL_CMAKEDIR} COMPONENT dem)
install(EXPORT corlabCxxTargets NAMESPACE corlab:: FILE corlabCxxTargets.cmake
  DESTINATION ${CORLAB_INSTALL_CMAKEDIR} COMPONENT cxx)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/corlabConfig.cmake.in
  ${CMAKE_BINARY_DIR}/corlabConfig.cmake INSTALL_DESTINATION ${CORLAB_INSTALL_CMAKEDIR}
  PATH_VARS CORLAB_INSTALL_DATADIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/corlabConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/corlabConfig.cmake ${CMAKE_BINARY_DIR}/corlabConfigVersion.cmake
  DESTINATION ${CORLAB_INSTALL_CMAKEDIR} COMPONENT dem)

# pkg-config: the prefix is found from the .pc file's own place (${pcfiledir}), so the same files
# serve any prefix, DESTDIR and the .deb.
file(RELATIVE_PATH corlab_pc_to_prefix /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(REGEX REPLACE "/$" "" corlab_pc_to_prefix "${corlab_pc_to_prefix}")
foreach(pc corlab corlab-cxx)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/${pc}.pc.in ${CMAKE_BINARY_DIR}/pkgconfig/${pc}.pc @ONLY)
endforeach()
install(FILES ${CMAKE_BINARY_DIR}/pkgconfig/corlab.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT dem)
install(FILES ${CMAKE_BINARY_DIR}/pkgconfig/corlab-cxx.pc
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT cxx)

include(${PROJECT_SOURCE_DIR}/cmake/CorlabPackage.cmake)  # make deb
