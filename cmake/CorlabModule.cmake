# corlab_module(NAME <name> DEPS <targets...>)
# A module is a static library built from every .cpp under src/<name>/; its public headers live
# under include/corlab/<name>/. Adding a source file needs no CMake edit (re-run configure).
# SPDX-License-Identifier: BSD-3-Clause
function(corlab_module)
  cmake_parse_arguments(ARG "" "NAME" "DEPS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/${ARG_NAME}/*.cpp")
  if(NOT sources)  # a module with no sources yet still links (and carries its dependencies)
    set(sources "${PROJECT_BINARY_DIR}/empty_${ARG_NAME}.cpp")
    file(WRITE ${sources} "// empty module\n")
  endif()
  add_library(corlab_${ARG_NAME} STATIC ${sources})
  target_include_directories(corlab_${ARG_NAME}
    PUBLIC ${PROJECT_SOURCE_DIR}/include
    PRIVATE ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(corlab_${ARG_NAME} PUBLIC ${ARG_DEPS} PRIVATE corlab_warnings)
  target_compile_definitions(corlab_${ARG_NAME} PRIVATE
    CORLAB_DATA_DIR="${CORLAB_DATA_DIR}" CORLAB_STUDIES_DIR="${CORLAB_STUDIES_DIR}")
  add_library(corlab::${ARG_NAME} ALIAS corlab_${ARG_NAME})
endfunction()

# corlab_tests(DIR <dir> LABEL <label> LIBS <targets...>)
# Every <dir>/**/*_test.cpp becomes one GoogleTest executable; its tests carry LABEL.
function(corlab_tests)
  cmake_parse_arguments(ARG "" "DIR;LABEL" "LIBS" ${ARGN})
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS "${ARG_DIR}/*_test.cpp")
  foreach(test_src ${tests})
    get_filename_component(name ${test_src} NAME_WE)
    set(target ${ARG_LABEL}_${name})
    add_executable(${target} ${test_src})
    target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests ${PROJECT_SOURCE_DIR}/src)
    target_link_libraries(${target} PRIVATE ${ARG_LIBS} GTest::gtest_main corlab_warnings)
    target_compile_definitions(${target} PRIVATE
      CORLAB_DATA_DIR="${CORLAB_DATA_DIR}" CORLAB_STUDIES_DIR="${CORLAB_STUDIES_DIR}"
      CORLAB_SOURCE_DIR="${PROJECT_SOURCE_DIR}" CORLAB_BINARY_DIR="${PROJECT_BINARY_DIR}")
    set_target_properties(${target} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
    gtest_discover_tests(${target} PROPERTIES LABELS ${ARG_LABEL} DISCOVERY_TIMEOUT 60)
  endforeach()
endfunction()
