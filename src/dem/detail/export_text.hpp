// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file export_text.hpp
/// Text pieces shared by the DEM exports: the header, fit comments, the time-step block.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/time_step.hpp"

namespace corlab::dem::detail {

/// "# corlab <version> dem export for <code> ...": types, labels, radii, the wall.
std::string export_header(const ExportSpec& spec, std::string_view code);
/// "fit over a..b m/s (n speeds): rms .., max |de| .."
std::string fit_comment(const CurveFit& fit);
/// Whether any pair has friction (--friction MU or A/B=MU above 0).
bool has_friction(const ExportSpec& spec);
/// The friction as asked, for the headers: "0.3", "0.3; glass/steel 0.5".
std::string friction_words(const ExportSpec& spec);
/// The rolling stiffness k_roll [N/m] of a pair with E* [Pa], R* [m], m* [kg], G* [Pa]:
/// Mindlin's 8 G* a at the deepest overlap of a Hertz impact at v_max [m/s] (LAMMPS `rolling
/// sds`; YADE's krot = k_roll R*^2 [N m/rad]).
double rolling_stiffness(double e_star, double r_star, double m_star, double g_star, double v_max);
/// Speeds v_min..v_max, `points` linear [m/s] (the e(v) tables).
std::vector<double> table_speeds(const ExportSpec& spec, int points);

/// The recommended step of a fragment: the smallest contact time at v_max over the steps per
/// contact of the law each pair runs with in that code [s].
double recommended_step(const std::vector<PairCalibration>& pairs,
                        const std::function<CodeLaw(const PairCalibration&)>& law_of);
/// The comment block stating the contact times and the step (each line starts with `comment`).
std::string time_step_comment(const ExportSpec& spec,
                              const std::vector<PairCalibration>& pairs,
                              const std::function<CodeLaw(const PairCalibration&)>& law_of,
                              std::string_view comment = "#");

}  // namespace corlab::dem::detail

namespace corlab::dem::detail {

/// Rows of the e(v) tables the YADE and LAMMPS hooks interpolate.
inline constexpr int kHookTableRows = 64;
/// Worst |e(v) - e of the interpolated table| over the midpoints of the hook table's rows [-]:
/// `chi_table` true when the table holds chi(v) (LAMMPS hook), false when it holds e(v) (YADE).
double hook_table_error(const ExportSpec& spec, const PairCalibration& pair, bool chi_table);

}  // namespace corlab::dem::detail
