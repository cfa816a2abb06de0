// The table of ImpactConfig keys (config_key_table.hpp): unit, range, doc and accessor of each
// key, in documentation order.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/config/config_key_table.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <string_view>

namespace corlab::fem::config_table {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

KeyEntry entry(std::string_view key,
               std::string_view unit,
               std::optional<KeyRange> range,
               std::string_view doc,
               Accessor access,
               std::string_view echo_in = {}) {
  return {{key, kKindOf[access.index()], unit, range, doc, echo_in}, access};
}

KeyRange closed(double lo, double hi, std::string_view why = {}) {
  return {lo, hi, false, false, why};
}
KeyRange open_closed(double lo, double hi, std::string_view why = {}) {
  return {lo, hi, true, false, why};
}
KeyRange open(double lo, double hi, std::string_view why = {}) { return {lo, hi, true, true, why}; }
KeyRange closed_open(double lo, double hi, std::string_view why = {}) {
  return {lo, hi, false, true, why};
}

template <bool kSphere>
Material& body(ImpactConfig& c) {
  if constexpr (kSphere) {
    return c.sphere.material;
  } else {
    return c.substrate.material;
  }
}

// The six material keys of one body; `k` are their names in the order material, E, nu, rho,
// sigma_y, hardening. summary.json echoes the properties inside the material's object.
template <bool kSphere>
void add_material_keys(std::vector<KeyEntry>& t, const std::array<std::string_view, 6>& k) {
  t.push_back(entry(
      k[0], "", std::nullopt,
      "database name and/or E=..,nu=..,rho=..[,sy=..][,H=..] (applied first)",
      +[](ImpactConfig& c) { return &body<kSphere>(c); }));
  t.push_back(entry(
      k[1], "[Pa]", closed(1e4, 1e13, "from gels to 10 x diamond"), "Young's modulus E",
      +[](ImpactConfig& c) { return &body<kSphere>(c).youngs_modulus; }, k[0]));
  t.push_back(entry(
      k[2], "[-]", open(-1.0, 0.5, "isotropic elasticity"), "Poisson's ratio nu",
      +[](ImpactConfig& c) { return &body<kSphere>(c).poisson_ratio; }, k[0]));
  t.push_back(entry(
      k[3], "[kg/m^3]", closed(1.0, 1e5, "from foams to 4 x osmium"), "density rho",
      +[](ImpactConfig& c) { return &body<kSphere>(c).density; }, k[0]));
  t.push_back(entry(
      k[4], "[Pa]", open(0.0, kInf),
      "yield stress, `none` = elastic (yield strain sigma_y/E in [1e-5, 0.1))",
      +[](ImpactConfig& c) { return &body<kSphere>(c).yield_stress; }, k[0]));
  t.push_back(entry(
      k[5], "[Pa]", closed(0.0, kInf), "linear isotropic hardening modulus H (< E)",
      +[](ImpactConfig& c) { return &body<kSphere>(c).hardening_modulus; }, k[0]));
}

void add_geometry_and_mesh_keys(std::vector<KeyEntry>& t) {
  t.push_back(entry(
      "impact.velocity", "[m/s]",
      open_closed(0.0, 1000.0, "no equation of state for hypervelocity impact"),
      "impact speed towards the substrate", +[](ImpactConfig& c) { return &c.impact.velocity; }));
  t.push_back(entry(
      "impact.gap", "[m]", closed(0.0, 1.0),
      "initial gap, crossed in exact free flight (also <= sphere.radius)",
      +[](ImpactConfig& c) { return &c.impact.gap; }));
  t.push_back(entry(
      "impact.repeats", "[-]", closed(1.0, 100.0, "each impact costs a single run"),
      "impacts of the pair on the same spot (> 1: repeated impacts carrying residual stress, "
      "plastic strain and shape; e of each in e_impacts)",
      +[](ImpactConfig& c) { return &c.impact.repeats; }));
  t.push_back(entry(
      "impact.angle", "[deg]", closed_open(0.0, 90.0, "from the contact normal; 90 never touches"),
      "angle of the impact velocity from the contact normal (0, or >= 1 with solver.model = 3d; "
      "the normal speed is impact.velocity cos(angle))",
      +[](ImpactConfig& c) { return &c.impact.angle; }));
  t.push_back(entry(
      "contact.friction", "[-]", closed(0.0, 10.0), "Coulomb friction coefficient mu (3-D model)",
      +[](ImpactConfig& c) { return &c.contact.friction; }));
  t.push_back(entry(
      "contact.friction_enforcement", "", std::nullopt,
      "how the 3-D model holds stick: kinematic (the force that stops the relative tangential "
      "motion over the step, capped at mu f_n; Taylor & Flanagan 1989) | penalty (a tangential "
      "spring k_t = the normal penalty with a Coulomb return map: compliant)",
      +[](ImpactConfig& c) { return &c.contact.enforcement; }));
  t.push_back(entry(
      "mesh.h_min", "[m]", open_closed(0.0, 1.0),
      "element size at the contact (3-D model: with this and mesh.contact_elements unset, a/4)",
      +[](ImpactConfig& c) { return &c.mesh.h_min; }));
  t.push_back(entry(
      "mesh.contact_elements", "[-]", closed(0.0, 1000.0),
      "h <= predicted contact radius / this (0 = off)",
      +[](ImpactConfig& c) { return &c.mesh.contact_elements; }));
  t.push_back(entry(
      "mesh.refine_factor", "[-]", closed(1.0, 10.0),
      "refined zone radius = this x predicted contact radius",
      +[](ImpactConfig& c) { return &c.mesh.refine_factor; }));
  t.push_back(entry(
      "mesh.refine_depth", "[-]", closed(0.25, 10.0),
      "refined zone depth below the contact = this x predicted contact radius",
      +[](ImpactConfig& c) { return &c.mesh.refine_depth; }));
  t.push_back(entry(
      "mesh.growth", "[-]", closed(1.0, MeshConfig::kMaxGrowth),
      "size ratio of neighbouring elements outside the zone",
      +[](ImpactConfig& c) { return &c.mesh.growth; }));
  t.push_back(entry(
      "mesh.h_max", "[m]", open_closed(0.0, 1.0), "largest element size (also >= mesh.h_min)",
      +[](ImpactConfig& c) { return &c.mesh.h_max; }));
  t.push_back(entry(
      "mesh.transitions", "[-]", closed(0.0, 1.0, "0 = off, 1 = on"),
      "3:1 transitions in the tensor-grid substrate and the sphere's ring and skin (fewer "
      "elements; axisymmetric model)",
      +[](ImpactConfig& c) { return &c.mesh.transitions; }));
  t.push_back(entry(
      "mesh.file", "", std::nullopt,
      "Gmsh .msh file instead of the built-in mesh (geometry keys then unused)",
      +[](ImpactConfig& c) { return &c.mesh.file; }));
}

void add_solver_keys(std::vector<KeyEntry>& t) {
  t.push_back(entry(
      "solver.model", "", std::nullopt,
      "axisymmetric (normal impacts) | 3d (the 3-D half model: hexahedra, friction, oblique "
      "impacts); this key alone chooses the model",
      +[](ImpactConfig& c) { return &c.solver.model; }));
  t.push_back(entry(
      "solver.safety_factor", "[-]",
      open_closed(0.0, 1.0, "and <= 1/sqrt(1 + solver.penalty_scale)"),
      "dt = this x stable step estimate",
      +[](ImpactConfig& c) { return &c.solver.safety_factor; }));
  t.push_back(entry(
      "solver.hourglass", "[-]",
      closed(0.0, 0.15, "LS-DYNA: stiffness hourglass above 0.15 may be unstable"),
      "Flanagan-Belytschko stiffness hourglass coefficient (axisymmetric quads)",
      +[](ImpactConfig& c) { return &c.solver.hourglass; }));
  t.push_back(entry(
      "solver.hourglass_3d", "[-]",
      closed(0.0, 0.15, "LS-DYNA: stiffness hourglass above 0.15 may be unstable"),
      "the same for the 3-D model's hexahedra",
      +[](ImpactConfig& c) { return &c.solver.hourglass_3d; }));
  t.push_back(entry(
      "solver.bulk_viscosity_linear", "[-]",
      closed(0.0, 0.12, "2 x the ABAQUS/Explicit and LS-DYNA default 0.06"),
      "linear bulk viscosity b1",
      +[](ImpactConfig& c) { return &c.solver.bulk_viscosity_linear; }));
  t.push_back(entry(
      "solver.bulk_viscosity_quadratic", "[-]",
      closed(0.0, 2.0, "ABAQUS/Explicit default 1.2, LS-DYNA 1.5"), "quadratic bulk viscosity b2",
      +[](ImpactConfig& c) { return &c.solver.bulk_viscosity_quadratic; }));
  t.push_back(entry(
      "solver.penalty_scale", "[-]",
      closed(0.1, 0.5, "softer lets the bodies interpenetrate, stiffer is unstable"),
      "contact penalty k = this x m_eff (2 / dt_crit)^2",
      +[](ImpactConfig& c) { return &c.solver.penalty_scale; }));
  t.push_back(entry(
      "solver.t_max", "[s]", closed(0.0, 10.0),
      "hard stop (0 = 20 Hertz contact times after contact; else > gap/velocity)",
      +[](ImpactConfig& c) { return &c.solver.t_max; }));
  t.push_back(entry(
      "solver.max_steps", "[-]", closed(1.0, 1e12),
      "refuse a run estimated to need more time steps (raise it to run anyway)",
      +[](ImpactConfig& c) { return &c.solver.max_steps; }));
  t.push_back(entry(
      "solver.max_elements", "[-]", closed(1.0, 1e9),
      "refuse, before meshing, a run whose mesh is estimated to have more elements (raise it to "
      "run anyway)",
      +[](ImpactConfig& c) { return &c.solver.max_elements; }));
  t.push_back(entry(
      "solver.max_element_steps", "[-]", closed(1.0, 1e16),
      "refuse, before meshing, a run estimated to need more element updates (elements x "
      "expected steps; raise it to run anyway)",
      +[](ImpactConfig& c) { return &c.solver.max_element_steps; }));
}

void add_step_control_and_output_keys(std::vector<KeyEntry>& t) {
  t.push_back(entry(
      "solver.subcycling_levels", "[-]", closed(0.0, 6.0, "2^6 = 64 base steps per major cycle"),
      "element subcycling: elements step at up to 2^this x the base step (0 = off; axisymmetric "
      "model)",
      +[](ImpactConfig& c) { return &c.solver.subcycling_levels; }));
  t.push_back(entry(
      "solver.mass_scaling_max", "[-]",
      closed(1.0, 64.0, "dt x 64 = density x 4096 at the contact"),
      "mass scaling: the base step may grow up to this factor times the step floor (the "
      "contact's h-squares' step; 1 = off, floor included; axisymmetric model)",
      +[](ImpactConfig& c) { return &c.solver.mass_scaling_max; }));
  t.push_back(entry(
      "solver.mass_scaling_inertia", "[-]", closed(0.0, 1e-2, "quasi-static contact zone"),
      "mass scaling: bound on the added inertia (F^2 - 1) rho v^2 / p_ref (axisymmetric model)",
      +[](ImpactConfig& c) { return &c.solver.mass_scaling_inertia; }));
  t.push_back(entry(
      "solver.in_run_step_floor", "[-]", closed(0.0, 0.95, "below the run's first step"),
      "in-run mass scaling: substrate elements whose stable step falls below this fraction of "
      "the first step get mass during the run (0 = off; axisymmetric model, without subcycling)",
      +[](ImpactConfig& c) { return &c.solver.in_run_step_floor; }));
  t.push_back(entry(
      "solver.in_run_added_mass", "[-]", closed(0.0, 1e-2, "1 % of the sphere's mass"),
      "in-run mass scaling: bound on the mass it adds, a fraction of the sphere's mass",
      +[](ImpactConfig& c) { return &c.solver.in_run_added_mass; }));
  t.push_back(entry(
      "output.times", "[s]", closed(0.0, 10.0), "times at which to write VTU fields (a list)",
      +[](ImpactConfig& c) { return &c.output.field_times; }));
  t.push_back(entry(
      "output.history_every", "[-]", closed(1.0, 1e9), "write a history row every N steps",
      +[](ImpactConfig& c) { return &c.output.history_every; }));
}

std::vector<KeyEntry> build_table() {
  std::vector<KeyEntry> t;
  t.push_back(entry(
      "sphere.radius", "[m]", closed(1e-6, 1.0), "sphere radius R",
      +[](ImpactConfig& c) { return &c.sphere.radius; }));
  add_material_keys<true>(t, {"sphere.material", "sphere.E", "sphere.nu", "sphere.rho",
                              "sphere.sigma_y", "sphere.hardening"});
  t.push_back(entry(
      "substrate.shape", "", std::nullopt,
      "what the sphere hits: flat (the elastic-plastic substrate below) | rigid (a rigid "
      "frictionless flat; the substrate keys are then unused) | sphere (a second sphere at rest, "
      "radius substrate.radius, of substrate.material)",
      +[](ImpactConfig& c) { return &c.substrate.shape; }));
  t.push_back(entry(
      "substrate.radius", "[m]", closed(1e-6, 10.0),
      "radial extent (also >= 2 predicted contact radii); for substrate.shape = sphere its "
      "radius R2",
      +[](ImpactConfig& c) { return &c.substrate.radius; }));
  t.push_back(entry(
      "substrate.depth", "[m]", closed(1e-6, 10.0),
      "depth, bottom face fixed unless substrate.boundary absorbs (also >= 2 predicted contact "
      "radii)",
      +[](ImpactConfig& c) { return &c.substrate.depth; }));
  t.push_back(entry(
      "substrate.boundary", "", std::nullopt,
      "the flat's far faces: fixed (base held, sides free; waves reflect) | absorbing "
      "(Lysmer-Kuhlemeyer dashpots rho c_p, rho c_s on the sides and base) | viscous_spring "
      "(the dashpots and springs alpha G / distance: a small block stands for the half-space); "
      "substrate.shape = flat only; the 3-D model's default block takes viscous_spring",
      +[](ImpactConfig& c) { return &c.substrate.boundary; }));
  add_material_keys<false>(t, {"substrate.material", "substrate.E", "substrate.nu", "substrate.rho",
                               "substrate.sigma_y", "substrate.hardening"});
  add_geometry_and_mesh_keys(t);
  add_solver_keys(t);
  add_step_control_and_output_keys(t);
  return t;
}

}  // namespace

const std::vector<KeyEntry>& key_table() {
  static const std::vector<KeyEntry> table = build_table();
  return table;
}

const KeyEntry* find_entry(std::string_view key) {
  const auto& t = key_table();
  const auto it =
      std::find_if(t.begin(), t.end(), [key](const KeyEntry& e) { return e.info.key == key; });
  return it == t.end() ? nullptr : &*it;
}

}  // namespace corlab::fem::config_table
