// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One function per area; module.cpp calls them all. Each lives in bind_<area>.cpp.
#include <pybind11/pybind11.h>

#include <nlohmann/json_fwd.hpp>

namespace corlab::python {
void bind_materials(pybind11::module_& m);
void bind_models(pybind11::module_& m);
void bind_simulate(pybind11::module_& m);
void bind_study(pybind11::module_& m);
void bind_fit(pybind11::module_& m);
void bind_dem(pybind11::module_& m);

/// A JSON value as Python objects (objects as dicts, arrays as lists, null as None): for records
/// whose one serialisation is JSON (the config echo, a model's description).
pybind11::object json_to_python(const nlohmann::json& j);
}  // namespace corlab::python
