// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file model_info.hpp
/// Descriptive metadata of an analytic coefficient-of-restitution (CoR) model: citation,
/// equation, validity range and verification status.

#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace corlab::restitution {

/// How far the implemented formula has been checked against public sources.
/// Mapping of the statuses of docs/reference/models.md:
///  - the seed paper's own text (Ma et al. 2023)            -> kVerifiedPaper
///  - "confirmed (two sources)", "confirmed (one source + derivation)"
///                                                         -> kVerifiedSecondSource
///  - "one source" (not cross-checked), "unconfirmed"      -> kUnverified
/// The original wording is kept in ModelInfo::status_note.
enum class Status {
  kVerifiedPaper,         ///< formula read in the seed paper's text (and re-derived)
  kVerifiedSecondSource,  ///< confirmed by a second public source or an independent derivation
  /// corlab's own model: fitted to and scored on held-out runs of corlab's FE dataset
  kVerifiedDataset,
  kUnverified,  ///< constants or form not confirmed; do not treat as exact
};

/// "verified-paper", "verified-second-source", "verified-dataset" or "unverified".
std::string_view to_string(Status status);

/// Calibration range of a model in the dimensionless groups of Ma et al. 2023:
/// k1 = E*/(rho v^2) [-] and k2 = sigma_y/E* [-]. Outside it the model extrapolates.
struct DimensionlessBox {
  double k1_min = 0.0;
  double k1_max = 0.0;
  double k2_min = 0.0;
  double k2_max = 0.0;
};

/// Metadata of one registered model (see registry.hpp).
struct ModelInfo {
  std::string name;                     ///< registry key, e.g. "ma2023"
  std::string title;                    ///< short human-readable name
  std::string citation;                 ///< author, year, journal, equation numbers
  std::string equation;                 ///< the formula in plain text
  std::string validity;                 ///< validity range / calibration range
  Status status = Status::kUnverified;  ///< verification status (see Status)
  std::string status_note;  ///< the reference's wording of the status and what is unconfirmed
  bool clamped_by_default = true;  ///< whether e is clamped to [0, 1] unless told otherwise
  /// Where the model was calibrated, when known numerically (`corlab predict` warns outside).
  std::optional<DimensionlessBox> calibrated = std::nullopt;
  /// Largest Johnson damage number rho v^2 / sigma_y,substrate [-] up to which the model's
  /// held-out errors were measured within 2 % RMS (`corlab predict` warns above); empty = none
  /// measured.
  std::optional<double> accurate_damage_number = std::nullopt;
  /// Largest radius ratio R1/R2 of the data the model was fitted to [-] (`corlab predict` warns
  /// above); empty = the model reads the pair only through rho* (exact for any R1/R2).
  std::optional<double> fitted_radius_ratio = std::nullopt;
};

/// The model's description as JSON: name, title, citation, equation, validity, status,
/// status_note, clamped_by_default, calibrated ({k1_min, k1_max, k2_min, k2_max} or null),
/// accurate_damage_number (or null). The one
/// serialisation of a ModelInfo: `corlab models --format json`, the explorer's catalog and
/// Python's `corlab.models()`.
nlohmann::json model_info_json(const ModelInfo& info);

}  // namespace corlab::restitution
