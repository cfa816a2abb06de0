#pragma once
// One function per area; module.cpp calls them all. Each lives in bind_<area>.cpp.
#include <pybind11/pybind11.h>

namespace corlab::python {
void bind_materials(pybind11::module_& m);
void bind_models(pybind11::module_& m);
void bind_simulate(pybind11::module_& m);
void bind_study(pybind11::module_& m);
void bind_fit(pybind11::module_& m);
void bind_dem(pybind11::module_& m);
}  // namespace corlab::python
