// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file explorer_api.hpp
/// What the e(v) explorer page asks the C++ (explorer/page/explorer.js through embind,
/// bindings.cpp): JSON text in, JSON text out, so that the page holds no formula. SI units
/// throughout: E, sigma_y, H [Pa], rho [kg/m^3], v [m/s], e [-].

#include <string>

namespace corlab::explorer {

/// The built-in materials (name, E, nu, rho, sigma_y, H, source), the registered models with
/// their metadata and calibration boxes, corlab2026's 95 % prediction interval and the corlab
/// version, as one JSON object.
std::string catalog();

/// Evaluates a request {"sphere": spec, "substrate": spec, "velocity": [v...], "nearest": n}
/// (specs as `corlab predict` takes them) and returns e(v) of every registered model, where each
/// is outside its calibration box, corlab2026's prediction interval, and the n FE dataset runs
/// nearest the pair (load_dataset). Bad input gives {"error": {message, field, value,
/// constraint}}, the message `corlab predict` prints for it.
std::string evaluate(const std::string& request);

/// The DEM export of the pair (`corlab dem --type SPHERE:RADIUS --wall SUBSTRATE --wall-only
/// --model MODEL --v-min V0 --v-max V1`, src/dem: the same calibration and writers): a request
/// {"sphere", "substrate", "radius" [m], "model", "v_min", "v_max" [m/s], "radius_ratio" [-]}
/// gives {"fragments": {"LAMMPS", "LIGGGHTS", "YADE"}, "command", "pairs": [{"target",
/// "routes": [{"code", "route", "max_abs_error", "time_step" [s]}]}]} or {"error": ...}. A
/// radius ratio R1/R2 > 0 exports a particle pair instead: the two bodies as particle types
/// "sphere" (R1) and "substrate" (R1/ratio), every pair of them calibrated, no wall.
std::string dem_export(const std::string& request);

/// Keeps the FE dataset's runs for evaluate(): a JSON object of equal-length columns named as in
/// data/fe_restitution/dataset.csv (null for an infinite or empty cell). Returns {"runs": n} or
/// {"error": ...}.
std::string load_dataset(const std::string& columns);

}  // namespace corlab::explorer
