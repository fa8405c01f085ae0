// BoundExtrapolation: Anderson's acceleration of Coulomb's fixed point on the slip bounds
// (solvers/bound_extrapolation.hpp, docs/method.md §8.4), on affine maps G(s) = c + M s whose
// fixed point and contraction are known.
#include "solvers/bound_extrapolation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace fosls {
namespace {

/// G(s) = c + M s with M = Q diag(rates) Qᵀ, Q a rotation mixing all entries.
struct AffineMap {
  Eigen::MatrixXd m;
  Vector c;
  AffineMap(const Eigen::Vector3d& rates, const Vector& constant) : c(constant) {
    const Eigen::Matrix3d q = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, 1.0, 0.0).normalized()))
                                  .toRotationMatrix();
    m = q * rates.asDiagonal() * q.transpose();
  }
  Vector operator()(const Vector& s) const { return c + m * s; }
  Vector fixed_point() const {
    return (Eigen::MatrixXd::Identity(3, 3) - m).partialPivLu().solve(c);
  }
};

/// Updates until s is within 1e-10 of the fixed point (at most 200); `depth` 0 is plain.
int updates_to_fixed_point(const AffineMap& map, int depth) {
  BoundExtrapolation extrapolation(depth);
  const Vector target = map.fixed_point();
  Vector s = Vector::Zero(3);
  for (int k = 1; k <= 200; ++k) {
    const Vector g = map(s);
    s = depth == 0 ? g : extrapolation.next(s, g);
    EXPECT_TRUE((s.array() >= 0.0).all());
    if ((s - target).norm() <= 1e-10 * target.norm()) return k;
  }
  return 201;
}

TEST(BoundExtrapolation, ASlowFixedPointIsReachedInAFractionOfThePlainUpdates) {
  // The wedge's rate, 0.65 per update, in one direction; both signs in the others.
  const AffineMap map({0.65, 0.5, -0.45}, Vector::Constant(3, 1.0));
  ASSERT_TRUE((map.fixed_point().array() > 0.0).all());
  const int plain = updates_to_fixed_point(map, 0), extrapolated = updates_to_fixed_point(map, 2);
  EXPECT_GE(plain, 50);
  EXPECT_LE(extrapolated, 10) << "plain " << plain;
}

TEST(BoundExtrapolation, AFastFixedPointKeepsThePlainUpdates) {
  const AffineMap map({0.1, 0.05, -0.08}, Vector::Constant(3, 1.0));
  BoundExtrapolation extrapolation(2);
  Vector s = Vector::Zero(3), plain = s;
  for (int k = 0; k < 8; ++k) {
    s = extrapolation.next(s, map(s));
    plain = map(plain);
    EXPECT_EQ(s, plain) << "update " << k;  // bit for bit: no extrapolation happened
  }
}

TEST(BoundExtrapolation, AnEdgeOutOfContactGetsNoBoundAndNoneIsNegative) {
  BoundExtrapolation extrapolation(2);
  // Bounds shrinking slowly towards 0 on edge 1 (an extrapolation of them may fall below zero,
  // which is clipped) and growing on edge 0; edge 2 has g = 0 throughout.
  Vector s(3), g(3);
  s << 1.0, 1.0, 0.0;
  for (int k = 0; k < 4; ++k) {
    g << 2.0 - 0.9 * (2.0 - s[0]), 0.9 * s[1] - 0.05, 0.0;
    s = extrapolation.next(s, g);
    EXPECT_GE(s[1], 0.0);
    EXPECT_EQ(s[2], 0.0);
  }
}

TEST(BoundExtrapolation, AChangedContactSetStartsAfresh) {
  const AffineMap map({0.65, 0.5, -0.45}, Vector::Constant(3, 1.0));
  BoundExtrapolation extrapolation(2);
  Vector s = Vector::Zero(3);
  for (int k = 0; k < 3; ++k) s = extrapolation.next(s, map(s));
  // The first edge leaves contact: the update is G itself, not a combination with the history.
  Vector g = map(s);
  g[0] = 0.0;
  EXPECT_EQ(extrapolation.next(s, g), g);
}

}  // namespace
}  // namespace fosls
