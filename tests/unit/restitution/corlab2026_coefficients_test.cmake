# corlab2026's coefficients come from model_fit.json, and a coefficient the file lacks, one
# kCorlab2026Coefficients lacks, or one that is not a number is a build error naming it
# (cmake/Corlab2026Coefficients.cmake, src/restitution/corlab2026.cpp).
#   cmake -DSOURCE_DIR=... -DCXX=... -DWORK=... -P corlab2026_coefficients_test.cmake
# SPDX-License-Identifier: BSD-3-Clause
set(json ${SOURCE_DIR}/data/fe_restitution/model_fit.json)
set(generator ${SOURCE_DIR}/cmake/Corlab2026Coefficients.cmake)
file(REMOVE_RECURSE ${WORK})
file(READ ${json} shipped)

# Generates the fragment from `text` and compiles corlab2026.cpp with it (syntax only); sets
# rc_var and out_var to the generator's or the compiler's exit code and output.
function(build_with case text rc_var out_var)
  file(WRITE ${WORK}/${case}/model_fit.json "${text}")
  execute_process(COMMAND ${CMAKE_COMMAND} -DJSON=${WORK}/${case}/model_fit.json
    -DOUT=${WORK}/${case}/corlab2026_fitted.inc -P ${generator}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc EQUAL 0)
    execute_process(COMMAND ${CXX} -std=c++20 -fsyntax-only -I${SOURCE_DIR}/include -I${SOURCE_DIR}/src
      -I${WORK}/${case} ${SOURCE_DIR}/src/restitution/corlab2026.cpp
      RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  endif()
  set(${rc_var} ${rc} PARENT_SCOPE)
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

function(expect_error case text name)
  build_with(${case} "${text}" rc out)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${case}: built, expected an error naming ${name}")
  endif()
  if(NOT out MATCHES "\"${name}\"")
    message(FATAL_ERROR "${case}: the error does not name \"${name}\":\n${out}")
  endif()
  message(STATUS "${case}: build error naming \"${name}\"")
endfunction()

build_with(shipped "${shipped}" rc out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the shipped model_fit.json does not build:\n${out}")
endif()
file(STRINGS ${WORK}/shipped/corlab2026_fitted.inc entries REGEX "^{\"")
list(LENGTH entries n)
if(NOT n EQUAL 11)
  message(FATAL_ERROR "expected the 11 coefficients of model_fit.json, generated ${n}")
endif()

string(JSON extra SET "${shipped}" coefficients zeta 0.5)
expect_error(extra "${extra}" zeta)
string(JSON missing REMOVE "${shipped}" coefficients kappa_cavity)
expect_error(missing "${missing}" kappa_cavity)
string(JSON text SET "${shipped}" coefficients c1 "\"0.25\"")
expect_error(not_a_number "${text}" c1)
