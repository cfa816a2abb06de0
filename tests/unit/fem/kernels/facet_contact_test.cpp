// Node-on-facet projection (facet_contact.hpp): exact on a flat tilted facet, weights that sum
// to one and reproduce the closest point, the gap's sign, and a warped facet's closest point.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/kernels/facet_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace corlab::fem {
namespace {

TEST(FacetContact, ProjectsOnAFlatTiltedFacet) {
  // A 2 x 1 rectangle in the plane z = 0.1 x, corners counter-clockwise seen from above.
  const double c[4][3] = {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.2}, {2.0, 1.0, 0.2}, {0.0, 1.0, 0.0}};
  const double p[3] = {0.5, 0.25, -0.3};
  const FacetProjection f = project_on_facet(p, c);
  const double n[3] = {-0.1 / std::sqrt(1.01), 0.0, 1.0 / std::sqrt(1.01)};
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(f.normal[d], n[d], 1e-12);
  // Signed distance to the plane 0.1 x - z = 0 along the upward normal.
  EXPECT_NEAR(f.gap, (p[2] - 0.1 * p[0]) / std::sqrt(1.01), 1e-12);
  EXPECT_LT(f.gap, 0.0);
  EXPECT_TRUE(on_facet(f));
  double sum = 0.0;
  double x[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < 4; ++i) {
    sum += f.weight[i];
    for (int d = 0; d < 3; ++d) x[d] += f.weight[i] * c[i][d];
  }
  EXPECT_NEAR(sum, 1.0, 1e-14);
  // The closest point plus gap x normal is the slave.
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(x[d] + f.gap * f.normal[d], p[d], 1e-12);
}

TEST(FacetContact, WarpedFacetClosestPointIsOrthogonal) {
  // One corner raised: a hyperbolic paraboloid.
  const double c[4][3] = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 1.0, 0.3}, {0.0, 1.0, 0.0}};
  const double p[3] = {0.7, 0.6, 0.5};
  const FacetProjection f = project_on_facet(p, c);
  double x[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < 4; ++i)
    for (int d = 0; d < 3; ++d) x[d] += f.weight[i] * c[i][d];
  // p - x is along the normal: its tangential part vanishes.
  const double r[3] = {p[0] - x[0], p[1] - x[1], p[2] - x[2]};
  const double along = r[0] * f.normal[0] + r[1] * f.normal[1] + r[2] * f.normal[2];
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(r[d], along * f.normal[d], 1e-10);
  EXPECT_NEAR(f.gap, along, 1e-14);
  EXPECT_GT(f.gap, 0.0);
}

TEST(FacetContact, PointsBeyondTheFacetAreFlagged) {
  const double c[4][3] = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {0.0, 1.0, 0.0}};
  const double p[3] = {1.5, 0.5, -0.01};
  const FacetProjection f = project_on_facet(p, c);
  EXPECT_FALSE(on_facet(f));
  EXPECT_NEAR(f.xi, 2.0, 1e-12);
}

}  // namespace
}  // namespace corlab::fem
