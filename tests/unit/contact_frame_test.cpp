// The one roller mechanism of both dimensions (fem/contact_frame.hpp, docs/method.md §11): a
// roller whose axis is within 30° of the contact's tangent plane keeps the obstacle constraint,
// with its axis as a fixed tangent; a more oblique one wins and drops it. Checked on the frames
// and on a space whose contact boundary meets a symmetry roller.
#include <gtest/gtest.h>

#include "fem/contact_frame.hpp"
#include "fem/fosls_space.hpp"
#include "mesh/builtin_meshes.hpp"

namespace fosls {
namespace {

template <int dim>
void expect_orthogonal(const Mat<dim>& q) {
  EXPECT_LT((q.transpose() * q - Mat<dim>::Identity()).norm(), 1e-14);
}

TEST(ContactFrame, TheNormalFrameIsOrthogonalWithTheNormalFirst) {
  const Point n2 = Point(0.3, -1.0).normalized();
  expect_orthogonal<2>(normal_frame<2>(n2));
  EXPECT_EQ(normal_frame<2>(n2).col(0), n2);
  EXPECT_EQ(normal_frame<2>(n2).col(1), Point(-n2.y(), n2.x()));  // t = (−n_y, n_x)
  const Point3 n3 = Point3(0.3, -1.0, 0.2).normalized();
  expect_orthogonal<3>(normal_frame<3>(n3));
  EXPECT_EQ(normal_frame<3>(n3).col(0), n3);
}

TEST(ContactFrame, ARollerWithin30DegreesBecomesAFixedTangent) {
  // 2D: a roller on x (bit 0) meets a contact normal 20° off −y: the normal loses its x part.
  const double a = 20.0 * M_PI / 180.0;
  const Mat<2> q2 = roller_frame<2>(Point(std::sin(a), -std::cos(a)), 1);
  expect_orthogonal<2>(q2);
  EXPECT_LT((q2.col(0) - Point(0, -1)).norm(), 1e-15);
  EXPECT_NEAR(std::abs(q2(0, 1)), 1.0, 1e-15);  // the tangent is ±e_x, the prescribed axis
  // 3D: rollers on x and y (bits 0, 1) through a normal 20° off −z: t1 = e_x, t2 = ±e_y.
  const Mat<3> q3 = roller_frame<3>(Point3(std::sin(a), 0, -std::cos(a)), 3);
  expect_orthogonal<3>(q3);
  EXPECT_LT((q3.col(0) - Point3(0, 0, -1)).norm(), 1e-15);
  EXPECT_EQ(q3.col(1), Point3::UnitX());
  EXPECT_NEAR(std::abs(q3(1, 2)), 1.0, 1e-15);
}

TEST(ContactFrame, AMoreObliqueRollerWinsInBothDimensions) {
  const double a = 40.0 * M_PI / 180.0;
  EXPECT_TRUE(roller_frame<2>(Point(std::sin(a), -std::cos(a)), 1).isZero());
  EXPECT_TRUE(roller_frame<3>(Point3(std::sin(a), 0, -std::cos(a)), 1).isZero());
  EXPECT_FALSE(roller_frame<3>(Point3(std::sin(a), 0, -std::cos(a)), 2).isZero());  // on y
}

TEST(ContactFrame, WhereASymmetryRollerMeetsTheContactBoundaryBothHold) {
  // The unit square: contact below, a roller (u_x = 0) on the left, pushed from the top.
  const Mesh mesh = make_square({.size = 0.25});
  std::vector<BoundaryRole> groups(4);  // bottom, right, top, left
  groups[0].role = GroupRole::kContact;
  groups[2] = {GroupRole::kDirichlet, kEveryComponent};
  groups[3] = {GroupRole::kDirichlet, 1};
  const FoslsSpace<2> space(mesh, groups);
  int corner = -1;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (mesh.vertex(v).norm() < 1e-12) corner = v;
  ASSERT_GE(corner, 0);
  ASSERT_TRUE(space.is_contact_vertex(corner));
  EXPECT_EQ(space.vertex_normal(corner), Point(0, -1));
  EXPECT_EQ(space.role(space.u_dof(corner, 0)), DofRole::kNormalU);
  EXPECT_EQ(space.role(space.u_dof(corner, 1)), DofRole::kFixed);  // U_t: the roller's u_x
  // The roller's free component has zero traction: σ_y fixed, σ_x free on its edges.
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (mesh.edge_group(e) == 3) {
      EXPECT_EQ(space.role(space.sigma_dof(e, 0)), DofRole::kFree);
      EXPECT_EQ(space.role(space.sigma_dof(e, 1)), DofRole::kFixed);
    }
}

}  // namespace
}  // namespace fosls
