// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One function per area; module.cpp calls them all. Each lives in bind_<area>.cpp.
#include <pybind11/pybind11.h>

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

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

/// A Python str as UTF-8 text; a str that has none (a lone surrogate, "\ud800") is an InputError
/// (ValueError) naming `field` and the value's repr, not pybind11's "Unable to cast" RuntimeError.
std::string utf8_text(const pybind11::handle& text, std::string_view field);
}  // namespace corlab::python
