// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file registry.hpp
/// Runtime registry of the analytic CoR models: lookup by name (CLI, Python, studies), list with
/// metadata, and checked scalar / vectorised evaluation.
///
///   auto model = corlab::restitution::make_model("ma2023", sphere, substrate);
///   double e = model.cor(1.0);                       // [m/s] -> [-]
///   std::vector<double> es = model.cor(velocities);  // one allocation (the output)

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "corlab/materials/material.hpp"
#include "corlab/restitution/corlab2026.hpp"
#include "corlab/restitution/jackson_green2010.hpp"
#include "corlab/restitution/johnson1985.hpp"
#include "corlab/restitution/ma2023.hpp"
#include "corlab/restitution/model_info.hpp"
#include "corlab/restitution/thornton1997.hpp"
#include "corlab/restitution/wu2003.hpp"

namespace corlab::restitution {

/// Accepted sphere radii of ModelOptions::radius [m]: e does not depend on R, but the energy
/// models' intermediate values leave double range beyond these.
inline constexpr double kMinModelRadius = 1e-9;
inline constexpr double kMaxModelRadius = 1e3;

/// Options that apply across models.
struct ModelOptions {
  std::optional<bool> clamp;  ///< clamp e to [0, 1]; empty = the model's default
  double radius = 1.0;        ///< sphere radius R [m] (energy models only; e is R-independent)
  /// R1/R2 [-] of a sphere hitting a free second sphere of the substrate's material at rest;
  /// 0 (the default) is a flat; above 1 the sphere is the larger body (accepted: the same impact
  /// as the smaller body hitting the larger; corlab2026p warns beyond its fitted R1/R2 <= 1,
  /// validity.hpp). A sphere-on-flat model sees the pair as a sphere of density
  /// rho* = 3 m*/(4 pi R*^3) on a flat (pair_effective_density, material.hpp), the same Hertz
  /// impact; corlab2026p reads the pair whole (corlab2026p.hpp).
  double radius_ratio = 0.0;
};

/// A model bound to a material pair. Cheap to copy.
class Model {
 public:
  using Kernel = std::variant<Ma2023,
                              Thornton1997,
                              JacksonGreen2010,
                              JacksonGreen2010Fit,
                              Wu2003,
                              Johnson1985,
                              Corlab2026>;

  Model(const ModelInfo& info, Kernel kernel, bool clamped);

  /// Metadata (name, citation, equation, validity, status).
  const ModelInfo& info() const { return *info_; }
  /// Whether this instance clamps e to [0, 1].
  bool clamped() const { return clamped_; }
  /// The model's own yield velocity [m/s] (e = 1 below it).
  double yield_velocity() const;
  /// CoR at v [m/s]; throws InputError naming "velocity" unless v is finite and > 0.
  double cor(double velocity) const;
  /// Vectorised CoR: e[i] = cor(v[i]); checks every velocity first (InputError names the index)
  /// and that the spans have equal length. No allocation.
  void cor(std::span<const double> velocities, std::span<double> out) const;
  /// Vectorised CoR returning a new vector.
  std::vector<double> cor(std::span<const double> velocities) const;
  /// The underlying kernel (for tests and advanced use).
  const Kernel& kernel() const { return kernel_; }

 private:
  const ModelInfo* info_;
  Kernel kernel_;
  bool clamped_;
};

/// Every registered model with its metadata, in a fixed order.
const std::vector<ModelInfo>& model_catalog();

/// Registered names in catalog order.
std::vector<std::string> model_names();

/// Metadata by name; throws InputError "invalid model = 'foo': must be one of [...]".
const ModelInfo& model_info(std::string_view name);

/// Binds model `name` to a sphere and a substrate (validated; the substrate needs a yield
/// stress), a flat or, for options.radius_ratio > 0, a free second sphere. Throws InputError for
/// an unknown name or bad materials/options.
Model make_model(std::string_view name,
                 const Material& sphere,
                 const Material& substrate,
                 const ModelOptions& options = {});

}  // namespace corlab::restitution
