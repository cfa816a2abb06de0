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

// The hook's functions (Python, inside LAMMPS's `python ... here """..."""`): per-contact memory of
// v_in, the damping, and the post_force callback over wall contacts and particle pairs.
constexpr std::string_view kHookFunctions =
    R"(corlab_memory = {}
corlab_lmp = []
corlab_dv = corlab_v[1] - corlab_v[0]
corlab_planes = [w for w, wall in enumerate(corlab_walls) if wall[0] == "plane"]
corlab_plane_n = np.array([corlab_walls[w][2] for w in corlab_planes], float).reshape(-1, 3)
corlab_plane_d = (np.array([corlab_walls[w][1] for w in corlab_planes], float).reshape(-1, 3)
                  * corlab_plane_n).sum(axis=1)
corlab_wall_rows = np.array(corlab_wall_row, np.int64).reshape(len(corlab_walls), len(corlab_row))
corlab_wall_estars = np.array(corlab_wall_estar, float).reshape(len(corlab_walls), len(corlab_row))

def corlab_factor(name, keys, rows, rate):
    # chi(e(v_in)) / v_in of each contact [s/m]: taken at its first step (v_in = the approach
    # speed then, chi from the pair's table, linear in v, end values outside) and kept.
    old_keys, old_f = corlab_memory.get(name, (np.zeros(0, np.int64), np.zeros(0)))
    pos = np.clip((rate - corlab_v[0]) / corlab_dv, 0.0, corlab_v.size - 1.0)
    k = np.minimum(pos.astype(np.int64), corlab_v.size - 2)
    w = pos - k
    chi = corlab_chi[rows, k] * (1.0 - w) + corlab_chi[rows, k + 1] * w
    factor = np.where(rate > 0, chi / np.maximum(rate, 1e-300), 0.0)
    if old_keys.size and keys.size:
        j = np.minimum(np.searchsorted(old_keys, keys), old_keys.size - 1)
        found = old_keys[j] == keys
        factor[found] = old_f[j[found]]
    order = np.argsort(keys)
    corlab_memory[name] = (keys[order], factor[order])
    return factor

def corlab_damping(factor, rate, estar, radius, overlap):
    # Hysteresis damping K delta^1.5 chi rate / v_in [N], K = 4/3 E* sqrt(R*).
    return 4.0 / 3.0 * estar * np.sqrt(radius) * overlap ** 1.5 * factor * rate

corlab_plane_rows = corlab_wall_rows[corlab_planes]
corlab_near = {}

def corlab_candidates(x, r, tag):
    # Atom pairs and (atom, plane) that may touch before some atom moves skin/2 = r_min/2: kept
    # from the step they were found (cKDTree) until an atom moves that far or LAMMPS reorders.
    c = corlab_near
    if ("tag" not in c or c["tag"].shape != tag.shape or not np.array_equal(c["tag"], tag)
            or ((x - c["x"]) ** 2).sum(axis=1).max() > 0.25 * c["skin"] ** 2):
        c["tag"], c["x"], c["skin"] = tag.copy(), x.copy(), r.min()
        tree = cKDTree(x, balanced_tree=False, compact_nodes=False)
        c["pairs"] = tree.query_pairs(2.0 * r.max() + c["skin"], output_type="ndarray")
        gap = x @ corlab_plane_n.T - corlab_plane_d
        c["plane"] = np.nonzero(gap < (r + c["skin"])[:, None])
    return c["pairs"], c["plane"]

def corlab_wall_contacts(x, r, t, near):
    # Every (atom, wall) in contact: atom, wall, overlap [m], unit normal into the particles.
    i, k = near
    gap = (x[i] * corlab_plane_n[k]).sum(axis=1) - corlab_plane_d[k]
    m = (r[i] > gap) & (corlab_plane_rows[k, t[i]] >= 0)
    i, k = i[m], k[m]
    atoms, walls = [i], [np.array(corlab_planes, np.int64)[k]]
    overlaps, normals = [r[i] - gap[m]], [corlab_plane_n[k]]
    for w, wall in enumerate(corlab_walls):
        if wall[0] != "cylinder":
            continue
        axis, c1, c2, radius, lo, hi = wall[1:]
        o = [a for a in range(3) if a != axis]
        d = x[:, o] - np.array([c1, c2])
        rho = np.sqrt((d * d).sum(axis=1))
        i = np.nonzero((r > radius - rho) & (corlab_wall_rows[w][t] >= 0) & (x[:, axis] >= lo)
                       & (x[:, axis] <= hi))[0]
        n = np.zeros((i.size, 3))
        n[:, o] = -d[i] / np.maximum(rho[i], 1e-300)[:, None]
        atoms.append(i)
        walls.append(np.full(i.size, w, np.int64))
        overlaps.append(r[i] - (radius - rho[i]))
        normals.append(n)
    return (np.concatenate(atoms), np.concatenate(walls), np.concatenate(overlaps),
            np.concatenate(normals))

def corlab_ev_force(lmpptr, vflag):
    if not corlab_lmp:
        corlab_lmp.append(lammps(ptr=lmpptr))
    lmp = corlab_lmp[0]
    nlocal = lmp.extract_global("nlocal")
    nall = nlocal + lmp.extract_global("nghost")
    x = lmp.numpy.extract_atom("x", nelem=nall)
    v = lmp.numpy.extract_atom("v", nelem=nall)
    r = lmp.numpy.extract_atom("radius", nelem=nall)
    t = lmp.numpy.extract_atom("type", nelem=nall)
    tag = lmp.numpy.extract_atom("id", nelem=nall).astype(np.int64)
    f = lmp.numpy.extract_atom("f", nelem=nlocal)
    pairs, plane = corlab_candidates(x[:nall], r[:nall], tag[:nall])
    if corlab_walls:
        near = plane[0] < nlocal
        i, w, overlap, n = corlab_wall_contacts(x[:nlocal], r[:nlocal], t[:nlocal],
                                                (plane[0][near], plane[1][near]))
        rate = -(v[i] * n).sum(axis=1)
        factor = corlab_factor("wall", tag[i] * len(corlab_walls) + w,
                               corlab_wall_rows[w, t[i]], rate)
        force = corlab_damping(factor, rate, corlab_wall_estars[w, t[i]], r[i], overlap)
        for a in range(3):
            f[:, a] += np.bincount(i, force * n[:, a], minlength=nlocal)
    if nall < 2 or corlab_row.max() < 0:
        return
    if pairs.size == 0:
        corlab_factor("pair", np.zeros(0, np.int64), np.zeros(0, np.int64), np.zeros(0))
        return
    i, j = pairs[:, 0], pairs[:, 1]
    d = x[j] - x[i]
    dist = np.sqrt((d * d).sum(axis=1))
    overlap = r[i] + r[j] - dist
    m = (overlap > 0) & (corlab_row[t[i], t[j]] >= 0) & ((i < nlocal) | (j < nlocal))
    i, j, d, dist, overlap = i[m], j[m], d[m], dist[m], overlap[m]
    n = d / dist[:, None]
    rate = ((v[i] - v[j]) * n).sum(axis=1)
    keys = np.minimum(tag[i], tag[j]) * 2 ** 31 + np.maximum(tag[i], tag[j])
    factor = corlab_factor("pair", keys, corlab_row[t[i], t[j]], rate)
    force = corlab_damping(factor, rate, corlab_estar[t[i], t[j]], r[i] * r[j] / (r[i] + r[j]),
                           overlap)
    li, lj = i < nlocal, j < nlocal
    for a in range(3):
        f[:, a] += (np.bincount(j[lj], force[lj] * n[lj, a], minlength=nlocal)
                    - np.bincount(i[li], force[li] * n[li, a], minlength=nlocal))
)";

// The pair of type `t` with wall material `m` (nullptr: none, e.g. no wall material).
const PairCalibration* wall_pair(const std::vector<PairCalibration>& pairs, int t, int m) {
  for (const auto& p : pairs) {
    if (p.type_j == 0 && p.type_i == t && p.wall == m) return &p;
  }
  return nullptr;
}

// One wall as the hook's Python tuple: ("plane", point, normal) or ("cylinder", axis, c1, c2,
// radius, lo, hi) [m].
std::string hook_wall(const Wall& w) {
  if (w.shape == WallShape::plane) {
    return fmt::format("(\"plane\", ({:.17g}, {:.17g}, {:.17g}), ({:.17g}, {:.17g}, {:.17g}))",
                       w.point[0], w.point[1], w.point[2], w.normal[0], w.normal[1], w.normal[2]);
  }
  return fmt::format("(\"cylinder\", {}, {:.17g}, {:.17g}, {:.17g}, {:.17g}, {:.17g})", w.axis,
                     w.centre[0], w.centre[1], w.radius, w.lo, w.hi);
}

// The Python of the hook (LAMMPS `python ... here`): tables, then the post_force function.
std::string hook_python(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  const std::size_t n = spec.types.size();
  std::vector<std::vector<int>> row(n + 1, std::vector<int>(n + 1, -1));
  std::vector<std::vector<double>> estar(n + 1, std::vector<double>(n + 1, 0.0));
  std::string chi;
  int rows = 0;
  std::vector<int> row_of(pairs.size(), -1);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto& p = pairs[k];
    if (p.constant) continue;
    row_of[k] = rows++;
    if (p.type_j != 0) {
      const auto i = static_cast<std::size_t>(p.type_i);
      const auto j = static_cast<std::size_t>(p.type_j);
      row[i][j] = row[j][i] = row_of[k];
      estar[i][j] = estar[j][i] = p.effective_modulus;
    }
    std::vector<std::string> c;
    for (const double v : detail::table_speeds(spec, detail::kHookTableRows)) {
      c.push_back(fmt::format("{:.8g}", exact_chi(std::min(p.curve(v), 1.0))));
    }
    chi += fmt::format("    [{}],  # {}\n", fmt::join(c, ", "), p.name());
  }
  std::string out = "python corlab_ev_force here \"\"\"\n";
  out += "import numpy as np\nfrom lammps import lammps\nfrom scipy.spatial import cKDTree\n";
  out += "# row of each particle type pair [type i][type j] in corlab_chi, -1: not the hook's\n";
  out += "corlab_row = np.array([";
  for (const auto& r : row) out += fmt::format("[{}], ", fmt::join(r, ", "));
  out += "])\ncorlab_estar = np.array([";  // E* [Pa] of each type pair
  for (const auto& r : estar) out += fmt::format("[{}], ", fmt::join(r, ", "));
  std::vector<std::string> vs;
  for (const double v : detail::table_speeds(spec, detail::kHookTableRows)) {
    vs.push_back(fmt::format("{:.8g}", v));
  }
  out += fmt::format("])\ncorlab_v = np.array([{}])  # m/s\ncorlab_chi = np.array([\n{}])\n",
                     fmt::join(vs, ", "), chi);
  out +=
      "# The walls of the fix wall/gran/region fixes below (edit both), [m]; per wall and type\n"
      "# the row in corlab_chi (-1: not the hook's) and E* [Pa]\ncorlab_walls = [";
  std::vector<std::string> walls;
  std::vector<std::string> wall_rows;
  std::vector<std::string> wall_estar;
  for (const Wall& w : export_walls(spec)) {
    walls.push_back(hook_wall(w));
    std::vector<int> r(n + 1, -1);
    std::vector<double> e(n + 1, 0.0);
    for (int t = 1; t <= static_cast<int>(n); ++t) {
      const PairCalibration* p = wall_pair(pairs, t, w.material);
      if (p == nullptr) continue;
      r[static_cast<std::size_t>(t)] = row_of[static_cast<std::size_t>(p - pairs.data())];
      e[static_cast<std::size_t>(t)] = p->effective_modulus;
    }
    wall_rows.push_back(fmt::format("np.array([{}])", fmt::join(r, ", ")));
    wall_estar.push_back(fmt::format("np.array([{}])", fmt::join(e, ", ")));
  }
  out +=
      fmt::format("{}]\ncorlab_wall_row = [{}]\ncorlab_wall_estar = [{}]\n", fmt::join(walls, ", "),
                  fmt::join(wall_rows, ", "), fmt::join(wall_estar, ", "));
  out += kHookFunctions;
  out += "\"\"\"\nfix corlab_ev all python/invoke 1 post_force corlab_ev_force\n";
  return out;
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
      const PairCalibration* p = wall_pair(pairs, t, walls[k].material);
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

std::string write_lammps(const ExportSpec& spec,
                         const std::vector<PairCalibration>& pairs,
                         bool python_hook) {
  const bool any_curve =
      std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return !p.constant; });
  const bool hook = python_hook && any_curve;
  std::string out = detail::export_header(
      spec, "LAMMPS (pair_style granular, tested with Debian 12's 29Sep2021 update 2)");
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
  if (hook) {
    out +=
        "# e(v): elastic Hertz plus a per-contact hook (fix python/invoke, post_force; needs\n"
        "# Debian's python3-lammps and python3-scipy) adding the hysteresis damping\n"
        "# K delta^1.5 chi delta_dot / v_in with the exact chi(e(v_in)) of each contact's normal\n"
        "# approach speed v_in (tables below, linear in v, end values outside). Its virial is not\n"
        "# counted (pressure); contact memory is per MPI rank (a contact that moves to another\n"
        "# rank restarts its v_in). No Python: `corlab dem` also writes lammps_nopython.in.\n";
  } else if (any_curve) {
    out +=
        "# e(v) without Python: per pair the better of `damping viscoelastic` (F_d = eta a m*\n"
        "# delta_dot, a = sqrt(R* delta); its e falls as 1 - c v^(1/5)) with eta fitted to the\n"
        "# target, and the constant e closest to it (misfits below). lammps.in delivers e(v)\n"
        "# itself (fix python/invoke).\n";
  }
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
  if (hook) out += hook_python(spec, pairs);
  const auto law = [python_hook](const PairCalibration& p) { return pair_law(p, python_hook); };
  out += detail::time_step_comment(spec, pairs, law);
  out += fmt::format("timestep {:.4g}\n", detail::recommended_step(pairs, law));
  return out;
}

}  // namespace corlab::dem
