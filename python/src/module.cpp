// The compiled part of the Python package `corlab` (corlab._core).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/version.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "corlab: coefficient of restitution of elastic-plastic impacts (SI units)";
  m.attr("__version__") = std::string(corlab::kVersion);
  // corlab::InputError (bad input) becomes ValueError with the same one-line message.
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const corlab::InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  corlab::python::bind_materials(m);
  corlab::python::bind_models(m);
  corlab::python::bind_simulate(m);
  corlab::python::bind_study(m);
  corlab::python::bind_fit(m);
  corlab::python::bind_dem(m);
}
