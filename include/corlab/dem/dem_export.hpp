// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file dem_export.hpp
/// Calibration of every particle-type pair (and each type against a flat wall) to a target
/// restitution, and the input fragments for LAMMPS, LIGGGHTS and YADE plus e(v)/chi tables.
/// Calibration (physics) and text (I/O) are separate: calibrate_pairs() then write_*().

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "corlab/dem/calibration.hpp"
#include "corlab/dem/dem_walls.hpp"
#include "corlab/dem/time_step.hpp"
#include "corlab/materials/material.hpp"

namespace corlab::dem {

/// One DEM particle type (LAMMPS/LIGGGHTS type id = index + 1).
struct ParticleType {
  Material material;    ///< elastic constants and density (yield stress for e(v) models)
  double radius = 0.0;  ///< [m]
  std::string label;    ///< name in the exports; empty: the material's name (inline: type<id>)
};

/// A material with the label the exports give it: "LABEL=SPEC" (e.g. "glass=E=63e9,nu=0.22,
/// rho=2500") or a plain material spec (label: the database name; empty for an inline spec).
struct LabelledMaterial {
  std::string label;
  Material material;
  bool label_given = false;  ///< "LABEL=SPEC": the user's label (else the database name's)
};
/// Parses "LABEL=SPEC" or "SPEC" (materials/material_database.hpp); InputError naming `field`.
LabelledMaterial parse_labelled_material(std::string_view text, std::string_view field);

/// A constant e for one pair that replaces the export's target there (e.g. an elastic
/// particle-particle pair that no e(v) model covers).
struct PairRestitution {
  std::string first;         ///< type label or 1-based type id
  std::string second;        ///< type label, type id, or "wall"
  double restitution = 1.0;  ///< e in (0, 1] (1: elastic)
};
/// Parses "A/B=E" (labels or type ids, "wall" for the wall); InputError naming `pair`.
PairRestitution parse_pair_restitution(std::string_view text);

/// An e(v) table for one pair that replaces the export's target there: an FE run is of one pair
/// of materials and radii, so one table for every pair (`table` below) fits an export of one type.
struct PairTable {
  std::string first;       ///< type label or 1-based type id
  std::string second;      ///< type label, type id, or "wall"
  std::string source;      ///< the table's file name (parse_pair_table), in the exports
  RestitutionCurve curve;  ///< e(v) [m/s] -> [-] (tabulated_curve)
};
/// A number of one pair (--friction A/B=MU): labels or type ids, or a wall's label ("wall" when
/// there is one wall material).
struct PairValue {
  std::string first;
  std::string second;
  double value = 0.0;
};
/// Parses "A/B=X" with X a finite number >= 0; InputError naming `field` (e.g. friction).
PairValue parse_pair_value(std::string_view text, std::string_view field);

/// Parses "A/B=FILE" into first, second and source (the curve is the caller's to read);
/// InputError naming `pair-table`.
PairTable parse_pair_table(std::string_view text);

/// The two bodies of one pair as `corlab predict` takes them: the particle of type_i is the
/// sphere, the other body (type_j's particle, or the wall) the substrate.
struct PairBodies {
  Material sphere;
  Material substrate;
  double radius_ratio = 0.0;  ///< r_i / r_j; 0: the wall, a flat [-]
  std::string sphere_label;
  std::string substrate_label;
};
/// A pair's e(v) computed outside this library (corlab's FE solver:
/// dataset/dem_fe_targets.hpp): the target, its description in the exports, and one-line
/// warnings for the user (how far it can be trusted).
struct ExternalTarget {
  RestitutionCurve curve;  ///< e(v) [m/s] -> [-]
  std::string description;
  std::vector<std::string> warnings;
};
/// Computes a pair's ExternalTarget at the fit speeds [m/s] (the curve answers at any speed).
using PairTargetSource =
    std::function<ExternalTarget(const PairBodies& bodies, std::span<const double> speeds)>;
/// The model names that PairTargetSource answers ("fe", "auto"; not registered models).
bool is_external_model(std::string_view model);

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
  /// The wall's label as the user gave it (LABEL=MATERIAL); empty: its material's name, or "wall".
  std::string wall_label;
  std::vector<PairRestitution> pair_restitution;  ///< constant e of single pairs
  std::vector<PairTable> pair_tables;             ///< e(v) tables of single pairs
  /// Coulomb friction coefficient mu [-] of every pair (0: frictionless, the normal part only);
  /// above 0 each fragment adds Mindlin's tangential stiffness (tangential.hpp).
  double friction = 0.0;
  /// e(v) of every pair without its own target when `model` is "fe" or "auto"
  /// (is_external_model); set by the CLI and Python (the FE solver is not part of this library).
  PairTargetSource target_source;
  /// Coulomb mu [-] of single pairs (--friction A/B=MU), replacing `friction` there.
  std::vector<PairValue> pair_friction;
  /// Rolling resistance coefficient mu_r [-] of every pair (0: none): the largest rolling
  /// moment is mu_r R* F_n (each code's own keyword, dem_walls.hpp).
  double rolling = 0.0;
  /// Wall materials after the first (`wall`): material k of the walls is extra_walls[k - 1].
  std::vector<LabelledMaterial> extra_walls;
  /// The walls' geometry (each names its material); empty with a wall: the floor z = 0.
  std::vector<Wall> walls;
};

/// Most rows per pair of the e(v) tables (write_table_csv, write_json): each row of a fitted pair
/// integrates two impacts (the viscoelastic and thornton_ning columns), 1000 rows of two pairs
/// take about 1.5 s; the hooks interpolate 64.
inline constexpr int kMaxTablePoints = 10'000;
/// Requires `points` in [2, kMaxTablePoints] (InputError naming table-points).
void validate_table_points(int points);

/// The label of type `id` (1-based) and of the wall, as written in the exports.
std::string type_label(const ExportSpec& spec, int id);
std::string wall_label(const ExportSpec& spec);

/// The calibrated contact of one pair (type_j = 0 means the wall).
struct PairCalibration {
  int type_i = 1;                  ///< particle type id (1-based)
  int type_j = 1;                  ///< particle type id, 0 = wall
  double effective_modulus = 0.0;  ///< E* [Pa]
  double effective_radius = 0.0;   ///< R* [m]
  double effective_mass = 0.0;     ///< m* [kg] (wall: sphere mass)
  /// rho* = 3 m*/(4 pi R*^3) [kg/m^3]: the density of the sphere whose impact on a flat is this
  /// pair's (wall: the particle's; two identical spheres: 4 rho); a model's e(v) is taken at it.
  double effective_density = 0.0;
  double hertz_stiffness = 0.0;  ///< K = 4/3 E* sqrt(R*) [N/m^1.5]
  double shear_modulus = 0.0;    ///< Mindlin's G* [Pa]: k_t = 8 G* a (tangential.hpp)
  double friction = 0.0;  ///< Coulomb mu [-]: ExportSpec::friction (calibrate_pairs), or the pair's
                          ///< own --friction A/B=MU (calibrate_export)
  int wall = 0;           ///< type_j = 0: the wall material's index (ExportSpec::walls)
  std::string label;      ///< "glass-glass", "glass-copper" (type labels; wall last)
  std::string target;     ///< "constant e = 0.5" or "thornton1997 (sphere 2 on 1)"
  RestitutionCurve curve;          ///< target e(v) [m/s] -> [-]
  std::optional<double> constant;  ///< the constant target e (--restitution or a pair's own)
  double contact_time_fast = 0.0;  ///< Hertz contact time at v_max [s] (the shortest)
  double contact_time_slow = 0.0;  ///< Hertz contact time at v_min [s]
  // constant e
  double chi = 0.0;                 ///< exact hysteresis chi for the constant e [-]
  double tsuji_alpha = 0.0;         ///< exact TsujiLaw alpha [-]
  double lammps_tsuji_input = 0.0;  ///< e_in for LAMMPS damping tsuji [-]
  // e(v)
  std::optional<CurveFit> viscoelastic;   ///< fitted c [N s/m^1.5] of ViscoelasticHertzLaw
  std::optional<CurveFit> thornton;       ///< fitted p_y [Pa] of ThorntonNingLaw
  std::optional<CurveFit> liggghts;       ///< fitted p_y [Pa] of LiggghtsThorntonNingLaw
  std::optional<CurveFit> best_constant;  ///< minimax constant e of the e(v) (parameter = e)
  /// LIGGGHTS thornton_ning with the yield ratios written per type (a type shares one ratio
  /// among its pairs): its e at the fit speeds against the target (parameter = worst ratio).
  std::optional<CurveFit> liggghts_written;
  double particle_radius = 0.0;  ///< r_i of type_i [m] (LIGGGHTS yield ratio)
  /// One-line warnings on the target: a model asked outside its validity (as `corlab predict`
  /// warns), an FE speed without an e.
  std::vector<std::string> warnings;
  /// "i-j" or "i-wall" (type ids) followed by the label: "1-wall (glass-copper)".
  std::string name() const;
  /// LAMMPS damping viscoelastic coefficient eta_n = c/(m* sqrt(R*)) [1/(m s)].
  double lammps_viscoelastic_eta() const;
  /// LIGGGHTS coefficientYieldRatio = pi R* p_y / (2 E* r_i) [-].
  double liggghts_yield_ratio() const;
};

/// Validates the spec (InputError naming the field: radii in [1e-9, 1e3] m, labels unique over the
/// types and the wall and not a bare type id, each pair named by --pair or --pair-table once and
/// with a particle; a target e outside [kMinRestitution, 1] at a speed of the range names the
/// pair, the model and the speed) and calibrates every pair i <= j and each
/// type against the wall. A pair's target: its --pair constant or --pair-table, else the export's
/// (restitution, model or table; with none, every pair needs its own). A model takes the pair as
/// `corlab predict` does (PairBodies; only the particle yielding: the other body is the sphere),
/// with predict's warnings in PairCalibration::warnings; model "fe" or "auto" is
/// ExportSpec::target_source's (InputError naming `model` without one).
std::vector<PairCalibration> calibrate_pairs(const ExportSpec& spec);

/// Every pair of the export with all its walls: calibrate_pairs with the first wall material,
/// then each further wall material's type-wall pairs (PairCalibration::wall), and each pair's
/// Coulomb mu (its --friction A/B=MU, else the export's). Validates the walls (InputError naming
/// the field). What `corlab dem` and corlab.dem.export write.
std::vector<PairCalibration> calibrate_export(const ExportSpec& spec);
/// The label of wall material `k` (0: wall_label) as written in the exports.
std::string wall_label(const ExportSpec& spec, int k);
/// The walls of the export: spec.walls, or with a wall material and none given the floor z = 0.
std::vector<Wall> export_walls(const ExportSpec& spec);

/// The mesh files an export's LIGGGHTS fragment reads: (file name, wall_stl) per oblique plane,
/// corlab_wallK.stl for wall K (1-based, export_walls order). What `corlab dem` writes to --out
/// and corlab.dem.export returns.
std::vector<std::pair<std::string, std::string>> wall_meshes(const ExportSpec& spec);
/// Adds the wall "[LABEL=]MATERIAL[@SHAPE]" (dem_walls.hpp) to the spec: a new label is a new
/// wall material, a label seen before names the same one (its material must then be the same).
void add_wall(ExportSpec& spec, std::string_view text);

/// LIGGGHTS thornton_ning's coefficientYieldRatio per type (a_y = ratio r_i): its wall fit,
/// else its same-type fit; 1 (never yields) for a type without a fitted pair.
std::vector<double> liggghts_type_ratios(const ExportSpec& spec,
                                         const std::vector<PairCalibration>& pairs);
/// LIGGGHTS writes one normal model for all pairs: thornton_ning (e(v) through per-type yield
/// ratios) when its worst misfit over the pairs is below that of per-pair constants (model hertz)
/// and the walls are of one material.
bool liggghts_uses_thornton_ning(const std::vector<PairCalibration>& pairs);

/// How one code's fragment delivers one pair's target: the law it runs, in words, and its
/// max |e_law - e_target| over the fit speeds (0 where exact; the table interpolation for the
/// hooks). The time step adds at most kTimeStepError (time_step.hpp) at the recommended step.
struct Delivery {
  CodeLaw law = CodeLaw::yade_mindlin;
  std::string route;
  double max_abs_error = 0.0;
  std::vector<double> law_e;  ///< e the code's law delivers at the fit speeds, where not the target
};
/// e YADE 2023.02a's Hertz-Mindlin delivers for its input en: measured, as it falls short of en
/// above en = 0.9 (0.99 -> 0.979); en itself below 0.85 and at 1 (table in yade_writer.cpp).
double yade_delivered_e(double en);
Delivery lammps_delivery(const ExportSpec& spec, const PairCalibration& pair, bool python_hook);
Delivery liggghts_delivery(const std::vector<PairCalibration>& pairs, const PairCalibration& pair);
Delivery yade_delivery(const ExportSpec& spec, const PairCalibration& pair);
/// The recommended step of each fragment [s]: the shortest contact time at v_max over the
/// measured steps per contact of the law each pair runs with (time_step.hpp).
double lammps_time_step(const std::vector<PairCalibration>& pairs, bool python_hook);
double liggghts_time_step(const std::vector<PairCalibration>& pairs);
double yade_time_step(const std::vector<PairCalibration>& pairs);

/// LAMMPS (7Jan2022 / Debian 12) fragment: pair_style granular with per-type-pair pair_coeff and
/// one fix wall/gran per type (zplane at z = 0). Constant e: damping tsuji, pre-compensated.
/// e(v): elastic Hertz plus a `fix python/invoke` hook that adds the hysteresis damping with the
/// exact chi(e(v_in)) per contact (needs Debian's python3-lammps). `python_hook = false`: no
/// Python; per pair the better of a fitted `damping viscoelastic` and a constant e.
std::string write_lammps(const ExportSpec& spec,
                         const std::vector<PairCalibration>& pairs,
                         bool python_hook = true);
/// The same fragment with the e(v) damping in C++: `fix corlab/ev` (corlab-lammps, built where
/// Debian's liblammps-dev is installed; apps/corlab-lammps) instead of the Python hook; the same
/// law, table, delivery (lammps_delivery(.., true)) and time step.
std::string write_lammps_compiled(const ExportSpec& spec,
                                  const std::vector<PairCalibration>& pairs);
/// LIGGGHTS 3.8 fragment (model hertz: constant e per type pair, exact; or thornton_ning).
std::string write_liggghts(const ExportSpec& spec, const std::vector<PairCalibration>& pairs);
/// YADE fragment (Python): materials, en per material pair, the e(v) hook, O.dt.
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
