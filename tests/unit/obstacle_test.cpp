// The rigid obstacles of both dimensions (assembly/problem_data.hpp): a plane, a ball and a gap
// function seen from a boundary point along the body's normal or the obstacle's, and the one
// cap on large gaps. A 2D configuration and the same one in the plane z = 0 of 3D give the
// same gaps: the formulas are written once.
#include <gtest/gtest.h>

#include <cmath>

#include "assembly/problem_data.hpp"

namespace fosls {
namespace {

template <int dim>
Vec<dim> at(double x, double y) {
  Vec<dim> p = Vec<dim>::Zero();
  p[0] = x, p[1] = y;
  return p;
}

template <int dim>
ContactData<dim> plane() {
  ContactData<dim> c;
  c.obstacle.kind = RigidObstacle<dim>::Kind::kPlane;
  c.obstacle.point = at<dim>(0, -1);
  c.obstacle.normal = at<dim>(0, 1);  // from the obstacle into the body, above it
  return c;
}

template <int dim>
ContactData<dim> ball() {
  ContactData<dim> c;
  c.obstacle.kind = RigidObstacle<dim>::Kind::kBall;
  c.obstacle.center = at<dim>(0, -3);
  c.obstacle.radius = 2;  // its top at y = −1
  return c;
}

template <class Dim>
class ObstacleTest : public ::testing::Test {};
using Dimensions = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(ObstacleTest, Dimensions);

TYPED_TEST(ObstacleTest, APlaneIsMetAlongTheNormalOrStraightDown) {
  constexpr int dim = TypeParam::value;
  const Vec<dim> p = at<dim>(0.5, 0), oblique = at<dim>(0.6, -0.8), sideways = at<dim>(1, 0);
  EXPECT_DOUBLE_EQ(locate_obstacle<dim>(plane<dim>(), p, oblique).gap, 1.0 / 0.8);
  EXPECT_EQ(locate_obstacle<dim>(plane<dim>(), p, oblique).direction, oblique);
  EXPECT_TRUE(std::isinf(locate_obstacle<dim>(plane<dim>(), p, sideways).gap));  // misses it
  ContactData<dim> down = plane<dim>();
  down.direction = ConstraintDirection::kObstacleNormal;
  EXPECT_DOUBLE_EQ(locate_obstacle<dim>(down, p, oblique).gap, 1.0);
  EXPECT_EQ(locate_obstacle<dim>(down, p, oblique).direction, at<dim>(0, -1));
}

TYPED_TEST(ObstacleTest, ABallIsMetAtTheRaysFirstHitOrMissed) {
  constexpr int dim = TypeParam::value;
  const Vec<dim> down = at<dim>(0, -1);
  EXPECT_NEAR(locate_obstacle<dim>(ball<dim>(), at<dim>(0, 0), down).gap, 1.0, 1e-15);
  // From (1, 0) straight down the ray meets the circle where y = −3 + √3.
  EXPECT_NEAR(locate_obstacle<dim>(ball<dim>(), at<dim>(1, 0), down).gap, 3.0 - std::sqrt(3.0),
              1e-15);
  EXPECT_TRUE(std::isinf(locate_obstacle<dim>(ball<dim>(), at<dim>(3, 0), down).gap));
  EXPECT_TRUE(std::isinf(locate_obstacle<dim>(ball<dim>(), at<dim>(0, 0), at<dim>(0, 1)).gap));
  ContactData<dim> radial = ball<dim>();
  radial.direction = ConstraintDirection::kObstacleNormal;
  const ContactPoint<dim> r = locate_obstacle<dim>(radial, at<dim>(1, 0), down);
  EXPECT_NEAR(r.gap, std::sqrt(10.0) - 2.0, 1e-15);
  EXPECT_LT((r.direction - at<dim>(-1, -3) / std::sqrt(10.0)).norm(), 1e-15);
}

TYPED_TEST(ObstacleTest, FromInsideTheBallTheGapIsNegative) {
  constexpr int dim = TypeParam::value;
  // (1, −1.5) lies inside: 3D measures back along n to the sphere, 2D radially (its results are
  // kept bit for bit); both agree where n meets the ball head on.
  const Vec<dim> down = at<dim>(0, -1);
  const double gap = locate_obstacle<dim>(ball<dim>(), at<dim>(1, -1.5), down).gap;
  const double expected = dim == 2 ? std::hypot(1.0, 1.5) - 2.0 : -1.5 + (3.0 - std::sqrt(3.0));
  EXPECT_NEAR(gap, expected, 1e-15);
  EXPECT_LT(gap, 0.0);
  EXPECT_NEAR(locate_obstacle<dim>(ball<dim>(), at<dim>(0, -1.5), down).gap, -0.5, 1e-15);
}

TYPED_TEST(ObstacleTest, AGapFunctionIsTakenAsItIs) {
  constexpr int dim = TypeParam::value;
  ContactData<dim> c;
  c.obstacle.kind = RigidObstacle<dim>::Kind::kGap;
  if constexpr (dim == 2)
    c.gap = [](double x, double y) { return x * x + y; };
  else
    c.gap = [](double x, double y, double) { return x * x + y; };
  EXPECT_DOUBLE_EQ(locate_obstacle<dim>(c, at<dim>(2, 0.5), at<dim>(0, -1)).gap, 4.5);
}

TEST(Obstacle, OneCapOnLargeGapsAtTenDiameters) {
  EXPECT_EQ(capped_gap(std::numeric_limits<double>::infinity(), 2.0), 20.0);
  EXPECT_EQ(capped_gap(25.0, 2.0), 20.0);
  EXPECT_EQ(capped_gap(-3.0, 2.0), -3.0);
  EXPECT_EQ(capped_gap(std::nan(""), 2.0), 20.0);
}

}  // namespace
}  // namespace fosls
