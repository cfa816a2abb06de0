// corlab2026p where it is accurate, the FE elsewhere (auto_restitution.hpp).
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/dataset/auto_restitution.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "corlab/dataset/impact_box.hpp"
#include "corlab/restitution/registry.hpp"

namespace corlab::dataset {
namespace {

constexpr std::string_view kModel = "corlab2026p";

/// "name = value outside [min, max]" when value is outside `r` (a relative slack of 1e-9 for
/// values that went through text), else empty.
std::optional<std::string> outside(std::string_view name, double value, const Range& r) {
  constexpr double kSlack = 1e-9;
  if (value >= r.min * (1 - kSlack) && value <= r.max * (1 + kSlack)) return std::nullopt;
  return fmt::format("{} = {:.4g} outside [{:g}, {:g}]", name, value, r.min, r.max);
}

}  // namespace

ModelRangeCheck corlab2026p_accurate(const fem::ImpactConfig& config) {
  if (fem::rigid_target(config)) return {false, "a rigid flat (not in corlab2026p's datasets)"};
  if (!config.substrate.material.yield_stress) {
    return {false, "the substrate does not yield (corlab2026p's datasets: a yielding substrate)"};
  }
  const ImpactBox box = pair_box();
  const DimensionlessInputs in = dimensionless_inputs(config);
  const double v = config.impact.velocity;
  if (!(in.velocity_ratio >= box.velocity_ratio_min)) {
    return {false, fmt::format("v/v_y = {:.4g} below {:g} (near or below first yield)",
                               in.velocity_ratio, box.velocity_ratio_min)};
  }
  if (in.velocity_ratio > kCorlab2026pAccurateVelocityRatio) {
    return {false, fmt::format("v/v_y = {:.4g} above {:g} (past the near-yield regime, where "
                               "corlab2026p's dataset residuals exceed 2 %)",
                               in.velocity_ratio, kCorlab2026pAccurateVelocityRatio)};
  }
  if (v > box.velocity_max) {
    return {false, fmt::format("v = {:g} m/s above {:g} m/s", v, box.velocity_max)};
  }
  const double damage_max = *restitution::model_info(kModel).accurate_damage_number;
  if (!(in.damage_number <= damage_max)) {
    return {false, fmt::format("damage number rho* v^2/sigma_y = {:.3g} > {:g}", in.damage_number,
                               damage_max)};
  }
  const Range radius{0.0, 0.0};
  for (auto why :
       {outside("sigma_y/E*", in.k2, box.k2),
        outside("E_sphere/E_substrate", in.modulus_ratio, box.modulus_ratio),
        outside("rho_sphere/rho_substrate", in.density_ratio, box.density_ratio),
        outside("nu_sphere", in.nu_sphere, box.nu),
        outside("nu_substrate", in.nu_substrate, box.nu),
        outside("H/E of the sphere", in.hardening_ratio_sphere, box.hardening_ratio),
        outside("H/E of the substrate", in.hardening_ratio_substrate, box.hardening_ratio),
        std::isinf(in.sphere_yield_ratio) ? std::nullopt
                                          : outside("sigma_y,sphere/sigma_y,substrate",
                                                    in.sphere_yield_ratio, box.sphere_yield_ratio),
        in.radius_ratio == 0.0 ? outside("R1/R2", 0.0, radius)
                               : outside("R1/R2", in.radius_ratio, box.radius_ratio)}) {
    if (why) return {false, *why};
  }
  return {true, ""};
}

std::vector<study::FePoint> auto_curve(const study::FePair& pair,
                                       const std::vector<double>& velocities,
                                       const study::FeCurveOptions& options) {
  std::vector<study::FePoint> points(velocities.size());
  std::vector<double> fe_speeds;
  std::vector<std::size_t> fe_rows;
  std::vector<std::string> why(velocities.size());
  restitution::ModelOptions model_options;
  model_options.radius_ratio = pair.radius_ratio;
  std::optional<restitution::Model> model;
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    const ModelRangeCheck check = corlab2026p_accurate(study::fe_curve_config(pair, velocities[i]));
    if (!check.accurate) {
      why[i] = fmt::format("{} not accurate: {}", kModel, check.why);
      fe_speeds.push_back(velocities[i]);
      fe_rows.push_back(i);
      continue;
    }
    if (!model) model = restitution::make_model(kModel, pair.sphere, pair.substrate, model_options);
    study::FePoint& p = points[i];
    constexpr double kP = kCorlab2026pAccurateInterval95;
    p.velocity = velocities[i];
    p.e = model->cor(velocities[i]);
    p.e_error = p.e * kP / (1.0 - kP);
    p.status = "model";
    p.answered_by = kModel;
    p.detail = fmt::format("inside {}'s accurate range: 95 % prediction interval +-{:.1f} %",
                           kModel, 100 * kP);
  }
  if (fe_speeds.empty()) return points;
  const std::vector<study::FePoint> fe = study::fe_curve(pair, fe_speeds, options);
  for (std::size_t j = 0; j < fe_rows.size(); ++j) {
    study::FePoint& p = points[fe_rows[j]];
    p = fe[j];
    p.detail = why[fe_rows[j]] + (p.detail.empty() ? "" : "; " + p.detail);
  }
  return points;
}

}  // namespace corlab::dataset
