// The table of result fields (result_fields.hpp): one entry per field.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/result_fields.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <type_traits>

#include "corlab/materials/material.hpp"
#include "corlab/version.hpp"

namespace corlab::fem {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// Accessor of an ImpactResult member: empty for a failed run (no result). Integers are widened to
/// long long; an enum is written as `to_string(value)` (found by argument-dependent lookup).
template <auto Member>
FieldValue result_member(const FieldInput& in) {
  if (in.result == nullptr) return {};
  const auto& v = in.result->*Member;
  using T = std::remove_cvref_t<decltype(v)>;
  if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, std::vector<double>>) {
    return v;  // a flag or a list of reals as it is
  } else if constexpr (std::is_integral_v<T>) {
    return static_cast<long long>(v);
  } else if constexpr (std::is_floating_point_v<T>) {
    return static_cast<double>(v);
  } else if constexpr (std::is_enum_v<T>) {
    return std::string(to_string(v));
  } else {
    return std::string(v);
  }
}

template <auto Member>
constexpr FieldKind member_kind() {
  using T = std::remove_cvref_t<decltype(std::declval<ImpactResult>().*Member)>;
  if constexpr (std::is_same_v<T, bool>) return FieldKind::boolean;
  if constexpr (std::is_integral_v<T>) return FieldKind::integer;
  if constexpr (std::is_floating_point_v<T>) return FieldKind::real;
  if constexpr (std::is_same_v<T, std::vector<double>>) return FieldKind::real_list;
  return FieldKind::text;
}

/// A field that is one ImpactResult member (kind and accessor follow from the member).
template <auto Member>
constexpr ResultField member(std::string_view name,
                             std::string_view unit,
                             std::string_view description,
                             std::uint8_t outputs) {
  return {name, unit, description, member_kind<Member>(), &result_member<Member>, outputs};
}

/// The same for a machine-dependent member (timings, instruction set): left out when two runs
/// are compared.
template <auto Member>
constexpr ResultField machine_member(std::string_view name,
                                     std::string_view unit,
                                     std::string_view description,
                                     std::uint8_t outputs) {
  ResultField f = member<Member>(name, unit, description, outputs);
  f.machine_dependent = true;
  return f;
}

/// A real-valued field computed from the case's inputs (written for failed runs too).
constexpr ResultField derived(std::string_view name,
                              std::string_view unit,
                              std::string_view description,
                              FieldValue (*value)(const FieldInput&)) {
  return {name, unit, description, FieldKind::real, value, kCsv};
}

FieldValue wall_time(const FieldInput& in) {
  if (in.result != nullptr && in.result->wall_s > 0.0) return in.result->wall_s;
  return in.wall_s;
}

double e_star(const FieldInput& in) { return contact_effective_modulus(*in.config); }

// The yield stress of the body that yields [Pa]: the substrate's; on the rigid flat, where only
// the sphere can yield, the sphere's (it was NaN, with k2, for a yielding sphere). NaN when that
// body is elastic (documented in the field's description).
double substrate_yield_stress(const FieldInput& in) {
  if (rigid_target(*in.config)) return in.config->sphere.material.yield_stress.value_or(kNan);
  return in.config->substrate.material.yield_stress.value_or(kNan);
}

FieldValue substrate_yield(const FieldInput& in) { return substrate_yield_stress(in); }

FieldValue k2_of(const FieldInput& in) {
  const double sy = substrate_yield_stress(in);
  return std::isnan(sy) ? kNan : k2(sy, e_star(in));
}

// k1 with rho* of the pair (the sphere's density on a flat, fixed or rigid).
FieldValue k1_of(const FieldInput& in) {
  const ImpactConfig& c = *in.config;
  const double rho1 = c.sphere.material.density;
  const double rho = sphere_target(c)
                         ? pair_effective_density(c.sphere.radius / c.substrate.radius, rho1,
                                                  rho1 / c.substrate.material.density)
                         : rho1;
  return k1(e_star(in), rho, c.impact.velocity);
}

using R = ImpactResult;

// A field that is the ImpactResult member of the same name (written once, so the two cannot
// drift), machine-dependent or not.
#define CORLAB_RESULT_MEMBER(member_name, ...) member<&R::member_name>(#member_name, __VA_ARGS__)
#define CORLAB_MACHINE_MEMBER(member_name, ...) \
  machine_member<&R::member_name>(#member_name, __VA_ARGS__)

// The order is the results.csv column order (existing files are resumed only with the same
// header): add a CSV field at the end of the result members, before the derived inputs.
const std::array kFields{
    CORLAB_RESULT_MEMBER(e, "-", "CoR from momentum: rebound / impact c.o.m. velocity", kBoth),
    CORLAB_RESULT_MEMBER(e_energy, "-", "CoR from the sphere's rebound kinetic energy", kBoth),
    CORLAB_RESULT_MEMBER(e_impacts,
                         "-",
                         "e of each impact that rebounded (impact.repeats; the first is e)",
                         kSummary),
    CORLAB_RESULT_MEMBER(
        e_last, "-", "e of the last impact (= e unless impact.repeats > 1)", kBoth),
    CORLAB_RESULT_MEMBER(F_max, "N", "largest contact force", kBoth),
    CORLAB_RESULT_MEMBER(delta_max, "m", "largest indentation", kBoth),
    CORLAB_RESULT_MEMBER(t_contact, "s", "duration of contact", kBoth),
    CORLAB_RESULT_MEMBER(crater_depth, "m", "residual surface depth on the axis", kBoth),
    CORLAB_RESULT_MEMBER(plastic_strain_max, "-", "largest plastic strain", kBoth),
    CORLAB_RESULT_MEMBER(energy_initial, "J", "sphere kinetic energy at impact", kBoth),
    CORLAB_RESULT_MEMBER(
        energy_sphere_loss, "J", "initial - rebound KE (of the relative motion)", kBoth),
    CORLAB_RESULT_MEMBER(energy_dissipated_plastic, "J", "plastic work", kBoth),
    CORLAB_RESULT_MEMBER(energy_hourglass, "J", "hourglass energy at the end", kBoth),
    CORLAB_RESULT_MEMBER(energy_viscous, "J", "bulk-viscosity dissipation", kSummary),
    CORLAB_RESULT_MEMBER(energy_balance_error, "-", "max |balance| / initial", kBoth),
    CORLAB_RESULT_MEMBER(hysteresis_area, "J", "closed integral of F d(delta)", kBoth),
    CORLAB_RESULT_MEMBER(penetration_max, "m", "largest penalty penetration", kSummary),
    CORLAB_RESULT_MEMBER(separated, "-", "the sphere left before t_max", kSummary),
    CORLAB_RESULT_MEMBER(elements, "-", "elements of the mesh", kBoth),
    CORLAB_RESULT_MEMBER(nodes, "-", "nodes of the mesh", kSummary),
    CORLAB_RESULT_MEMBER(steps, "-", "time steps taken", kBoth),
    CORLAB_RESULT_MEMBER(
        element_updates, "-", "element updates done (subcycling: < elements x steps)", kSummary),
    CORLAB_RESULT_MEMBER(h_contact, "m", "element size at the contact", kSummary),
    CORLAB_RESULT_MEMBER(
        sphere_velocity_final, "m/s", "sphere c.o.m. velocity at the end, + up", kSummary),
    CORLAB_RESULT_MEMBER(target_velocity_final,
                         "m/s",
                         "target c.o.m. velocity at the end, + up (a flat: 0)",
                         kSummary),
    CORLAB_RESULT_MEMBER(time_step, "s", "initial stable time step", kSummary),
    CORLAB_RESULT_MEMBER(end_time, "s", "simulated time at the end", kSummary),
    ResultField{"wall_s", "s", "wall-clock time of the run", FieldKind::real, &wall_time, kBoth,
                true},
    CORLAB_MACHINE_MEMBER(element_steps_per_s, "1/s", "throughput", kBoth),
    CORLAB_RESULT_MEMBER(
        e_error,
        "-",
        "discretisation-error bar of e: e +/- e_error (scatter estimator, error_bar.hpp)",
        kBoth),
    CORLAB_RESULT_MEMBER(
        e_coarse, "-", "e on the mesh twice as coarse (error-bar companion)", kBoth),
    CORLAB_RESULT_MEMBER(suspect, "-", "why the run is suspect (empty: it is not)", kBoth),
    CORLAB_RESULT_MEMBER(status, "-", "how the run ended (run_status.hpp)", kSummary),
    CORLAB_RESULT_MEMBER(status_detail, "-", "one line on a run that did not rebound", kSummary),
    CORLAB_RESULT_MEMBER(
        substrate_von_mises_max, "Pa", "largest substrate von Mises stress at the end", kSummary),
    CORLAB_RESULT_MEMBER(mass_scaling, "-", "base step / the physical one (1 = none)", kBoth),
    CORLAB_RESULT_MEMBER(
        added_mass_fraction, "-", "mass added by mass scaling / sphere mass", kBoth),
    CORLAB_RESULT_MEMBER(in_run_added_mass_fraction,
                         "-",
                         "mass added by in-run mass scaling / sphere mass",
                         kSummary),
    CORLAB_RESULT_MEMBER(
        in_run_scaled_elements, "-", "substrate elements in-run mass scaling scaled", kSummary),
    CORLAB_RESULT_MEMBER(in_run_steps_saved,
                         "-",
                         "steps in-run mass scaling saved (estimate along the run)",
                         kSummary),
    CORLAB_RESULT_MEMBER(energy_mass_scaling,
                         "J",
                         "kinetic energy in-run mass scaling took out (momentum kept)",
                         kSummary),
    CORLAB_MACHINE_MEMBER(
        simd, "-", "instruction set of the solver's hot loops (CORLAB_SIMD)", kSummary),
    ResultField{"corlab_build", "-", "corlab version and git commit of the run (provenance)",
                FieldKind::text,
                [](const FieldInput&) -> FieldValue { return std::string(build_id()); }, kBoth,
                true},
    CORLAB_RESULT_MEMBER(e_error_reason,
                         "-",
                         "why an error estimate asked for has no e_error (empty: it has)",
                         kBoth),
    CORLAB_RESULT_MEMBER(
        e_n, "-", "normal restitution of the c.o.m. (= e for a normal impact)", kBoth),
    CORLAB_RESULT_MEMBER(
        e_t, "-", "tangential c.o.m. velocity ratio v_x'/v_x (3-D model, oblique)", kBoth),
    CORLAB_RESULT_MEMBER(omega, "rad/s", "rebound spin about the symmetry plane's normal", kBoth),
    CORLAB_RESULT_MEMBER(rebound_angle, "deg", "rebound angle from the normal", kBoth),
    CORLAB_RESULT_MEMBER(energy_friction, "J", "frictional dissipation (3-D model)", kBoth),
    CORLAB_RESULT_MEMBER(energy_absorbed,
                         "J",
                         "energy the absorbing far boundary took out (substrate.boundary = "
                         "absorbing): elastic waves radiated into the half-space",
                         kBoth),
    CORLAB_RESULT_MEMBER(
        e_t_error, "-", "discretisation-error bar of e_t (as e_error, same companions)", kBoth),
    CORLAB_RESULT_MEMBER(
        omega_error, "rad/s", "discretisation-error bar of omega (as e_error)", kBoth),
    CORLAB_RESULT_MEMBER(mesh_choice,
                         "-",
                         "who chose h_contact: keys (mesh.h_min, mesh.contact_elements) or model "
                         "(the 3-D default, neither key set)",
                         kSummary),
    CORLAB_RESULT_MEMBER(
        mesh_reason, "-", "the rule behind h_contact, a/h and the default's basis", kSummary),
    derived("E_star",
            "Pa",
            "effective modulus (Ma et al. 2023 eq. 3)",
            [](const FieldInput& in) -> FieldValue { return e_star(in); }),
    derived("k1", "-", "E* / (rho v^2) (Ma et al. 2023 eq. 5; two spheres: rho*)", &k1_of),
    derived("k2", "-", "sigma_y / E* (Ma et al. 2023 eq. 6; nan if that body is elastic)", &k2_of),
    derived("sphere_rho",
            "kg/m^3",
            "sphere density",
            [](const FieldInput& in) -> FieldValue { return in.config->sphere.material.density; }),
    derived("sigma_y",
            "Pa",
            "substrate yield stress; on the rigid flat the sphere's (nan if that body is elastic)",
            &substrate_yield),
    derived("velocity",
            "m/s",
            "impact velocity",
            [](const FieldInput& in) -> FieldValue { return in.config->impact.velocity; }),
};

#undef CORLAB_RESULT_MEMBER
#undef CORLAB_MACHINE_MEMBER

}  // namespace

std::span<const ResultField> result_fields() { return kFields; }

const ResultField* find_result_field(std::string_view name) {
  for (const auto& f : kFields) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

std::string_view to_string(FieldKind kind) {
  switch (kind) {
    case FieldKind::real:
      return "real";
    case FieldKind::integer:
      return "integer";
    case FieldKind::boolean:
      return "boolean";
    case FieldKind::text:
      return "text";
    case FieldKind::real_list:
      return "real_list";
  }
  return "text";
}

std::string field_text(const FieldValue& value) {
  struct Text {
    std::string operator()(std::monostate) const { return {}; }
    std::string operator()(double v) const {
      if (std::isnan(v)) return {};  // no value here (see the header); JSON writes null
      if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
      return fmt::format("{}", v);
    }
    std::string operator()(long long v) const { return fmt::format("{}", v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return v; }
    std::string operator()(const std::vector<double>& v) const {
      std::string out;
      for (const double x : v) {
        if (!out.empty()) out += ';';  // (not "literal" + string: GCC 12's -Wrestrict)
        out += (*this)(x);
      }
      return out;
    }
  };
  return std::visit(Text{}, value);
}

}  // namespace corlab::fem
