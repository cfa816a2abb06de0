// The compiled part of the Python package `corlab` (corlab._core).
// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/pybind11.h>

#include <string>
#include <string_view>
#include <utility>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/version.hpp"

namespace corlab::python {

std::string utf8_text(const pybind11::handle& text, std::string_view field) {
  namespace py = pybind11;
  try {
    return text.cast<std::string>();
  } catch (const py::cast_error&) {
    // shown with the surrogate escaped ("a\ud800b")
    const auto shown = py::str(text).attr("encode")("utf-8", "backslashreplace");
    throw_invalid(field, shown.cast<std::string>(),
                  "text that has a UTF-8 form (no lone surrogate such as \\ud800)");
  }
}

}  // namespace corlab::python

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
    } catch (const pybind11::cast_error& e) {
      // A Python value a binding could not convert (a str where a number is due): bad input,
      // so ValueError, not pybind11's RuntimeError. The bindings that know the field say it.
      PyErr_SetString(PyExc_ValueError,
                      (std::string("invalid value: a Python value of the wrong type or form (") +
                       e.what() + ")")
                          .c_str());
    }
  });
  corlab::python::bind_materials(m);
  corlab::python::bind_models(m);
  corlab::python::bind_simulate(m);
  corlab::python::bind_study(m);
  corlab::python::bind_fit(m);
  corlab::python::bind_dem(m);
}
