// The smallest dihedral angle, the shape measure behind the half ball's mesh test
// (tests/solver/tet_hertz_test.cpp), on shapes whose angles are known.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/tet_quality.hpp"
#include "mesh/tet_refinement.hpp"

namespace fosls {
namespace {

TEST(TetQuality, KnownShapes) {
  const TetMesh regular({Point3(1, 1, 1), Point3(1, -1, -1), Point3(-1, 1, -1), Point3(-1, -1, 1)},
                        {{0, 1, 2, 3}}, {}, {});
  EXPECT_NEAR(smallest_dihedral_angle(regular), std::acos(1.0 / 3.0) * 180.0 / M_PI, 1e-10);
  EXPECT_NEAR(smallest_dihedral_angle(make_box({1, 1, 1}, Point3(1, 1, 1))), 45.0, 1e-10);
  const TetMesh flat({Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0), Point3(0.3, 0.3, 1e-3)},
                     {{0, 1, 2, 3}}, {}, {});
  EXPECT_LT(smallest_dihedral_angle(flat), 0.5);
}

}  // namespace
}  // namespace fosls
