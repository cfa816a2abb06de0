// Materials and dimensionless groups.
// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/materials/material.hpp"
#include "corlab/materials/material_database.hpp"

namespace py = pybind11;

namespace corlab::python {

void bind_materials(py::module_& m) {
  py::class_<Material>(m, "Material", "Isotropic material, SI units")
      .def(py::init([](double E, double nu, double rho, std::optional<double> sigma_y, double H,
                       std::string name) {
             Material mat{.name = std::move(name),
                          .youngs_modulus = E,
                          .poisson_ratio = nu,
                          .density = rho,
                          .yield_stress = sigma_y,
                          .hardening_modulus = H,
                          .source = ""};
             validate(mat, "material");
             return mat;
           }),
           py::arg("E"), py::arg("nu"), py::arg("rho"), py::arg("sigma_y") = py::none(),
           py::arg("H") = 0.0, py::arg("name") = "inline")
      .def_readonly("name", &Material::name)
      .def_readonly("E", &Material::youngs_modulus, "Young's modulus [Pa]")
      .def_readonly("nu", &Material::poisson_ratio, "Poisson's ratio [-]")
      .def_readonly("rho", &Material::density, "density [kg/m^3]")
      .def_readonly("sigma_y", &Material::yield_stress, "yield stress [Pa] or None")
      .def_readonly("H", &Material::hardening_modulus, "linear hardening modulus [Pa]")
      .def_readonly("source", &Material::source)
      .def("__repr__", [](const Material& mat) {
        return "Material(" + mat.name + ", E=" + std::to_string(mat.youngs_modulus) + ")";
      });
  m.def(
      "material", [](const std::string& spec) { return parse_material_spec(spec, "material"); },
      py::arg("spec"),
      "Material from a database name, 'E=..,nu=..,rho=..[,sy=..]', or 'name,key=value'.");
  m.def("material_names", [] { return MaterialDatabase::builtin().names(); });
  m.def("effective_modulus",
        py::overload_cast<const Material&, const Material&>(&effective_modulus), py::arg("sphere"),
        py::arg("substrate"), "E* [Pa] (Ma et al. 2023 eq. 3)");
  m.def(
      "k1",
      [](double e_star, double rho, double v) {
        require_positive("E_star", e_star, "[Pa]");
        require_positive("rho", rho, "[kg/m^3]");
        require_positive("v", v, "[m/s]");
        return k1(e_star, rho, v);
      },
      py::arg("E_star"), py::arg("rho"), py::arg("v"),
      "k1 = E*/(rho v^2) (Ma et al. 2023 eq. 5); ValueError unless every input is finite and > 0");
  m.def(
      "k2",
      [](double sigma_y, double e_star) {
        require_positive("sigma_y", sigma_y, "[Pa]");
        require_positive("E_star", e_star, "[Pa]");
        return k2(sigma_y, e_star);
      },
      py::arg("sigma_y"), py::arg("E_star"),
      "k2 = sigma_y/E* (Ma eq. 6); ValueError unless both are finite and > 0");
}

}  // namespace corlab::python
