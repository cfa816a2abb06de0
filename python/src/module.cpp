// The compiled part of the Python package `corlab` (corlab._core).
// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/pybind11.h>

#include <utility>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/version.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "corlab: coefficient of restitution of elastic-plastic impacts (SI units)";
  m.attr("__version__") = std::string(corlab::kVersion);
  // corlab::InputError (bad input) becomes ValueError with the same one-line message and, as
  // data, the attributes field, value and constraint ("" when not about one field).
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(std::move(p));
    } catch (const corlab::InputError& e) {
      namespace py = pybind11;
      auto error =
          py::reinterpret_steal<py::object>(PyObject_CallFunction(PyExc_ValueError, "s", e.what()));
      if (!error) return;  // the Python error of the failed call stays set
      error.attr("field") = e.field();
      error.attr("value") = e.value();
      error.attr("constraint") = e.constraint();
      PyErr_SetObject(PyExc_ValueError, error.ptr());
    }
  });
  corlab::python::bind_materials(m);
  corlab::python::bind_models(m);
  corlab::python::bind_simulate(m);
  corlab::python::bind_study(m);
  corlab::python::bind_fit(m);
  corlab::python::bind_dem(m);
}
