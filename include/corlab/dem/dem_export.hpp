#pragma once
/// @file dem_export.hpp
/// Calibration of every particle-type pair (and each type against a flat wall) to a target
/// restitution, and the input fragments for LAMMPS, LIGGGHTS and YADE plus e(v)/chi tables.
/// Calibration (physics) and text (I/O) are separate: calibrate_pairs() then write_*().

#include <optional>
#include <string>
#include <vector>

#include "corlab/dem/calibration.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::dem {

/// One DEM particle type (LAMMPS/LIGGGHTS type id = index + 1).
struct ParticleType {
  Material material;    ///< elastic constants and density (yield stress for e(v) models)
  double radius = 0.0;  ///< [m]
};

/// What the user asks for.
struct ExportSpec {
  std::vector<ParticleType> types;    ///< at least one
  std::optional<Material> wall;       ///< flat wall material (rigid mass); empty = no wall
  std::optional<double> restitution;  ///< constant target e in (0, 1); else e(v) below
  std::string model;                  ///< registered CoR model name for e(v) (e.g. thornton1997)
  std::optional<RestitutionCurve> table;  ///< e(v) table (FE results) instead of a model
  std::string table_source;               ///< description of the table (file name)
  double v_min = 0.1;                     ///< lower end of the velocity range [m/s]
  double v_max = 10.0;                    ///< upper end [m/s]
  int fit_points = 9;                     ///< speeds of the e(v) fits (log-uniform)
  bool wall_only = false;                 ///< only type-wall contacts (no particle pairs)
};

/// The calibrated contact of one pair (type_j = 0 means the wall).
struct PairCalibration {
  int type_i = 1;                  ///< particle type id (1-based)
  int type_j = 1;                  ///< particle type id, 0 = wall
  double effective_modulus = 0.0;  ///< E* [Pa]
  double effective_radius = 0.0;   ///< R* [m]
  double effective_mass = 0.0;     ///< m* [kg] (wall: sphere mass)
  double hertz_stiffness = 0.0;    ///< K = 4/3 E* sqrt(R*) [N/m^1.5]
  std::string target;              ///< "constant e = 0.5" or "thornton1997 (sphere 2 on 1)"
  RestitutionCurve curve;          ///< target e(v) [m/s] -> [-]
  // constant e
  double chi = 0.0;                 ///< exact hysteresis chi for the constant e [-]
  double tsuji_alpha = 0.0;         ///< exact TsujiLaw alpha [-]
  double lammps_tsuji_input = 0.0;  ///< e_in for LAMMPS damping tsuji [-]
  // e(v)
  std::optional<CurveFit> viscoelastic;  ///< fitted c [N s/m^1.5] of ViscoelasticHertzLaw
  std::optional<CurveFit> thornton;      ///< fitted p_y [Pa] of ThorntonNingLaw
  std::optional<CurveFit> liggghts;      ///< fitted p_y [Pa] of LiggghtsThorntonNingLaw
  double particle_radius = 0.0;          ///< r_i of type_i [m] (LIGGGHTS yield ratio)
  /// LAMMPS damping viscoelastic coefficient eta_n = c/(m* sqrt(R*)) [1/(m s)].
  double lammps_viscoelastic_eta() const;
  /// LIGGGHTS coefficientYieldRatio = pi R* p_y / (2 E* r_i) [-].
  double liggghts_yield_ratio() const;
};

/// Validates the spec (InputError naming the field) and calibrates every pair i <= j and each
/// type against the wall.
std::vector<PairCalibration> calibrate_pairs(const ExportSpec& spec);

/// LAMMPS (29Sep2021+) fragment: pair_style granular with per-type-pair pair_coeff and one
/// fix wall/gran per type (zplane at z = 0), pre-compensated where LAMMPS's mapping is not exact.
std::string write_lammps(const ExportSpec& spec, const std::vector<PairCalibration>& pairs);
/// LIGGGHTS 3.8 fragment (constant e: model hertz, exact; e(v): model thornton_ning).
std::string write_liggghts(const ExportSpec& spec, const std::vector<PairCalibration>& pairs);
/// YADE fragment (Python): materials and interaction physics.
std::string write_yade(const ExportSpec& spec, const std::vector<PairCalibration>& pairs);
/// e(v) and chi(v) table, CSV: pair,v,e,chi,e_viscoelastic (linear interpolation in v).
std::string write_table_csv(const ExportSpec& spec,
                            const std::vector<PairCalibration>& pairs,
                            int points = 64);
/// Everything (calibrations, fits with their errors, tables) as JSON.
std::string write_json(const ExportSpec& spec,
                       const std::vector<PairCalibration>& pairs,
                       int points = 64);

}  // namespace corlab::dem
