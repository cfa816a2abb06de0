// Yield-onset velocity by bisection on ln v with the impact solver.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/paper/yield_velocity.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "corlab/core/error.hpp"
#include "corlab/fem/solver/simulate.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::study {

double hertz_yield_onset_velocity(double sphere_rho, double E_star, double sigma_y) {
  // rho V^2 / Y = (4/5) pi^4 (0.8)^5 (Y/E*)^4 with p0 = 1.6 Y  (models.md section 5.1)
  const double k = 0.8 * std::pow(std::numbers::pi, 4) * std::pow(0.8, 5);
  return std::sqrt(k * std::pow(sigma_y, 5) / (sphere_rho * std::pow(E_star, 4)));
}

OnsetResult find_yield_onset(const fem::ImpactConfig& base,
                             const OnsetOptions& options,
                             const ImpactRunner& run,
                             const ProbeCache& cached,
                             const std::function<void(const OnsetProbe&)>& on_probe) {
  require_positive("onset.v_low", options.v_low, "[m/s]");
  require_positive("onset.v_high", options.v_high, "[m/s]");
  if (!(options.v_high > options.v_low)) {
    throw_invalid("onset.v_high", options.v_high, "> onset.v_low");
  }
  if (options.iterations < 0) {
    throw_invalid("onset.iterations", static_cast<double>(options.iterations), ">= 0");
  }
  require_non_negative("onset.threshold", options.threshold);

  OnsetResult out;
  auto probe = [&](double v) {
    if (cached) {
      if (auto hit = cached(v)) {
        hit->plastic = hit->plastic_strain_max > options.threshold;
        out.probes.push_back(*hit);
        return *hit;
      }
    }
    fem::ImpactConfig config = base;
    config.impact.velocity = v;
    const fem::ImpactResult r = run ? run(config) : fem::simulate(config);
    OnsetProbe p{v, r.plastic_strain_max, r.e, r.plastic_strain_max > options.threshold};
    out.probes.push_back(p);
    if (on_probe) on_probe(p);
    return p;
  };

  const OnsetProbe lo = probe(options.v_low);
  const OnsetProbe hi = probe(options.v_high);
  out.bracketed = !lo.plastic && hi.plastic;
  if (!out.bracketed) {
    out.v_elastic = lo.plastic ? std::numeric_limits<double>::quiet_NaN() : options.v_low;
    out.v_plastic = hi.plastic ? options.v_high : std::numeric_limits<double>::quiet_NaN();
    out.v_onset = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  double a = options.v_low;
  double b = options.v_high;
  for (int k = 0; k < options.iterations; ++k) {
    const double mid = std::sqrt(a * b);
    if (probe(mid).plastic) {
      b = mid;
    } else {
      a = mid;
    }
  }
  out.v_elastic = a;
  out.v_plastic = b;
  out.v_onset = std::sqrt(a * b);
  return out;
}

namespace {

/// Runs (or looks up) one loading-half probe of the scaled onset search.
class LoadingProbes {
 public:
  LoadingProbes(const fem::ImpactConfig& base,
                const ScaledOnsetOptions& options,
                const ControlledRunner& run,
                const KindProbeCache& cached,
                const std::function<void(const OnsetProbe&)>& on_probe,
                OnsetResult& out)
      : base_(base),
        options_(options),
        run_(run),
        cached_(cached),
        on_probe_(on_probe),
        out_(out) {}

  OnsetProbe probe(bool elastic_reference, double v) {
    if (cached_) {
      if (auto hit = cached_(elastic_reference, v)) {
        hit->plastic = !elastic_reference && hit->plastic_strain_max > options_.threshold;
        hit->elastic_reference = elastic_reference;
        out_.probes.push_back(*hit);
        return *hit;
      }
    }
    fem::ImpactConfig config = base_;
    config.impact.velocity = v;
    if (elastic_reference) config.substrate.material.yield_stress = std::nullopt;
    fem::SimulationControl control;
    control.stop_at_max_compression = true;
    const fem::ImpactResult r = run_ ? run_(config, control) : fem::simulate(config, control);
    if (r.status != fem::RunStatus::kMaxCompression) {
      throw std::runtime_error(fmt::format("yield-onset probe at v = {} m/s ended as {} ({})", v,
                                           fem::to_string(r.status), r.status_detail));
    }
    OnsetProbe p;
    p.velocity = v;
    p.plastic_strain_max = r.plastic_strain_max;
    p.e = r.e;
    p.plastic = !elastic_reference && r.plastic_strain_max > options_.threshold;
    p.elastic_reference = elastic_reference;
    p.von_mises_max = r.substrate_von_mises_max;
    out_.probes.push_back(p);
    if (on_probe_) on_probe_(p);
    return p;
  }

 private:
  const fem::ImpactConfig& base_;
  const ScaledOnsetOptions& options_;
  const ControlledRunner& run_;
  const KindProbeCache& cached_;
  const std::function<void(const OnsetProbe&)>& on_probe_;
  OnsetResult& out_;
};

void check_options(const ScaledOnsetOptions& o) {
  require_open_range("onset.bracket", o.bracket, 0.0, 1.0);
  if (o.max_widen < 0) throw_invalid("onset.max_widen", static_cast<double>(o.max_widen), ">= 0");
  require_positive("onset.reference_tolerance", o.reference_tolerance);
  require_non_negative("onset.threshold", o.threshold);
}

}  // namespace

OnsetResult find_yield_onset_scaled(const fem::ImpactConfig& base,
                                    const ScaledOnsetOptions& options,
                                    const ControlledRunner& run,
                                    const KindProbeCache& cached,
                                    const std::function<void(const OnsetProbe&)>& on_probe) {
  check_options(options);
  const auto& substrate = base.substrate.material;
  if (!substrate.yield_stress) {
    throw_invalid("substrate.sigma_y", "none", "a yield stress (the onset of what?)");
  }
  const double sigma_y = *substrate.yield_stress;
  OnsetResult out;
  LoadingProbes probes(base, options, run, cached, on_probe, out);

  // Elastic reference: v_scaled = v_ref (sigma_y / s_ref)^(5/2), s_ref ~ p0 ~ v^(2/5).
  double v_ref = hertz_yield_onset_velocity(
      base.sphere.material.density, effective_modulus(base.sphere.material, substrate), sigma_y);
  for (int k = 0; k < 2; ++k) {
    const OnsetProbe ref = probes.probe(true, v_ref);
    out.v_scaled = v_ref * std::pow(sigma_y / ref.von_mises_max, 2.5);
    if (std::abs(std::log(out.v_scaled / v_ref)) < std::log1p(options.reference_tolerance)) break;
    v_ref = out.v_scaled;
  }

  // Confirming bracket, moved by (1 + b)^2 until it holds the onset.
  const double step = 1.0 + options.bracket;
  double lo = out.v_scaled / step;
  double hi = out.v_scaled * step;
  bool lo_plastic = probes.probe(false, lo).plastic;
  bool hi_plastic = probes.probe(false, hi).plastic;
  for (int k = 0; k < options.max_widen && (lo_plastic || !hi_plastic); ++k) {
    if (lo_plastic) {
      hi = lo;
      lo /= step * step;
      lo_plastic = probes.probe(false, lo).plastic;
      hi_plastic = true;
    } else {
      lo = hi;
      hi *= step * step;
      hi_plastic = probes.probe(false, hi).plastic;
      lo_plastic = false;
    }
  }
  out.bracketed = !lo_plastic && hi_plastic;
  out.v_elastic = lo_plastic ? std::numeric_limits<double>::quiet_NaN() : lo;
  out.v_plastic = hi_plastic ? hi : std::numeric_limits<double>::quiet_NaN();
  out.v_onset = out.bracketed ? std::sqrt(lo * hi) : std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace corlab::study
