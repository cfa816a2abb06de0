# The shared C library libcorlab_dem (include/corlab/corlab_dem.h) and its installation:
# headers, library, material data, CMake package config (find_package(corlab)) and pkg-config.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

add_library(corlab_dem_c SHARED ${PROJECT_SOURCE_DIR}/src/dem_capi/corlab_dem.cpp)
set_target_properties(corlab_dem_c PROPERTIES OUTPUT_NAME corlab_dem VERSION ${PROJECT_VERSION}
  SOVERSION ${PROJECT_VERSION_MAJOR} EXPORT_NAME corlab_dem CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
  LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/lib)
target_include_directories(corlab_dem_c PUBLIC
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
# Only the C API is exported; the static corlab modules stay internal.
target_link_libraries(corlab_dem_c PRIVATE corlab::dem corlab_warnings)
target_link_options(corlab_dem_c PRIVATE "LINKER:--exclude-libs,ALL")
target_compile_definitions(corlab_dem_c PRIVATE
  CORLAB_DEM_INSTALL_DATA_DIR="${CMAKE_INSTALL_FULL_DATADIR}/corlab")
add_library(corlab::corlab_dem ALIAS corlab_dem_c)

install(TARGETS corlab_dem_c EXPORT corlabTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dem)
install(FILES ${PROJECT_SOURCE_DIR}/include/corlab/corlab_dem.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/corlab COMPONENT dem)
install(FILES ${PROJECT_SOURCE_DIR}/data/materials.toml
  DESTINATION ${CMAKE_INSTALL_DATADIR}/corlab COMPONENT dem)
install(EXPORT corlabTargets NAMESPACE corlab:: FILE corlabTargets.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/corlab COMPONENT dem)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/corlabConfig.cmake.in
  ${CMAKE_BINARY_DIR}/corlabConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/corlab
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/corlabConfigVersion.cmake
  COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_BINARY_DIR}/corlabConfig.cmake ${CMAKE_BINARY_DIR}/corlabConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/corlab COMPONENT dem)
# pkg-config: prefix substituted at install time, so `cmake --install --prefix P` is honoured.
set(PC_PREFIX "@PC_PREFIX@")  # kept for the install-time substitution below
configure_file(${PROJECT_SOURCE_DIR}/cmake/corlab.pc.in ${CMAKE_BINARY_DIR}/corlab.pc.in.cfg @ONLY)
install(CODE "
  file(READ \"${CMAKE_BINARY_DIR}/corlab.pc.in.cfg\" pc)
  string(REPLACE \"@PC_PREFIX@\" \"\${CMAKE_INSTALL_PREFIX}\" pc \"\${pc}\")
  file(WRITE \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig/corlab.pc\" \"\${pc}\")
  message(STATUS \"Installing: \${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig/corlab.pc\")
" COMPONENT dem)
