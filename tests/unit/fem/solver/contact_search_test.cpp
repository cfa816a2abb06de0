// The cursor search of contact_search.hpp on a flat and a kinked master polyline.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/fem/solver/contact_search.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace corlab::fem {
namespace {

// Master surface z = 0 at r = 0, 1, 2, 3, 4 (nodes 0-4) [m].
struct Flat {
  std::vector<double> r{0.0, 1.0, 2.0, 3.0, 4.0};
  std::vector<double> z{0.0, 0.0, 0.0, 0.0, 0.0};
  std::vector<int> masters{0, 1, 2, 3, 4};
};

TEST(ContactSearch, InitialSegmentIsTheOneUnderTheSlave) {
  const Flat f;
  EXPECT_EQ(initial_segment(f.r.data(), f.masters, 0.0), 0);
  EXPECT_EQ(initial_segment(f.r.data(), f.masters, 1.5), 1);
  EXPECT_EQ(initial_segment(f.r.data(), f.masters, 3.9), 3);
  EXPECT_EQ(initial_segment(f.r.data(), f.masters, 9.0), 3);  // beyond the end: last segment
}

TEST(ContactSearch, WalksFromAStaleCursorInBothDirections) {
  const Flat f;
  const ContactCandidate right = find_contact(f.r.data(), f.z.data(), f.masters, 3.25, -0.1, 0);
  EXPECT_EQ(right.segment, 3);
  EXPECT_TRUE(right.active);
  EXPECT_NEAR(right.projection.gap, -0.1, 1e-15);
  EXPECT_NEAR(right.projection.xi, 0.25, 1e-15);
  const ContactCandidate left = find_contact(f.r.data(), f.z.data(), f.masters, 0.5, -0.1, 3);
  EXPECT_EQ(left.segment, 0);
  EXPECT_NEAR(left.projection.xi, 0.5, 1e-15);
}

TEST(ContactSearch, AboveTheSurfaceIsInactive) {
  const Flat f;
  const ContactCandidate c = find_contact(f.r.data(), f.z.data(), f.masters, 1.5, 0.01, 1);
  EXPECT_FALSE(c.active);
  EXPECT_EQ(c.segment, 1);
  EXPECT_GT(c.projection.gap, 0.0);
}

TEST(ContactSearch, BeyondTheLastNodeIsOffTheSurface) {
  const Flat f;
  // Below z = 0 but past r = 4: no master segment under it, so no contact force.
  const ContactCandidate off = find_contact(f.r.data(), f.z.data(), f.masters, 4.5, -0.1, 3);
  EXPECT_FALSE(off.active);
  // Within the round-off tolerance of the last node: still on, xi clamped to 1.
  const ContactCandidate on = find_contact(f.r.data(), f.z.data(), f.masters, 4.0 + 1e-12, -0.1, 3);
  EXPECT_TRUE(on.active);
  EXPECT_EQ(on.projection.xi, 1.0);
}

TEST(ContactSearch, ConvexCornerKeepsTheCurrentSegment) {
  // A ridge at node 1: (0,0) -> (1,0.5) -> (2,0). A slave just below the peak projects past the
  // end of segment 0 and before the start of segment 1; it stays on the segment it was on.
  const std::vector<double> r{0.0, 1.0, 2.0};
  const std::vector<double> z{0.0, 0.5, 0.0};
  const std::vector<int> masters{0, 1, 2};
  const ContactCandidate c = find_contact(r.data(), z.data(), masters, 1.0, 0.49, 0);
  EXPECT_EQ(c.segment, 0);
  EXPECT_TRUE(c.active);
  const ContactCandidate d = find_contact(r.data(), z.data(), masters, 1.0, 0.49, 1);
  EXPECT_EQ(d.segment, 1);
  EXPECT_TRUE(d.active);
}

}  // namespace
}  // namespace corlab::fem
