# GSL for the explorer's WebAssembly build: the GSL parts src/dem uses (ODE, roots, minimisers,
# special functions and what they call), compiled by emcc from Debian's source package.
#   CORLAB_GSL_SOURCE_DIR  the unpacked source (`apt-get source gsl`; `make explorer` fetches it)
# Defines the static library corlab_gsl (headers as <gsl/gsl_*.h>). A GSL function of another
# part fails the link naming it: add its directory to gsl_parts.
# SPDX-License-Identifier: BSD-3-Clause
set(CORLAB_GSL_SOURCE_DIR "" CACHE PATH "Debian's GSL source (apt-get source gsl)")
if(NOT EXISTS "${CORLAB_GSL_SOURCE_DIR}/configure" OR
   NOT EXISTS "${CORLAB_GSL_SOURCE_DIR}/gsl_math.h")
  message(FATAL_ERROR "corlab explorer: CORLAB_GSL_SOURCE_DIR = '${CORLAB_GSL_SOURCE_DIR}' is not "
    "a GSL source tree (make explorer fetches it with `apt-get source gsl`)")
endif()
set(gsl_parts err sys ieee-utils complex poly roots min ode-initval2 specfunc)

# config.h for wasm32: GSL's own configure, run once with emcc (no x87 excess precision).
set(gsl_build ${PROJECT_BINARY_DIR}/gsl)
if(NOT EXISTS ${gsl_build}/config.h)
  file(MAKE_DIRECTORY ${gsl_build})
  message(STATUS "corlab explorer: configuring GSL for wasm32 (about a minute)")
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env CC=${CMAKE_C_COMPILER}
      ${CORLAB_GSL_SOURCE_DIR}/configure --disable-shared --host=wasm32-unknown-none
      --build=x86_64-pc-linux-gnu ac_cv_c_extended_fp=no
    WORKING_DIRECTORY ${gsl_build} RESULT_VARIABLE gsl_configure
    OUTPUT_FILE ${gsl_build}/configure.log ERROR_FILE ${gsl_build}/configure.log)
  if(NOT gsl_configure EQUAL 0)
    file(REMOVE ${gsl_build}/config.h)
    message(FATAL_ERROR "corlab explorer: GSL's configure failed (${gsl_build}/configure.log)")
  endif()
endif()

# Headers as installed: <gsl/gsl_*.h>.
file(GLOB gsl_headers ${CORLAB_GSL_SOURCE_DIR}/gsl_*.h ${CORLAB_GSL_SOURCE_DIR}/*/gsl_*.h)
file(COPY ${gsl_headers} DESTINATION ${gsl_build}/include/gsl)

# Each part's library sources, as its Makefile.am lists them (lib<name>_la_SOURCES).
set(gsl_sources)
foreach(part ${gsl_parts})
  file(READ ${CORLAB_GSL_SOURCE_DIR}/${part}/Makefile.am makefile)
  string(REPLACE "\\\n" " " makefile "${makefile}")
  if(NOT makefile MATCHES "lib[a-z0-9]+_la_SOURCES *=([^\n]*)")
    message(FATAL_ERROR "corlab explorer: no library sources in GSL's ${part}/Makefile.am")
  endif()
  string(REGEX MATCHALL "[A-Za-z0-9_]+\\.c" files "${CMAKE_MATCH_1}")
  foreach(f ${files})
    list(APPEND gsl_sources ${CORLAB_GSL_SOURCE_DIR}/${part}/${f})
  endforeach()
endforeach()
add_library(corlab_gsl STATIC ${gsl_sources})
target_include_directories(corlab_gsl PRIVATE ${gsl_build} ${CORLAB_GSL_SOURCE_DIR})
target_include_directories(corlab_gsl SYSTEM PUBLIC ${gsl_build}/include)
target_compile_definitions(corlab_gsl PRIVATE HAVE_CONFIG_H=1)
target_compile_options(corlab_gsl PRIVATE -w)  # a third-party library: its warnings are not ours
