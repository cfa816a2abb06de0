// The 3-D model's master surface on the deformable flat: the Catmull-Rom spline through the
// block's top grid (spline_surface.hpp), and a slave's contact with it.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/hex_master_surface.hpp"

#include <algorithm>

#include "corlab/fem/kernels/spline_surface.hpp"
#include "fem/solver/hex_model.hpp"

namespace corlab::fem::hex_solver {

MasterSurface make_master_surface(const HexMesh& mesh) {
  MasterSurface surface;
  if (mesh.top_faces.empty()) return surface;
  surface.nu = mesh.top_x.size();
  surface.nv = mesh.top_y.size();
  surface.node.assign(surface.nu * surface.nv, -1);
  const std::size_t faces_u = surface.nu - 1;
  for (std::size_t f = 0; f < mesh.top_faces.size(); ++f) {
    const std::size_t a = f % faces_u;
    const std::size_t b = f / faces_u;
    // Corners counter-clockwise from (a, b): (a, b), (a + 1, b), (a + 1, b + 1), (a, b + 1).
    const auto& c = mesh.top_faces[f];
    surface.node[a + surface.nu * b] = c[0];
    surface.node[a + 1 + surface.nu * b] = c[1];
    surface.node[a + 1 + surface.nu * (b + 1)] = c[2];
    surface.node[a + surface.nu * (b + 1)] = c[3];
  }
  return surface;
}

ControlNode control_node(const MasterSurface& surface, long a, long b) {
  ControlNode c;
  if (b < 0) {
    b = -b;
    c.mirror = -1.0;
  }
  const auto last_u = static_cast<long>(surface.nu) - 1;
  const auto last_v = static_cast<long>(surface.nv) - 1;
  const auto i = static_cast<std::size_t>(std::clamp(a, 0L, last_u));
  const auto j = static_cast<std::size_t>(std::clamp(b, 0L, last_v));
  c.node = surface.node[i + surface.nu * j];
  return c;
}

namespace {

// The start grid's parameter of the coordinate x [m] along its lines: the node i at i, linear
// between nodes, clamped to the grid [-].
double grid_parameter(const std::vector<double>& lines, double x) {
  const auto it = std::upper_bound(lines.begin(), lines.end(), x);
  const long last = static_cast<long>(lines.size()) - 2;
  const long i = std::clamp(static_cast<long>(it - lines.begin()) - 1, 0L, last);
  const auto k = static_cast<std::size_t>(i);
  const double t = (x - lines[k]) / (lines[k + 1] - lines[k]);
  return static_cast<double>(i) + std::clamp(t, 0.0, 1.0);
}

}  // namespace

SlaveContact surface_contact(const HexModel& m, const HexState& s, std::size_t n) {
  const NodeKinematics& slave = s.node[n];
  const double p[3] = {slave.x, slave.y, slave.z};
  return surface_contact_at(m, s, p);
}

SlaveContact surface_contact_at(const HexModel& m, const HexState& s, const double* p) {
  const MasterSurface& surface = m.surface;
  auto control = [&](long a, long b, double* x) {
    const ControlNode c = control_node(surface, a, b);
    const NodeKinematics& q = s.node[static_cast<std::size_t>(c.node)];
    x[0] = q.x;
    x[1] = c.mirror * q.y;
    x[2] = q.z;
  };
  // The whole grid, and half a patch across the symmetry plane, where the mirror image continues
  // the surface.
  const SplineDomain domain{0.0, static_cast<double>(surface.nu - 1), -0.5,
                            static_cast<double>(surface.nv - 1)};
  const SplineProjection f = project_on_spline_surface(
      p, grid_parameter(m.mesh.top_x, p[0]), grid_parameter(m.mesh.top_y, p[1]), domain, control);
  SlaveContact c;
  c.gap = f.gap;
  for (int d = 0; d < 3; ++d) c.normal[d] = f.normal[d];
  for (long b = 0; b < 4; ++b)
    for (long a = 0; a < 4; ++a) {
      const auto i = static_cast<std::size_t>(a + 4 * b);
      c.masters[i] = control_node(surface, f.k - 1 + a, f.l - 1 + b);
      c.weight[i] = f.weight[i];
    }
  return c;
}

std::array<double, 3> master_velocity(const SlaveContact& c, const HexState& s) {
  std::array<double, 3> v{0.0, 0.0, 0.0};
  for (std::size_t j = 0; j < c.masters.size() && c.masters[j].node >= 0; ++j) {
    const NodeKinematics& q = s.node[static_cast<std::size_t>(c.masters[j].node)];
    v[0] += c.weight[j] * q.vx;
    v[1] += c.weight[j] * c.masters[j].mirror * q.vy;
    v[2] += c.weight[j] * q.vz;
  }
  return v;
}

void push_masters(const SlaveContact& c, const double* force, HexState& s) {
  for (std::size_t j = 0; j < c.masters.size() && c.masters[j].node >= 0; ++j) {
    NodeForce& f = s.nodal_force[static_cast<std::size_t>(c.masters[j].node)];
    f.x -= c.weight[j] * force[0];
    f.y -= c.weight[j] * c.masters[j].mirror * force[1];
    f.z -= c.weight[j] * force[2];
  }
}

}  // namespace corlab::fem::hex_solver
