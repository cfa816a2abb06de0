// Built-in impact mesh (mesh_generator.hpp): node sets, shape, sizes, scaling.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/mesh/mesh_generator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "corlab/core/error.hpp"
#include "corlab/fem/kernels/stable_time_step.hpp"
#include "corlab/fem/mesh/contact_estimate.hpp"
#include "corlab/fem/mesh/mesh_quality.hpp"

namespace corlab::fem {
namespace {

constexpr double kPi = std::numbers::pi;

MeshOptions options_at(double velocity, bool transitions = false) {
  ImpactConfig config;
  config.impact.velocity = velocity;
  config.mesh.transitions = transitions ? 1.0 : 0.0;
  return mesh_options_for(config);
}

double edge(const Mesh& m, int a, int b) {
  return std::hypot(m.r[static_cast<std::size_t>(a)] - m.r[static_cast<std::size_t>(b)],
                    m.z[static_cast<std::size_t>(a)] - m.z[static_cast<std::size_t>(b)]);
}

// Parameter: impact velocity [m/s] and mesh.transitions (3:1 transitions in the tensor substrate
// and the sphere's bottom ring).
class MeshAtVelocity : public ::testing::TestWithParam<std::tuple<double, bool>> {
 protected:
  static MeshOptions options() {
    return options_at(std::get<0>(GetParam()), std::get<1>(GetParam()));
  }
};

TEST(CounterClockwise, KeepsACounterClockwiseQuadAndFlipsAClockwiseOne) {
  Mesh m;
  m.r = {0.0, 1.0, 1.0, 0.0};
  m.z = {0.0, 0.0, 1.0, 1.0};
  const std::array<int, 4> ccw{0, 1, 2, 3};
  EXPECT_EQ(counter_clockwise(m, ccw), ccw);
  EXPECT_EQ(counter_clockwise(m, {0, 3, 2, 1}), ccw);
  EXPECT_EQ(counter_clockwise(m, {1, 0, 3, 2}), (std::array<int, 4>{1, 2, 3, 0}));
}

TEST_P(MeshAtVelocity, NodeSetsFollowTheConventions) {
  const MeshOptions o = options();
  const Mesh m = generate_impact_mesh(o);
  const double tol = 1e-12 * o.sphere_radius;
  ASSERT_EQ(m.node_body.size(), m.r.size());
  ASSERT_EQ(m.element_body.size(), m.quads.size());

  // axis: exactly the nodes at r = 0, in both bodies
  std::set<Body> axis_bodies;
  for (const int n : m.axis_nodes) {
    EXPECT_EQ(m.r[static_cast<std::size_t>(n)], 0.0);
    axis_bodies.insert(m.node_body[static_cast<std::size_t>(n)]);
  }
  EXPECT_EQ(axis_bodies.size(), 2u);
  EXPECT_EQ(static_cast<long>(m.axis_nodes.size()), std::count(m.r.begin(), m.r.end(), 0.0));

  // base: substrate nodes at z = -D, all of them
  for (const int n : m.base_nodes) {
    EXPECT_EQ(m.z[static_cast<std::size_t>(n)], -o.substrate_depth);
    EXPECT_EQ(m.node_body[static_cast<std::size_t>(n)], Body::kSubstrate);
  }
  long at_base = 0;
  for (int n = 0; n < m.num_nodes(); ++n)
    if (m.node_body[static_cast<std::size_t>(n)] == Body::kSubstrate &&
        m.z[static_cast<std::size_t>(n)] == -o.substrate_depth)
      ++at_base;
  EXPECT_EQ(static_cast<long>(m.base_nodes.size()), at_base);

  // substrate surface: z = 0, r increasing from 0 to W
  const auto& top = m.substrate_surface_nodes;
  ASSERT_GE(top.size(), 2u);
  EXPECT_EQ(m.r[static_cast<std::size_t>(top.front())], 0.0);
  EXPECT_EQ(m.r[static_cast<std::size_t>(top.back())], o.substrate_radius);
  for (std::size_t k = 0; k < top.size(); ++k) {
    EXPECT_EQ(m.z[static_cast<std::size_t>(top[k])], 0.0);
    EXPECT_EQ(m.node_body[static_cast<std::size_t>(top[k])], Body::kSubstrate);
    if (k > 0) {
      EXPECT_GT(m.r[static_cast<std::size_t>(top[k])], m.r[static_cast<std::size_t>(top[k - 1])]);
    }
  }

  // sphere surface: on the circle, from the lowest point, polar angle increasing, covering the
  // lower hemisphere
  const auto& surf = m.sphere_surface_nodes;
  const double zc = o.gap + o.sphere_radius;
  ASSERT_GE(surf.size(), 2u);
  EXPECT_EQ(m.r[static_cast<std::size_t>(surf.front())], 0.0);
  EXPECT_NEAR(m.z[static_cast<std::size_t>(surf.front())], o.gap, tol);
  double last_phi = -1.0;
  for (const int n : surf) {
    const double r = m.r[static_cast<std::size_t>(n)];
    const double z = m.z[static_cast<std::size_t>(n)];
    EXPECT_EQ(m.node_body[static_cast<std::size_t>(n)], Body::kSphere);
    EXPECT_NEAR(std::hypot(r, z - zc), o.sphere_radius, tol);
    const double phi = std::atan2(r, zc - z);
    EXPECT_GT(phi, last_phi);
    last_phi = phi;
  }
  EXPECT_GE(last_phi, 0.5 * kPi);

  // no two nodes of a body coincide (blocks share their edge nodes exactly)
  std::map<std::tuple<Body, long, long>, int> cells;
  const double cell = 0.05 * o.h_contact;
  for (int n = 0; n < m.num_nodes(); ++n) {
    const auto k = static_cast<std::size_t>(n);
    const long i = std::lround(m.r[k] / cell);
    const long j = std::lround(m.z[k] / cell);
    for (long di = -1; di <= 1; ++di)
      for (long dj = -1; dj <= 1; ++dj) {
        const auto it = cells.find({m.node_body[k], i + di, j + dj});
        if (it != cells.end()) {
          EXPECT_GT(edge(m, n, it->second), 0.01 * o.h_contact) << n << " " << it->second;
        }
      }
    cells[{m.node_body[k], i, j}] = n;
  }

  // bodies share no node
  for (std::size_t e = 0; e < m.quads.size(); ++e)
    for (const int n : m.quads[e])
      EXPECT_EQ(m.node_body[static_cast<std::size_t>(n)], m.element_body[e]);
}

TEST_P(MeshAtVelocity, ElementsAreWellShapedAndNotTooSmall) {
  const MeshOptions o = options();
  const Mesh m = generate_impact_mesh(o);
  for (const Body b : {Body::kSphere, Body::kSubstrate}) {
    const MeshQuality q = mesh_quality(m, b);
    EXPECT_GT(q.elements, 0);
    EXPECT_GT(q.min_jacobian, 0.0);  // every corner of every element
    EXPECT_GT(q.min_angle, 35.0 * kPi / 180.0);
    EXPECT_LT(q.max_angle, 145.0 * kPi / 180.0);
    EXPECT_LT(q.max_aspect_ratio, 1.05 * o.h_max / o.h_contact + 1.0);
    // the smallest element sets the explicit time step
    EXPECT_GE(q.min_width, 0.7 * o.h_contact);
    EXPECT_LE(q.max_edge, 1.3 * o.h_max);
  }
}

TEST_P(MeshAtVelocity, AreasAndVolumesMatchTheGeometry) {
  const MeshOptions o = options();
  const Mesh m = generate_impact_mesh(o);
  const double radius = o.sphere_radius;
  const MeshQuality s = mesh_quality(m, Body::kSphere);
  // inscribed polygon: short by at most sum (chord^3 / (12 R)) <= (pi R) h_max^2 / (12 R^2) R^2
  const double facet = kPi * o.h_max * o.h_max / 12.0;
  EXPECT_LT(s.area, 0.5 * kPi * radius * radius);
  EXPECT_GT(s.area, 0.5 * kPi * radius * radius - 1.3 * facet);
  EXPECT_NEAR(s.volume / (4.0 / 3.0 * kPi * radius * radius * radius), 1.0, 5e-3);
  const MeshQuality w = mesh_quality(m, Body::kSubstrate);
  EXPECT_NEAR(w.area, o.substrate_radius * o.substrate_depth, 1e-12 * w.area);
  EXPECT_NEAR(w.volume, kPi * o.substrate_radius * o.substrate_radius * o.substrate_depth,
              1e-12 * w.volume);
}

TEST_P(MeshAtVelocity, ContactSizeIsHAlongTheSurfacesAndInDepth) {
  const MeshOptions o = options();
  const Mesh m = generate_impact_mesh(o);
  const double h = o.h_contact;
  // substrate surface segments inside the zone
  const auto& top = m.substrate_surface_nodes;
  for (std::size_t k = 0; k + 1 < top.size(); ++k) {
    if (m.r[static_cast<std::size_t>(top[k + 1])] > o.zone_radius) break;
    const double e = edge(m, top[k], top[k + 1]);
    EXPECT_GE(e, 0.7 * h);
    EXPECT_LE(e, 1.3 * h);
  }
  // sphere surface segments within arc length zone_radius of the lowest point
  const auto& surf = m.sphere_surface_nodes;
  double s = 0.0;
  for (std::size_t k = 0; k + 1 < surf.size() && s < o.zone_radius; ++k) {
    const double e = edge(m, surf[k], surf[k + 1]);
    s += e;
    EXPECT_GE(e, 0.7 * h);
    EXPECT_LE(e, 1.3 * h);
  }
  EXPECT_GE(s, o.zone_radius - 1.3 * h);
  // in depth: axis segments of both bodies within the zone depth of the contact
  for (const Body body : {Body::kSphere, Body::kSubstrate}) {
    std::vector<double> z;
    for (const int n : m.axis_nodes)
      if (m.node_body[static_cast<std::size_t>(n)] == body)
        z.push_back(m.z[static_cast<std::size_t>(n)]);
    std::sort(z.begin(), z.end());
    if (body == Body::kSubstrate) std::reverse(z.begin(), z.end());  // from the contact down
    const double z0 = z.front();
    int checked = 0;
    for (std::size_t k = 0; k + 1 < z.size() && std::abs(z[k + 1] - z0) <= o.zone_depth;
         ++k, ++checked) {
      const double e = std::abs(z[k + 1] - z[k]);
      EXPECT_GE(e, 0.7 * h);
      EXPECT_LE(e, 1.3 * h);
    }
    EXPECT_GE(checked, 3);
  }
}

// Conforming: every element edge is shared by two elements of its body, or lies on the body's
// boundary (the substrate's four sides; the sphere's surface circle and the axis). A hanging node
// (an edge split on one side only, e.g. a misplaced 3:1 transition) leaves an edge used once
// inside the body.
TEST_P(MeshAtVelocity, ElementsMeetEdgeToEdge) {
  const MeshOptions o = options();
  const Mesh m = generate_impact_mesh(o);
  std::map<std::pair<int, int>, int> uses;
  for (const auto& q : m.quads)
    for (std::size_t k = 0; k < 4; ++k) ++uses[std::minmax(q[k], q[(k + 1) % 4])];
  const double tol = 1e-9 * o.sphere_radius;
  const double zc = o.gap + o.sphere_radius;
  const auto on_boundary = [&](int n) {
    const auto i = static_cast<std::size_t>(n);
    const double r = m.r[i];
    const double z = m.z[i];
    if (r == 0.0) return true;
    if (m.node_body[i] == Body::kSphere)
      return std::abs(std::hypot(r, z - zc) - o.sphere_radius) <= tol;
    return z == 0.0 || z == -o.substrate_depth || r == o.substrate_radius;
  };
  int inner_once = 0;
  for (const auto& [e, count] : uses) {
    EXPECT_LE(count, 2);
    if (count == 1 && !(on_boundary(e.first) && on_boundary(e.second))) ++inner_once;
  }
  EXPECT_EQ(inner_once, 0);
}

INSTANTIATE_TEST_SUITE_P(PaperVelocities,
                         MeshAtVelocity,
                         ::testing::Combine(::testing::Values(0.1, 1.0, 5.0, 70.0),
                                            ::testing::Bool()));

// The contact surfaces of a mesh: the sphere's surface nodes and the substrate's, (r, z) each.
std::vector<std::pair<double, double>> contact_surfaces(const Mesh& m) {
  std::vector<std::pair<double, double>> p;
  for (const auto* nodes : {&m.sphere_surface_nodes, &m.substrate_surface_nodes})
    for (const int n : *nodes)
      p.emplace_back(m.r[static_cast<std::size_t>(n)], m.z[static_cast<std::size_t>(n)]);
  return p;
}

// Element updates per base step of one body, levels against the mesh's shortest element.
double updates(const Mesh& m, Body body) {
  const double shortest = std::min(mesh_quality(m, Body::kSphere).min_characteristic_length,
                                   mesh_quality(m, Body::kSubstrate).min_characteristic_length);
  return explicit_cost(m, body, shortest).updates;
}

// mesh.transitions = 1 merges fine columns 3:1 (docs/theory/mesh.md, "3:1 transitions") in the
// tensor-grid substrate, in the sphere's bottom ring below the refined depth and in its skin
// beyond the refined zone; the contact surfaces (slave nodes and master segments) stay exactly
// as they were. Paper case (5 m/s, tensor substrate; the sphere's ring lies within the refined
// depth): 2301 -> 1463 substrate elements, the sphere unchanged. 0.1 m/s (block substrate,
// unchanged): the sphere's h-wide columns end in the ring instead of running on through the core
// to its top, and its h-thin skin rows merge along the arc: 3250 -> 1794 sphere elements, 1144 ->
// 547 sphere updates per base step.
TEST(ImpactMesh, TransitionsKeepTheContactSurfacesAndCutTheFineColumns) {
  for (const double v : {0.1, 5.0, 70.0}) {
    const Mesh plain = generate_impact_mesh(options_at(v, false));
    const Mesh coarsened = generate_impact_mesh(options_at(v, true));
    EXPECT_EQ(contact_surfaces(plain), contact_surfaces(coarsened)) << v;
    const Body cut = v < 1.0 ? Body::kSphere : Body::kSubstrate;
    const Body kept = v < 1.0 ? Body::kSubstrate : Body::kSphere;
    EXPECT_EQ(mesh_quality(plain, kept).elements, mesh_quality(coarsened, kept).elements) << v;
    EXPECT_LT(mesh_quality(coarsened, cut).elements, 0.8 * mesh_quality(plain, cut).elements) << v;
    EXPECT_LT(updates(coarsened, cut), 0.8 * updates(plain, cut)) << v;
  }
}

// The sphere elements under the contact: within depth `depth` [m] of the surface and within
// the refined zone's arc length (zone_radius) of the lowest point, each as its sorted corner
// coordinates (r, z).
std::vector<std::vector<std::pair<double, double>>> sphere_elements_within(const Mesh& m,
                                                                           const MeshOptions& o,
                                                                           double depth) {
  const double zc = o.gap + o.sphere_radius;
  std::vector<std::vector<std::pair<double, double>>> out;
  for (std::size_t e = 0; e < m.quads.size(); ++e) {
    if (m.element_body[e] != Body::kSphere) continue;
    std::vector<std::pair<double, double>> corners;
    bool inside = true;
    for (const int n : m.quads[e]) {
      const auto i = static_cast<std::size_t>(n);
      const double polar = std::atan2(m.r[i], zc - m.z[i]);  // from the downward axis [rad]
      inside = inside && m.z[i] < zc &&
               o.sphere_radius - std::hypot(m.r[i], m.z[i] - zc) <= depth &&
               o.sphere_radius * polar <= (1.0 + 1e-9) * o.zone_radius;
      corners.emplace_back(m.r[i], m.z[i]);
    }
    std::sort(corners.begin(), corners.end());
    if (inside) out.push_back(corners);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The sphere's transitions start below the refined depth (zone_depth, like the substrate's zone)
// and beyond the refined zone's edge: every sphere element within the refined depth under the
// contact is the plain mesh's, node for node (at 70 m/s the whole bottom ring lies within it, so
// nothing merges there). The skin beyond the zone, also that thin, has fewer rows with the
// transitions (as the substrate's beside its zone), the top block's fewer columns.
TEST(ImpactMesh, SphereTransitionsLeaveTheRefinedDepthAsItWas) {
  for (const double v : {0.1, 1.0, 70.0}) {
    const MeshOptions plain = options_at(v, false);
    const auto within = [&](const MeshOptions& o) {
      return sphere_elements_within(generate_impact_mesh(o), o, (1.0 + 1e-9) * o.zone_depth);
    };
    const auto expected = within(plain);
    EXPECT_GT(expected.size(), 50U) << v;
    EXPECT_EQ(within(options_at(v, true)), expected) << v;
  }
}

// Beyond the refined zone the skin's rows merge along the arc (add_bottom_ring, add_right_block):
// at 0.1 m/s the top block, which takes the rows that reach Q' -> K', has fewer of them on the
// axis above the centre than the ring's n_t, and the thin skin's aspect ratio is gone.
TEST(ImpactMesh, SkinRowsMergeBeyondTheRefinedZone) {
  const auto top_axis_nodes = [](const MeshOptions& o) {
    const Mesh m = generate_impact_mesh(o);
    const double zc = o.gap + o.sphere_radius;
    int n = 0;
    for (int i = 0; i < m.num_nodes(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      n += m.node_body[k] == Body::kSphere && m.r[k] == 0.0 && m.z[k] > zc ? 1 : 0;
    }
    return n;
  };
  const MeshOptions plain = options_at(0.1, false);
  const MeshOptions swept = options_at(0.1, true);
  EXPECT_LT(top_axis_nodes(swept) + 5, top_axis_nodes(plain));
  double worst = 0.0;
  const Mesh m = generate_impact_mesh(swept);
  for (std::size_t e = 0; e < m.quads.size(); ++e) {
    std::array<double, 4> r{};
    std::array<double, 4> z{};
    for (std::size_t k = 0; k < 4; ++k) {
      r[k] = m.r[static_cast<std::size_t>(m.quads[e][k])];
      z[k] = m.z[static_cast<std::size_t>(m.quads[e][k])];
    }
    if (m.element_body[e] == Body::kSphere)
      worst = std::max(worst, quad_quality(r, z).aspect_ratio);
  }
  EXPECT_LT(worst, 12.0);  // 21 with the ring's transitions only
}

// The refined zone is 1.5 a wide but only mesh.refine_depth x a deep (0.5 a by default).
TEST(ImpactMesh, RefinedZoneDepthFollowsTheConfig) {
  ImpactConfig config;
  config.impact.velocity = 30.0;
  const double a = predicted_contact_radius(config);
  EXPECT_DOUBLE_EQ(mesh_options_for(config).zone_depth, 0.5 * a);
  config.mesh.refine_depth = 1.5;
  EXPECT_DOUBLE_EQ(mesh_options_for(config).zone_depth, 1.5 * a);
}

// The substrate layout is the cheaper to integrate with element subcycling: for small contacts
// the three blocks, whose elements grow away from the zone in both directions; a tensor grid
// there would carry the zone's h-wide columns down to the base and its h-high rows out to r = W,
// thin elements with nearly the contact squares' stable step. So far from the zone no substrate
// element may be as thin as 1.25 h (the tensor grid: h; the blocks: >= 1.5 h at 3.4 zone radii).
TEST(ImpactMesh, SubstrateElementsFarFromASmallContactAreNotThin) {
  for (const double v : {0.01, 0.1, 1.0}) {
    const MeshOptions o = options_at(v);
    const Mesh m = generate_impact_mesh(o);
    const double far = 3.0 * o.zone_radius;
    int thin_far = 0;
    for (std::size_t e = 0; e < m.quads.size(); ++e) {
      if (m.element_body[e] != Body::kSubstrate) continue;
      std::array<double, 4> r{};
      std::array<double, 4> z{};
      for (std::size_t k = 0; k < 4; ++k) {
        r[k] = m.r[static_cast<std::size_t>(m.quads[e][k])];
        z[k] = m.z[static_cast<std::size_t>(m.quads[e][k])];
      }
      const double rc = 0.25 * (r[0] + r[1] + r[2] + r[3]);
      const double zc = 0.25 * (z[0] + z[1] + z[2] + z[3]);
      if (std::hypot(rc, zc) > far && quad_quality(r, z).width < 1.25 * o.h_contact) ++thin_far;
    }
    EXPECT_EQ(thin_far, 0) << "v = " << v;
  }
}

// The explicit step is set by the smallest characteristic length (stable_time_step.hpp). The
// uniform h x h contact squares of the substrate (the axis column included, whose hoop term
// shortens L_e) are the intended limit: no sphere element may be much smaller.
TEST(ImpactMesh, SmallestCharacteristicLengthIsTheContactElements) {
  for (const double v : {0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 40.0, 70.0, 100.0, 150.0, 200.0}) {
    for (const bool transitions : {false, true}) {
      const Mesh m = generate_impact_mesh(options_at(v, transitions));
      double sphere = 1e30;
      double substrate = 1e30;
      for (std::size_t e = 0; e < m.quads.size(); ++e) {
        double r[4];
        double z[4];
        for (std::size_t k = 0; k < 4; ++k) {
          r[k] = m.r[static_cast<std::size_t>(m.quads[e][k])];
          z[k] = m.z[static_cast<std::size_t>(m.quads[e][k])];
        }
        const double le = characteristic_length(quad4_geometry(r, z));
        (m.element_body[e] == Body::kSphere ? sphere : substrate) =
            std::min(m.element_body[e] == Body::kSphere ? sphere : substrate, le);
      }
      EXPECT_GE(sphere, 0.92 * substrate) << "v = " << v << ", transitions " << transitions;
    }
  }
}

TEST(MeshOptionsFor, SizesFromThePredictedContactRadius) {
  ImpactConfig config;
  const double a = predicted_contact_radius(config);
  MeshOptions o = mesh_options_for(config);
  EXPECT_DOUBLE_EQ(o.h_contact, std::min(config.mesh.h_min, a / config.mesh.contact_elements));
  EXPECT_DOUBLE_EQ(o.zone_radius, config.mesh.refine_factor * a);
  EXPECT_DOUBLE_EQ(o.zone_depth, config.mesh.refine_depth * a);
  EXPECT_DOUBLE_EQ(o.growth, config.mesh.growth);
  EXPECT_DOUBLE_EQ(o.h_max, config.mesh.h_max);
  // slow impact: the contact-elements bound takes over; 0 disables it
  config.impact.velocity = 0.1;
  const double a_slow = predicted_contact_radius(config);
  o = mesh_options_for(config);
  EXPECT_DOUBLE_EQ(o.h_contact, a_slow / config.mesh.contact_elements);
  EXPECT_LT(o.h_contact, config.mesh.h_min);
  config.mesh.contact_elements = 0.0;
  EXPECT_DOUBLE_EQ(mesh_options_for(config).h_contact, config.mesh.h_min);
}

TEST(ImpactMesh, RefinedZoneGrowsWithVelocity) {
  const MeshOptions slow = options_at(0.1);
  const MeshOptions fast = options_at(70.0);
  EXPECT_GT(fast.zone_radius, 10.0 * slow.zone_radius);
  auto fine_extent = [](const MeshOptions& o) {
    const Mesh m = generate_impact_mesh(o);
    const auto& top = m.substrate_surface_nodes;
    double r = 0.0;
    for (std::size_t k = 0; k + 1 < top.size(); ++k) {
      if (edge(m, top[k], top[k + 1]) > 1.3 * o.h_contact) break;
      r = m.r[static_cast<std::size_t>(top[k + 1])];
    }
    return r;
  };
  const double r_slow = fine_extent(slow);
  const double r_fast = fine_extent(fast);
  EXPECT_GE(r_slow, slow.zone_radius - slow.h_contact);
  EXPECT_GE(r_fast, fast.zone_radius - fast.h_contact);
  EXPECT_GT(r_fast, 10.0 * r_slow);
}

TEST(ImpactMesh, ElementCountScalesSensibly) {
  MeshOptions o = options_at(5.0);
  const Mesh base = generate_impact_mesh(o);
  // paper default: a few thousand elements per body (1444 and 2880 measured; the run time of the
  // paper case scales with them)
  EXPECT_LE(mesh_quality(base, Body::kSphere).elements, 2000);
  EXPECT_LE(mesh_quality(base, Body::kSubstrate).elements, 3200);
  // halving h in a fixed zone roughly quadruples the zone's elements (plus log-many rings)
  o.h_contact *= 0.5;
  const Mesh fine = generate_impact_mesh(o);
  const double ratio = static_cast<double>(fine.num_elements()) / base.num_elements();
  EXPECT_GT(ratio, 2.0);
  EXPECT_LT(ratio, 4.5);
}

TEST(ImpactMesh, ScalingAllLengthsScalesTheMesh) {
  const MeshOptions o = options_at(5.0);
  MeshOptions small = o;
  const double f = 1.0 / 14.0;
  small.sphere_radius *= f;
  small.gap *= f;
  small.substrate_radius *= f;
  small.substrate_depth *= f;
  small.h_contact *= f;
  small.zone_radius *= f;
  small.zone_depth *= f;
  small.h_max *= f;
  const Mesh a = generate_impact_mesh(o);
  const Mesh b = generate_impact_mesh(small);
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  ASSERT_EQ(a.num_elements(), b.num_elements());
  EXPECT_EQ(a.quads, b.quads);
  EXPECT_EQ(a.element_body, b.element_body);
  EXPECT_EQ(a.axis_nodes, b.axis_nodes);
  EXPECT_EQ(a.base_nodes, b.base_nodes);
  EXPECT_EQ(a.sphere_surface_nodes, b.sphere_surface_nodes);
  EXPECT_EQ(a.substrate_surface_nodes, b.substrate_surface_nodes);
  for (std::size_t n = 0; n < a.r.size(); ++n) {
    EXPECT_NEAR(b.r[n], f * a.r[n], 1e-9 * small.sphere_radius);
    EXPECT_NEAR(b.z[n], f * a.z[n], 1e-9 * small.sphere_radius);
  }
}

TEST(GradedPositions, UniformZoneThenGeometricGrowthEndingExactly) {
  const double h = 0.25e-3;
  const auto x = graded_positions(70e-3, h, 8e-3, 1.15, 5e-3);
  EXPECT_EQ(x.front(), 0.0);
  EXPECT_DOUBLE_EQ(x.back(), 70e-3);
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double s = x[k + 1] - x[k];
    if (x[k + 1] <= 8e-3 + 1e-12) {
      EXPECT_NEAR(s, h, 1e-15);
    }
    EXPECT_GE(s, h * (1 - 1e-12));
    EXPECT_LE(s, 1.25 * 5e-3);
    if (k > 0) {
      const double prev = x[k] - x[k - 1];
      EXPECT_LE(s / prev, 1.15 * 1.25);  // the rescaled growth stays near the ratio
      EXPECT_GE(s / prev, 1.0 - 1e-12);
    }
  }
  // all uniform when the zone covers the length
  const auto u = graded_positions(1e-3, 0.1e-3, 2e-3, 1.2, 1e-3);
  EXPECT_EQ(u.size(), 11u);
}

TEST(MeshOptionsValidation, NamesTheBadField) {
  MeshOptions o;
  o.h_contact = -1.0;
  try {
    generate_impact_mesh(o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mesh.h_contact"), std::string::npos) << e.what();
  }
  o = MeshOptions{};
  o.growth = 0.9;
  EXPECT_THROW(generate_impact_mesh(o), InputError);
  o = MeshOptions{};
  o.h_max = 0.1e-3;
  EXPECT_THROW(generate_impact_mesh(o), InputError);
}

}  // namespace
}  // namespace corlab::fem
