// The table of result fields (result_fields.hpp): one entry per field.
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
  if constexpr (std::is_same_v<T, bool>) {
    return v;
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

double e_star(const FieldInput& in) {
  return effective_modulus(in.config->sphere.material, in.config->substrate.material);
}

FieldValue substrate_yield(const FieldInput& in) {
  return in.config->substrate.material.yield_stress.value_or(kNan);
}

FieldValue k2_of(const FieldInput& in) {
  const auto& sy = in.config->substrate.material.yield_stress;
  return sy ? k2(*sy, e_star(in)) : kNan;
}

FieldValue k1_of(const FieldInput& in) {
  return k1(e_star(in), in.config->sphere.material.density, in.config->impact.velocity);
}

using R = ImpactResult;

// The order is the results.csv column order (existing files are resumed only with the same
// header): add a CSV field at the end of the result members, before the derived inputs.
const std::array kFields{
    member<&R::e>("e", "-", "CoR from momentum: rebound / impact c.o.m. velocity", kBoth),
    member<&R::e_energy>("e_energy", "-", "CoR from the sphere's rebound kinetic energy", kBoth),
    member<&R::force_max>("F_max", "N", "largest contact force", kBoth),
    member<&R::indentation_max>("delta_max", "m", "largest indentation", kBoth),
    member<&R::contact_time>("t_contact", "s", "duration of contact", kBoth),
    member<&R::crater_depth>("crater_depth", "m", "residual surface depth on the axis", kBoth),
    member<&R::plastic_strain_max>("plastic_strain_max", "-", "largest plastic strain", kBoth),
    member<&R::energy_initial>("energy_initial", "J", "sphere kinetic energy at impact", kBoth),
    member<&R::energy_sphere_loss>("energy_sphere_loss", "J", "initial - rebound KE", kBoth),
    member<&R::energy_dissipated_plastic>("energy_dissipated_plastic", "J", "plastic work", kBoth),
    member<&R::energy_hourglass>("energy_hourglass", "J", "hourglass energy at the end", kBoth),
    member<&R::energy_viscous>("energy_viscous", "J", "bulk-viscosity dissipation", kSummary),
    member<&R::energy_balance_error>("energy_balance_error", "-", "max |balance| / initial", kBoth),
    member<&R::hysteresis_area>("hysteresis_area", "J", "closed integral of F d(delta)", kBoth),
    member<&R::penetration_max>("penetration_max", "m", "largest penalty penetration", kSummary),
    member<&R::separated>("separated", "-", "the sphere left before t_max", kSummary),
    member<&R::elements>("elements", "-", "elements of the mesh", kBoth),
    member<&R::nodes>("nodes", "-", "nodes of the mesh", kSummary),
    member<&R::steps>("steps", "-", "time steps taken", kBoth),
    member<&R::element_updates>(
        "element_updates", "-", "element updates done (subcycling: < elements x steps)", kSummary),
    member<&R::h_contact>("h_contact", "m", "element size at the contact", kSummary),
    member<&R::time_step>("time_step", "s", "initial stable time step", kSummary),
    member<&R::end_time>("end_time", "s", "simulated time at the end", kSummary),
    ResultField{"wall_s", "s", "wall-clock time of the run", FieldKind::real, &wall_time, kBoth,
                true},
    ResultField{"element_steps_per_s", "1/s", "throughput", FieldKind::real,
                &result_member<&R::element_steps_per_s>, kBoth, true},
    member<&R::e_error>("e_error", "-", "discretisation-error estimate of e (two-grid GCI)", kBoth),
    member<&R::e_coarse>(
        "e_coarse", "-", "e on the mesh twice as coarse (error-bar companion)", kBoth),
    member<&R::suspect>("suspect", "-", "why the run is suspect (empty: it is not)", kBoth),
    member<&R::status>("status", "-", "how the run ended (run_status.hpp)", kSummary),
    member<&R::status_detail>(
        "status_detail", "-", "one line on a run that did not rebound", kSummary),
    member<&R::substrate_von_mises_max>(
        "substrate_von_mises_max", "Pa", "largest substrate von Mises stress at the end", kSummary),
    member<&R::mass_scaling>("mass_scaling", "-", "base step / the physical one (1 = none)", kBoth),
    member<&R::added_mass_fraction>(
        "added_mass_fraction", "-", "mass added by mass scaling / sphere mass", kBoth),
    ResultField{"simd", "-", "instruction set of the solver's hot loops (CORLAB_SIMD)",
                FieldKind::text, &result_member<&R::simd>, kSummary, true},
    ResultField{"corlab_build", "-", "corlab version and git commit of the run (provenance)",
                FieldKind::text,
                [](const FieldInput&) -> FieldValue { return std::string(build_id()); }, kBoth,
                true},
    derived("E_star",
            "Pa",
            "effective modulus (Ma et al. 2023 eq. 3)",
            [](const FieldInput& in) -> FieldValue { return e_star(in); }),
    derived("k1", "-", "E* / (rho v^2) (Ma et al. 2023 eq. 5)", &k1_of),
    derived("k2", "-", "sigma_y / E* (Ma et al. 2023 eq. 6; nan if elastic)", &k2_of),
    derived("sphere_rho",
            "kg/m^3",
            "sphere density",
            [](const FieldInput& in) -> FieldValue { return in.config->sphere.material.density; }),
    derived("sigma_y", "Pa", "substrate yield stress (nan if elastic)", &substrate_yield),
    derived("velocity",
            "m/s",
            "impact velocity",
            [](const FieldInput& in) -> FieldValue { return in.config->impact.velocity; }),
};

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
  }
  return "text";
}

std::string field_text(const FieldValue& value) {
  struct Text {
    std::string operator()(std::monostate) const { return {}; }
    std::string operator()(double v) const {
      if (std::isnan(v)) return "nan";
      if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
      return fmt::format("{}", v);
    }
    std::string operator()(long long v) const { return fmt::format("{}", v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return v; }
  };
  return std::visit(Text{}, value);
}

}  // namespace corlab::fem
