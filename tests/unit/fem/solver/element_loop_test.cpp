// The solver's hot loops (src/fem/solver/element_loop.cpp) on small structured blocks: the
// gather, lane and scatter bookkeeping against one element at a time, an exact uniform-strain
// patch, the inverted element's index, the subcycled pass against the plain one, the nodal
// updates against their formulas, and every SIMD level against the baseline.
// SPDX-License-Identifier: BSD-3-Clause
#include "fem/solver/element_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "corlab/fem/kernels/axisym_quad4.hpp"
#include "corlab/fem/solver/simd_level.hpp"
#include "corlab/materials/material.hpp"
#include "support/fem_test_meshes.hpp"

namespace corlab::fem::solver {
namespace {

/// An elastic steel-like body (E 210 GPa, nu 0.3, rho 7850 kg/m^3), hourglass 0.05, bulk
/// viscosity as given [-].
BodyParams steel(double b1, double b2) {
  Material mat;
  mat.youngs_modulus = 210e9;
  mat.poisson_ratio = 0.3;
  mat.density = 7850.0;
  BodyParams p;
  p.material = material_point(mat);
  p.density = mat.density;
  p.wave_speed = mat.dilatational_wave_speed();
  p.hourglass = 0.05;
  p.b1 = b1;
  p.b2 = b2;
  return p;
}

/// A structured nr x nz block of 1 x 1 mm elements from r = 1 mm (off the axis) with its nodal
/// arrays; nodes jittered by `jitter` (a fraction of h) so that the elements are not all alike.
struct Block {
  Mesh mesh;
  ElementConstants ec;
  ElementState es;
  std::vector<double> r, z, vr, vz, fr, fz, m, im, free_r, free_z, sphere;

  Block(int nr, int nz, double jitter) {
    testing::add_block(mesh, Body::kSubstrate, 1e-3, 0.0, nr * 1e-3, nz * 1e-3, nr, nz);
    for (int e = 0; e < mesh.num_elements(); ++e) ec.push_back(mesh.quads[e], e);
    es.resize(static_cast<std::size_t>(ec.size()));
    const int n = mesh.num_nodes();
    r = mesh.r;
    z = mesh.z;
    for (int i = 0; i < n; ++i) {
      r[i] += jitter * 1e-3 * std::sin(1.7 * i);
      z[i] += jitter * 1e-3 * std::cos(2.3 * i);
    }
    for (auto* v : {&vr, &vz, &fr, &fz}) v->assign(n, 0.0);
    for (auto* v : {&m, &im, &free_r, &free_z}) v->assign(n, 1.0);
    sphere.assign(n, 0.0);
  }
  NodalArrays arrays() {
    return {r.data(), z.data(),  vr.data(),     vz.data(),     fr.data(),    fz.data(),
            m.data(), im.data(), free_r.data(), free_z.data(), sphere.data()};
  }
  /// Velocities of a smooth, non-uniform deformation (compression, shear and swirl) [m/s].
  void deform() {
    for (std::size_t i = 0; i < r.size(); ++i) {
      vr[i] = 0.3 * std::sin(900.0 * z[i]) + 0.1 * r[i] * 1e3;
      vz[i] = -2.0 * z[i] * 1e3 + 0.2 * std::cos(700.0 * r[i]);
    }
  }
};

constexpr double kDt = 1e-8;  // [s], well below the 1 mm elements' stable step (~1.7e-7 s)

TEST(ElementLoop, BlocksGiveWhatEachElementGivesAlone) {
  // 37 elements: two full blocks of 16 and a partial one; every lane's gather, stress and
  // scatter must be its own element's.
  const BodyParams p = steel(0.06, 1.2);
  Block all(37, 1, 0.1);
  all.deform();
  Block one = all;
  ElementSums sums_all;
  element_loop(SimdLevel::kBaseline, {p, all.ec, all.es, 0, 37, all.arrays(), kDt}, sums_all);
  ElementSums sums_one;
  for (int e = 0; e < 37; ++e) {
    element_loop(SimdLevel::kBaseline, {p, one.ec, one.es, e, e + 1, one.arrays(), kDt}, sums_one);
  }
  for (int e = 0; e < 37; ++e) {
    ASSERT_EQ(all.es.srr[e], one.es.srr[e]) << "element " << e;
    ASSERT_EQ(all.es.szz[e], one.es.szz[e]) << "element " << e;
    ASSERT_EQ(all.es.srz[e], one.es.srz[e]) << "element " << e;
    ASSERT_EQ(all.es.qr[e], one.es.qr[e]) << "element " << e;
  }
  for (std::size_t i = 0; i < all.fr.size(); ++i) {
    ASSERT_NEAR(all.fr[i], one.fr[i], 1e-12 * std::abs(all.fr[i]) + 1e-30) << "node " << i;
    ASSERT_NEAR(all.fz[i], one.fz[i], 1e-12 * std::abs(all.fz[i]) + 1e-30) << "node " << i;
  }
  EXPECT_EQ(sums_all.dt_min, sums_one.dt_min);
  EXPECT_NEAR(sums_all.internal_work, sums_one.internal_work,
              1e-12 * std::abs(sums_one.internal_work));
  EXPECT_GT(std::abs(sums_all.internal_work), 0.0);
  EXPECT_EQ(sums_all.bad_element, -1);
}

TEST(ElementLoop, UniformStrainRateGivesTheSameStressInEveryElement) {
  // vz = -c z (z the nodes' positions at the step's end), vr = 0: on the mid-step geometry
  // z_mid = z (1 + c dt / 2) the rate is d_zz = -c / (1 + c dt / 2), uniform, d_rr = d_tt = 0
  // (uniaxial strain), exact for the one-point quad whatever its shape. Without bulk viscosity
  // the stress increment is the elastic one: s_zz = (lambda + 2G) d_zz dt, s_rr = s_tt = lambda
  // d_zz dt.
  const BodyParams p = steel(0.0, 0.0);
  Block b(20, 3, 0.15);
  const double c = 1e3;  // [1/s]
  for (std::size_t i = 0; i < b.r.size(); ++i) b.vz[i] = -c * b.z[i];
  ElementSums sums;
  element_loop(SimdLevel::kBaseline, {p, b.ec, b.es, 0, b.ec.size(), b.arrays(), kDt}, sums);
  const double g = p.material.shear_modulus;
  const double lam = p.material.bulk_modulus - 2.0 * g / 3.0;
  const double de = -c * kDt / (1.0 + 0.5 * c * kDt);
  for (int e = 0; e < b.ec.size(); ++e) {
    ASSERT_NEAR(b.es.szz[e], (lam + 2.0 * g) * de, 1e-9 * (lam + 2.0 * g) * c * kDt) << e;
    ASSERT_NEAR(b.es.srr[e], lam * de, 1e-9 * lam * c * kDt) << e;
    ASSERT_NEAR(b.es.stt[e], lam * de, 1e-9 * lam * c * kDt) << e;
    ASSERT_NEAR(b.es.srz[e], 0.0, 1e-9 * lam * c * kDt) << e;
  }
}

TEST(ElementLoop, NamesTheInvertedElementNotItsBlock) {
  // Elements 0..39 in blocks of 16: invert element 21 (lane 5 of the second block) by moving
  // one of its nodes through the element.
  const BodyParams p = steel(0.06, 1.2);
  for (const int bad : {0, 13, 21, 39}) {
    Block b(40, 1, 0.0);
    const std::array<int, 4> nd = b.ec.nodes(bad);
    b.r[nd[2]] = b.r[nd[0]] - 0.5e-3;  // the far corner crosses the element's near edge
    b.z[nd[2]] = b.z[nd[0]] - 0.5e-3;
    ElementSums sums;
    element_loop(SimdLevel::kBaseline, {p, b.ec, b.es, 0, 40, b.arrays(), kDt}, sums);
    EXPECT_EQ(sums.bad_element, bad);
    EXPECT_FALSE(sums.omega_min > 0.0);
  }
}

TEST(ElementLoop, SubcycledPassWithPositionsFromTheVelocitiesIsThePlainPass) {
  // A level-0 subcycled pass whose stored positions are x - dt v takes the rate (x - x_prev)/dt
  // = v: the plain pass's, up to the round-off of that difference; its viscous work is the
  // trapezoid from a zero start, so only the stresses and forces are compared.
  const BodyParams p = steel(0.06, 1.2);
  Block plain(18, 2, 0.1);
  plain.deform();
  Block sub = plain;
  for (int i = 0; i < 4; ++i) {
    sub.es.r_prev[i].resize(sub.ec.size());
    sub.es.z_prev[i].resize(sub.ec.size());
    for (int e = 0; e < sub.ec.size(); ++e) {
      const int n = sub.ec.corner[i][e];
      sub.es.r_prev[i][e] = sub.r[n] - kDt * sub.vr[n];
      sub.es.z_prev[i][e] = sub.z[n] - kDt * sub.vz[n];
    }
  }
  sub.es.bv.assign(sub.ec.size(), 0.0);
  ElementSums a;
  ElementSums s;
  element_loop(SimdLevel::kBaseline,
               {p, plain.ec, plain.es, 0, plain.ec.size(), plain.arrays(), kDt}, a);
  element_loop_subcycled(SimdLevel::kBaseline,
                         {p, sub.ec, sub.es, 0, sub.ec.size(), sub.arrays(), kDt}, 1.0, true, s);
  const double scale = std::abs(plain.es.szz[0]);
  ASSERT_GT(scale, 0.0);
  for (int e = 0; e < plain.ec.size(); ++e) {
    ASSERT_NEAR(sub.es.szz[e], plain.es.szz[e], 1e-6 * scale) << e;
    ASSERT_NEAR(sub.es.srz[e], plain.es.srz[e], 1e-6 * scale) << e;
    ASSERT_EQ(sub.es.r_prev[0][e], sub.r[sub.ec.corner[0][e]]) << "stored positions advanced";
  }
  EXPECT_NEAR(s.dt_min, a.dt_min, 1e-9 * a.dt_min);
}

TEST(ElementLoop, EverySimdLevelAgreesWithTheBaseline) {
  const BodyParams p = steel(0.06, 1.2);
  Block base(33, 2, 0.1);
  base.deform();
  ElementSums sb;
  Block ref = base;
  element_loop(SimdLevel::kBaseline, {p, ref.ec, ref.es, 0, ref.ec.size(), ref.arrays(), kDt}, sb);
  for (const SimdLevel level : supported_simd_levels()) {
    Block b = base;
    ElementSums s;
    element_loop(level, {p, b.ec, b.es, 0, b.ec.size(), b.arrays(), kDt}, s);
    for (std::size_t i = 0; i < b.fr.size(); ++i) {
      ASSERT_NEAR(b.fr[i], ref.fr[i], 1e-12 * std::abs(ref.fr[i]) + 1e-6) << to_string(level);
      ASSERT_NEAR(b.fz[i], ref.fz[i], 1e-12 * std::abs(ref.fz[i]) + 1e-6) << to_string(level);
    }
    EXPECT_NEAR(s.internal_work, sb.internal_work, 1e-12 * std::abs(sb.internal_work));
  }
}

TEST(NodeUpdate, IsTheCentralDifferenceFormula) {
  // Three nodes: free, fixed in r, fixed; the second and third on the sphere.
  std::vector<double> r{1.0, 2.0, 3.0}, z{0.5, 0.25, -1.0}, vr{1.0, -2.0, 0.0}, vz{0.5, 1.0, 0.0};
  std::vector<double> fr{10.0, 20.0, 30.0}, fz{-5.0, 4.0, 8.0}, m{2.0, 4.0, 1.0};
  std::vector<double> im{0.5, 0.25, 1.0}, free_r{1.0, 0.0, 0.0}, free_z{1.0, 1.0, 0.0};
  std::vector<double> sphere{0.0, 1.0, 1.0};
  const std::vector<double> r0 = r, z0 = z, vr0 = vr, vz0 = vz, fr0 = fr, fz0 = fz;
  const double dt = 0.1, dt_avg = 0.2;
  for (const SimdLevel level : supported_simd_levels()) {
    r = r0, z = z0, vr = vr0, vz = vz0, fr = fr0, fz = fz0;
    const NodalArrays x{r.data(), z.data(),  vr.data(),     vz.data(),     fr.data(),    fz.data(),
                        m.data(), im.data(), free_r.data(), free_z.data(), sphere.data()};
    const NodeSums ns = node_update(level, x, 3, dt, dt_avg);
    double ke = 0.0, ke_sphere = 0.0, p_sphere = 0.0, mz_sphere = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double ur = (vr0[i] + dt_avg * fr0[i] / m[i]) * free_r[i];
      const double uz = (vz0[i] + dt_avg * fz0[i] / m[i]) * free_z[i];
      EXPECT_DOUBLE_EQ(vr[i], ur) << i;
      EXPECT_DOUBLE_EQ(vz[i], uz) << i;
      EXPECT_DOUBLE_EQ(r[i], r0[i] + dt * ur) << i;
      EXPECT_DOUBLE_EQ(z[i], z0[i] + dt * uz) << i;
      EXPECT_EQ(fr[i], 0.0);
      EXPECT_EQ(fz[i], 0.0);
      const double k = 0.5 * m[i] * (vr0[i] * ur + vz0[i] * uz);  // product form: v^-1/2 . v^+1/2
      ke += k;
      ke_sphere += k * sphere[i];
      p_sphere += m[i] * uz * sphere[i];
      mz_sphere += m[i] * z[i] * sphere[i];
    }
    EXPECT_DOUBLE_EQ(ns.ke, ke);
    EXPECT_DOUBLE_EQ(ns.ke_sphere, ke_sphere);
    EXPECT_DOUBLE_EQ(ns.p_sphere, p_sphere);
    EXPECT_DOUBLE_EQ(ns.mz_sphere, mz_sphere);
  }
}

TEST(NodeUpdate, SubcycledNodesMoveOverTheirOwnStep) {
  // Levels 0 and 1 (scales 1, 2): a node moves over dt x its scale; in the contiguous pass a node
  // above the due level has no force and stays; the listed pass moves only the listed nodes.
  std::vector<double> r{0.0, 0.0}, z{1.0, 2.0}, vr{0.0, 0.0}, vz{1.0, 1.0}, fr{0.0, 0.0};
  std::vector<double> fz{2.0, 0.0}, m{1.0, 1.0}, im{1.0, 1.0}, one{1.0, 1.0}, sphere{1.0, 1.0};
  const std::vector<double> scale{1.0, 2.0}, step{0.1, 0.2};
  const std::vector<int> order{0, 1};
  const NodalArrays x{r.data(), z.data(),  vr.data(),  vz.data(),  fr.data(),    fz.data(),
                      m.data(), im.data(), one.data(), one.data(), sphere.data()};
  const SubcycledNodes a{x, order.data(), 1, step.data(), scale.data(), 0.5};
  const NodeSums due = node_update_due(SimdLevel::kBaseline, a, 2, 0);
  EXPECT_DOUBLE_EQ(vz[0], 1.0 + 0.5 * 2.0);
  EXPECT_DOUBLE_EQ(z[0], 1.0 + 0.1 * 2.0);
  EXPECT_DOUBLE_EQ(z[1], 2.0) << "level 1 is not due at level 0";
  EXPECT_DOUBLE_EQ(due.mz_sphere, 1.0 + 2.0) << "sum m z before the drift";
  const SubcycledNodes listed{x, order.data() + 1, 1, step.data(), scale.data(), 0.5};
  node_update_subcycled(SimdLevel::kBaseline, listed);
  EXPECT_DOUBLE_EQ(z[1], 2.0 + 0.2 * 1.0) << "node 1 over its own step 2 dt";
  EXPECT_DOUBLE_EQ(z[0], 1.2) << "node 0 not listed";
}

}  // namespace
}  // namespace corlab::fem::solver
