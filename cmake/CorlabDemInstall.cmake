# The shared C library libcorlab_dem (include/corlab/corlab_dem.h) and its install rules (component
# dem); the package files (find_package(corlab), pkg-config) are written by CorlabInstall.cmake.
# SPDX-License-Identifier: BSD-3-Clause
include(GNUInstallDirs)

add_library(corlab_dem_c SHARED ${PROJECT_SOURCE_DIR}/src/dem_capi/corlab_dem.cpp)
set_target_properties(corlab_dem_c PROPERTIES OUTPUT_NAME corlab_dem VERSION ${PROJECT_VERSION}
  SOVERSION ${PROJECT_VERSION_MAJOR} EXPORT_NAME corlab_dem CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
  LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/lib)
target_include_directories(corlab_dem_c PUBLIC
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
# Only the C API is exported; the static corlab modules stay internal.
target_link_libraries(corlab_dem_c PRIVATE corlab::dem corlab_warnings)
target_link_options(corlab_dem_c PRIVATE "LINKER:--exclude-libs,ALL")
add_library(corlab::corlab_dem ALIAS corlab_dem_c)

install(TARGETS corlab_dem_c EXPORT corlabTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dem NAMELINK_COMPONENT dem)
install(FILES ${PROJECT_SOURCE_DIR}/include/corlab/corlab_dem.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/corlab COMPONENT dem)
install(FILES ${PROJECT_SOURCE_DIR}/data/materials.toml
  DESTINATION ${CMAKE_INSTALL_DATADIR}/corlab COMPONENT dem)
