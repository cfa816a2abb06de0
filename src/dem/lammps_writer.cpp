// The LAMMPS fragment of a DEM export (pair_style granular, fix wall/gran, the e(v) hook).
// SPDX-License-Identifier: BSD-3-Clause
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "corlab/core/units.hpp"
#include "corlab/dem/dem_export.hpp"
#include "corlab/dem/hysteresis_chi.hpp"
#include "corlab/dem/lammps_mapping.hpp"
#include "corlab/dem/tangential.hpp"
#include "dem/detail/export_spec.hpp"
#include "dem/detail/export_text.hpp"
#include "dem/detail/lammps_hook.hpp"

namespace corlab::dem {
namespace {

enum class Route { tsuji, hook, viscoelastic, constant_fallback };

Route route_of(const PairCalibration& p, bool python_hook) {
  if (p.constant) return Route::tsuji;
  if (python_hook) return Route::hook;
  return p.viscoelastic->max_abs_error < p.best_constant->max_abs_error ? Route::viscoelastic
                                                                        : Route::constant_fallback;
}

CodeLaw law_of(Route r) {
  switch (r) {
    case Route::hook:
      return CodeLaw::lammps_hook;
    case Route::viscoelastic:
      return CodeLaw::lammps_viscoelastic;
    default:
      return CodeLaw::lammps_tsuji;
  }
}

// The law whose measured step the pair needs: an elastic pair (e = 1) of the hook's fragment runs
// elastic Hertz, the hook's law without its damping (no jump at first touch).
CodeLaw pair_law(const PairCalibration& p, bool python_hook) {
  if (python_hook && p.constant && *p.constant >= 1.0) return CodeLaw::lammps_hook;
  return law_of(route_of(p, python_hook));
}

// "tangential ..." of a pair with G* [Pa], E* [Pa] and mu: frictionless, or Mindlin's k_t = 8 G*
// [Pa] (F_t = k_t a xi), x_gamma = sqrt(4 G*/E*) [-] (the normal damping ratio) and mu [-].
std::string tangential(double shear_modulus, double effective_modulus, double friction) {
  if (friction <= 0.0) return "tangential linear_nohistory 0.0 0.0";
  return fmt::format("tangential mindlin_rescale {:.10g} {:.6g} {:.6g}",
                     mindlin_coefficient(shear_modulus),
                     tangential_damping_ratio(shear_modulus, effective_modulus), friction);
}

// " rolling sds k_roll 0 mu_r" of a pair with E* [Pa], R* [m], m* [kg] and G* [Pa] (k_roll:
// detail::rolling_stiffness, no rolling dashpot, the moment capped at mu_r R* F_n); "" without
// rolling resistance (mu_r = 0).
std::string rolling(
    const ExportSpec& spec, double e_star, double r_star, double m_star, double g_star) {
  if (spec.rolling <= 0.0) return "";
  return fmt::format(" rolling sds {:.10g} 0.0 {:.6g}",
                     detail::rolling_stiffness(e_star, r_star, m_star, g_star, spec.v_max),
                     spec.rolling);
}

// "hertz KN DAMP tangential ... damping MODEL" of one pair (pair_coeff and fix wall/gran).
std::string normal_model(const ExportSpec& spec, const PairCalibration& p, Route r) {
  const double kn = 4.0 / 3.0 * p.effective_modulus;
  const std::string t = tangential(p.shear_modulus, p.effective_modulus, p.friction);
  std::string damping;
  const double e = r == Route::tsuji ? p.constant.value_or(1.0) : p.best_constant->parameter;
  if (r == Route::hook || (r != Route::viscoelastic && e >= 1.0)) {
    damping = fmt::format("0.0 {} damping velocity", t);  // elastic Hertz
  } else if (r == Route::viscoelastic) {
    damping = fmt::format("{:.10g} {} damping viscoelastic", p.lammps_viscoelastic_eta(), t);
  } else {
    const double e_in = r == Route::tsuji ? p.lammps_tsuji_input : lammps_tsuji_input(e);
    damping = fmt::format("{:.10g} {} damping tsuji", e_in, t);
  }
  return fmt::format(
      "hertz {:.10g} {}{}", kn, damping,
      rolling(spec, p.effective_modulus, p.effective_radius, p.effective_mass, p.shear_modulus));
}

// The header's paragraph on the tangential part.
std::string tangential_comment(const ExportSpec& spec) {
  std::string out;
  if (spec.rolling > 0.0) {
    out = fmt::format(
        "# Rolling resistance (--rolling {:.6g}): `rolling sds k_roll 0 mu_r`, the moment capped\n"
        "# at mu_r R* F_n; k_roll [N/m] = 8 G* a at the deepest overlap of an impact at v_max\n"
        "# (Mindlin's tangential stiffness there), no rolling dashpot.\n",
        spec.rolling);
  }
  if (!detail::has_friction(spec)) return out + std::string(kFrictionlessComment);
  return out +
         fmt::format(
             "# Tangential (--friction {}): `mindlin_rescale k_t x_gamma mu`, Mindlin's no-slip\n"
             "# stiffness k_t a with k_t = 8 G* [Pa], 1/G* = (2-nu_1)/G_1 + (2-nu_2)/G_2 (what "
             "LAMMPS's\n"
             "# own k_t = NULL gives with hertz/material), the displacement rescaled as a shrinks\n"
             "# (Thornton et al. 2013), Coulomb mu; x_gamma = sqrt(4 G*/E*): the tangential "
             "dashpot\n"
             "# has the normal one's damping ratio (none where the normal part is elastic "
             "Hertz).\n",
             detail::friction_words(spec));
}

std::string route_comment(const ExportSpec& spec, const PairCalibration& p, Route r) {
  switch (r) {
    case Route::tsuji:
      return fmt::format("# {}: {}; damping tsuji, exact (e_in pre-compensated)\n", p.name(),
                         p.target);
    case Route::hook:
      return fmt::format(
          "# {}: {}; elastic Hertz + the hook's damping with chi(e(v_in)): max |de| {:.1e} "
          "(table interpolation)\n",
          p.name(), p.target, detail::hook_table_error(spec, p, true));
    case Route::viscoelastic:
      return fmt::format("# {}: {}; damping viscoelastic, {}\n", p.name(), p.target,
                         detail::fit_comment(*p.viscoelastic));
    default:
      return fmt::format("# {}: {}; constant e = {:.6g} (damping tsuji): {}\n", p.name(), p.target,
                         p.best_constant->parameter, detail::fit_comment(*p.best_constant));
  }
}

// The LAMMPS region of wall `w` (1-based id): the particles' side is its inside.
std::string wall_region(const Wall& wall, int w) {
  if (wall.shape == WallShape::plane) {
    return fmt::format(
        "region corlab_wall{} plane {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} "
        "side in units box\n",
        w, wall.point[0], wall.point[1], wall.point[2], wall.normal[0], wall.normal[1],
        wall.normal[2]);
  }
  return fmt::format(
      "region corlab_wall{} cylinder {} {:.10g} {:.10g} {:.10g} {:.10g} {:.10g} side in units box "
      "open 1 open 2\n",
      w, static_cast<char>('x' + wall.axis), wall.centre[0], wall.centre[1], wall.radius, wall.lo,
      wall.hi);
}

// The walls: a region each and one fix wall/gran/region per wall and type on group corlab_typeN
// (this LAMMPS, 29Sep2021, refuses dynamic groups for wall fixes), and a guard (fix halt) that
// stops a run holding an atom outside its type's group: it would pass through the walls unseen.
std::string wall_fixes(const ExportSpec& spec,
                       const std::vector<PairCalibration>& pairs,
                       bool python_hook) {
  std::string out =
      "# Walls act on group corlab_typeN: atoms added later must join it. fix pour / fix deposit\n"
      "# put what they insert into their own group: `fix ID corlab_typeN pour ... N ...`; after\n"
      "# a later create_atoms repeat `group corlab_typeN type N`. corlab_guard stops the run\n"
      "# (checked every 100 steps) if an atom of a walled type is outside its group. Wall W is\n"
      "# region corlab_wallW (a plane: its normal points to the particles; a cylinder: they are\n"
      "# inside, its ends open); fix corlab_wallW_tN is its contact with type N.\n";
  const auto walls = export_walls(spec);
  if (walls.empty()) return out;
  std::vector<std::string> orphan;
  for (int t = 1; t <= static_cast<int>(spec.types.size()); ++t) {
    out += fmt::format("group corlab_type{0} type {0}\n", t);
    orphan.push_back(fmt::format("(type=={0})*(1-gmask(corlab_type{0}))", t));
  }
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const int w = static_cast<int>(k) + 1;
    out += fmt::format("# wall {}: {}\n", w, wall_label(spec, walls[k].material));
    out += wall_region(walls[k], w);
    for (int t = 1; t <= static_cast<int>(spec.types.size()); ++t) {
      const PairCalibration* p = detail::wall_pair(pairs, t, walls[k].material);
      if (p == nullptr) continue;
      out += fmt::format(
          "fix corlab_wall{0}_t{1} corlab_type{1} wall/gran/region granular {2} region "
          "corlab_wall{0}\n",
          w, t, normal_model(spec, *p, route_of(*p, python_hook)));
    }
  }
  out += fmt::format(
      "variable corlab_orphan atom {}\ncompute corlab_orphans all reduce sum v_corlab_orphan\n"
      "variable corlab_orphans equal c_corlab_orphans\n"
      "fix corlab_guard all halt 100 v_corlab_orphans > 0.5 error hard message yes\n",
      fmt::join(orphan, "+"));
  return out;
}

}  // namespace

Delivery lammps_delivery(const ExportSpec& spec, const PairCalibration& pair, bool python_hook) {
  const Route r = route_of(pair, python_hook);
  switch (r) {
    case Route::tsuji:
      return {pair_law(pair, python_hook), "damping tsuji (pre-compensated)", 0.0, {}};
    case Route::hook:
      return {law_of(r),
              "elastic Hertz + corlab's python/invoke hook",
              detail::hook_table_error(spec, pair, true),
              {}};
    case Route::viscoelastic:
      return {law_of(r), "damping viscoelastic (fitted eta)", pair.viscoelastic->max_abs_error, {}};
    default:
      return {law_of(r),
              "damping tsuji, the closest constant e",
              pair.best_constant->max_abs_error,
              {}};
  }
}

double lammps_time_step(const std::vector<PairCalibration>& pairs, bool python_hook) {
  return detail::recommended_step(
      pairs, [python_hook](const PairCalibration& p) { return pair_law(p, python_hook); });
}

namespace {

// Which e(v) hook a fragment carries: none (lammps_nopython.in), the Python one (lammps.in) or
// the compiled fix corlab/ev (lammps_compiled.in, run by corlab-lammps).
enum class Hook { none, python, compiled };

// The header's paragraph on how the fragment delivers e(v) (none: every pair constant).
std::string ev_comment(Hook kind, bool any_curve) {
  if (any_curve && kind == Hook::compiled) {
    return "# Run: `corlab-lammps -in in.file` (built with corlab where Debian's liblammps-dev is\n"
           "# installed; plain lmp stops at `fix corlab/ev`: Unrecognized fix style). e(v): "
           "elastic\n"
           "# Hertz plus fix corlab/ev, the damping K delta^1.5 chi delta_dot / v_in with the "
           "exact\n"
           "# chi(e(v_in)) of each contact's normal approach speed v_in, in C++ (lammps.in's "
           "Python\n"
           "# hook, the same law and table, at native speed): pairs of pair_style granular's\n"
           "# neighbour list and the walls named in its line (edit both). Its virial is not "
           "counted\n"
           "# (pressure); contact memory is per MPI rank (a contact that moves to another rank\n"
           "# restarts its v_in); newton on or off; no run_style respa.\n";
  }
  if (any_curve && kind == Hook::python) {
    return "# e(v): elastic Hertz plus a per-contact hook (fix python/invoke, post_force; needs\n"
           "# Debian's python3-lammps and python3-scipy) adding the hysteresis damping\n"
           "# K delta^1.5 chi delta_dot / v_in with the exact chi(e(v_in)) of each contact's "
           "normal\n"
           "# approach speed v_in (tables below, linear in v, end values outside). Its virial is "
           "not\n"
           "# counted (pressure); contact memory is per MPI rank (a contact that moves to another\n"
           "# rank restarts its v_in). No Python: `corlab dem` also writes lammps_nopython.in.\n";
  }
  if (any_curve) {
    return "# e(v) without Python: per pair the better of `damping viscoelastic` (F_d = eta a m*\n"
           "# delta_dot, a = sqrt(R* delta); its e falls as 1 - c v^(1/5)) with eta fitted to the\n"
           "# target, and the constant e closest to it (misfits below). lammps.in delivers e(v)\n"
           "# itself (fix python/invoke), lammps_compiled.in at native speed (corlab-lammps).\n";
  }
  return "";
}

std::string write_fragment(const ExportSpec& spec,
                           const std::vector<PairCalibration>& pairs,
                           Hook kind) {
  const bool python_hook = kind != Hook::none;  // the e(v) routes: the same law either way
  const bool any_curve =
      std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return !p.constant; });
  const bool hook = python_hook && any_curve;
  std::string out = detail::export_header(
      spec, kind == Hook::compiled
                ? "corlab-lammps (Debian 12's LAMMPS 29Sep2021 update 2 with corlab's fix "
                  "corlab/ev)"
                : "LAMMPS (pair_style granular, tested with Debian 12's 29Sep2021 update 2)");
  out +=
      "# Needs: units si, atom_style sphere, comm_modify vel yes, fix nve/sphere; include it "
      "after\n"
      "# create_box (atoms added later: see the walls).\n# Normal model `hertz` with kn = 4/3 E* "
      "[Pa]: F = kn sqrt(R* delta) delta\n"
      "# (exact Hertz; `hertz/material` is avoided: this LAMMPS's fix wall/gran uses about\n"
      "# E/(2(1-nu)) for the wall).\n";
  out += tangential_comment(spec);
  out +=
      "# Constant e: `damping tsuji` maps e_in to alpha with a polynomial that is not exact for\n"
      "# this law (asked 0.3 it delivers 0.440), so e_in is pre-compensated: alpha(e_in) = the\n"
      "# exact alpha(e) (corlab ODE); e = 1: no damping.\n";
  out += ev_comment(kind, any_curve);
  out += "# Type pairs, the target and how this fragment delivers it:\n";
  for (const auto& p : pairs) out += route_comment(spec, p, route_of(p, python_hook));
  const auto [smallest, largest] =
      std::minmax_element(spec.types.begin(), spec.types.end(),
                          [](const auto& a, const auto& b) { return a.radius < b.radius; });
  out += fmt::format(
      "# Cutoff 2 r_max = {0:.6g} m (r_max [m] the largest type's radius): the farthest contact.\n"
      "# Without it LAMMPS sizes the pair cutoff from the atoms present at `run` and misses\n"
      "# contacts of larger atoms inserted later until they overlap deeply (fix pour).\n"
      "# Neighbour skin 0.2 r_min = {1:.6g} m.\npair_style granular {0:.6g}\nneighbor {1:.6g} bin\n"
      "neigh_modify delay 0\n",
      2.0 * largest->radius, 0.2 * smallest->radius);
  const auto n = static_cast<int>(spec.types.size());
  if (spec.wall_only) {
    out += "# --wall-only: particle-particle contacts elastic Hertz (e = 1), not calibrated\n";
    for (int i = 1; i <= n; ++i) {
      for (int j = i; j <= n; ++j) {
        const ParticleType& a = spec.types[static_cast<std::size_t>(i - 1)];
        const ParticleType& b = spec.types[static_cast<std::size_t>(j - 1)];
        const double e_star = effective_modulus(a.material, b.material);
        const double g_star = mindlin_shear_modulus(a.material, b.material);
        const double mu = detail::pair_friction(spec, i, j).value_or(spec.friction);
        const auto mass = [](const ParticleType& t) {
          return 4.0 / 3.0 * units::kPi * std::pow(t.radius, 3) * t.material.density;
        };
        out += fmt::format("pair_coeff {} {} hertz {:.10g} 0.0 {} damping velocity{}\n", i, j,
                           4.0 / 3.0 * e_star, tangential(g_star, e_star, mu),
                           rolling(spec, e_star, a.radius * b.radius / (a.radius + b.radius),
                                   mass(a) * mass(b) / (mass(a) + mass(b)), g_star));
      }
    }
  }
  for (const auto& p : pairs) {
    if (p.type_j == 0) continue;
    out += fmt::format("pair_coeff {} {} {}\n", p.type_i, p.type_j,
                       normal_model(spec, p, route_of(p, python_hook)));
  }
  out += wall_fixes(spec, pairs, python_hook);
  if (hook) {
    out += kind == Hook::compiled ? detail::lammps_compiled_fix(spec, pairs)
                                  : detail::lammps_python_hook(spec, pairs);
  }
  const auto law = [python_hook](const PairCalibration& p) { return pair_law(p, python_hook); };
  out += detail::time_step_comment(spec, pairs, law);
  out += fmt::format("timestep {:.4g}\n", detail::recommended_step(pairs, law));
  return out;
}

}  // namespace

std::string write_lammps(const ExportSpec& spec,
                         const std::vector<PairCalibration>& pairs,
                         bool python_hook) {
  return write_fragment(spec, pairs, python_hook ? Hook::python : Hook::none);
}

std::string write_lammps_compiled(const ExportSpec& spec,
                                  const std::vector<PairCalibration>& pairs) {
  return write_fragment(spec, pairs, Hook::compiled);
}

}  // namespace corlab::dem
