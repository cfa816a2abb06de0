// The LAMMPS fragments' e(v) hooks: lammps.in's Python one, lammps_compiled.in's fix corlab/ev.
// SPDX-License-Identifier: BSD-3-Clause
#include "dem/detail/lammps_hook.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "corlab/dem/dem_walls.hpp"
#include "corlab/dem/hysteresis_chi.hpp"
#include "dem/detail/export_spec.hpp"
#include "dem/detail/export_text.hpp"

namespace corlab::dem::detail {
namespace {

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

}  // namespace

const PairCalibration* wall_pair(const std::vector<PairCalibration>& pairs, int t, int m) {
  for (const auto& p : pairs) {
    if (p.type_j == 0 && p.type_i == t && p.wall == m) return &p;
  }
  return nullptr;
}

namespace {

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

}  // namespace

std::string lammps_python_hook(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
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

std::string lammps_compiled_fix(const ExportSpec& spec, const std::vector<PairCalibration>& pairs) {
  const auto speeds = table_speeds(spec, kHookTableRows);
  const auto table = [&](const PairCalibration& p) {
    std::vector<std::string> e;
    e.reserve(speeds.size());
    for (const double v : speeds) e.push_back(fmt::format("{:.10g}", std::min(p.curve(v), 1.0)));
    return fmt::format("{:.10g} {}", p.effective_modulus, fmt::join(e, " "));
  };
  std::string out = fmt::format(
      "# fix corlab_ev (one line): speeds V_MIN V_MAX N [m/s]; per e(v) pair of types `pair I J "
      "E*\n"
      "# e_1..e_N` (E* [Pa], e at the N speeds); per wall `wall plane PX PY PZ NX NY NZ` or `wall\n"
      "# cylinder AXIS(0-2) C1 C2 R LO HI` [m] (its region's), then per type `type N E* "
      "e_1..e_N`.\n"
      "fix corlab_ev all corlab/ev speeds {:.10g} {:.10g} {}",
      spec.v_min, spec.v_max, kHookTableRows);
  for (const auto& p : pairs) {
    if (p.constant || p.type_j == 0) continue;
    out += fmt::format(" pair {} {} {}", p.type_i, p.type_j, table(p));
  }
  for (const Wall& w : export_walls(spec)) {
    std::string types;
    for (int t = 1; t <= static_cast<int>(spec.types.size()); ++t) {
      const PairCalibration* p = wall_pair(pairs, t, w.material);
      if (p != nullptr && !p->constant) types += fmt::format(" type {} {}", t, table(*p));
    }
    if (types.empty()) continue;
    if (w.shape == WallShape::plane) {
      out += fmt::format(" wall plane {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}", w.point[0],
                         w.point[1], w.point[2], w.normal[0], w.normal[1], w.normal[2]);
    } else {
      out += fmt::format(" wall cylinder {} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}", w.axis,
                         w.centre[0], w.centre[1], w.radius, w.lo, w.hi);
    }
    out += types;
  }
  return out + "\n";
}

}  // namespace corlab::dem::detail
