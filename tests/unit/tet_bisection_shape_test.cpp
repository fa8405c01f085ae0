// Newest-vertex bisection of tetrahedra, locality and shape: the closure of one marked
// tetrahedron is bounded independently of the mesh size, and 30+ steps towards a point keep the
// smallest dihedral angle bounded below (the Kuhn box's descendants in three similarity classes);
// on the half and quarter ball the sphere groups stay on the sphere.
#include "tet_bisection_checks.hpp"

#include <cstdio>

#include "mesh/tet_half_ball.hpp"
#include "mesh/tet_quality.hpp"
#include "tet_bisection_meshes.hpp"

namespace fosls {
namespace {

/// The tetrahedra around the vertex nearest to p.
std::vector<int> tets_at_nearest_vertex(const TetMesh& m, const Point3& p) {
  int nearest = 0;
  for (int v = 1; v < m.num_vertices(); ++v)
    if ((m.vertex(v) - p).norm() < (m.vertex(nearest) - p).norm()) nearest = v;
  std::vector<int> marked;
  for (int t = 0; t < m.num_tets(); ++t)
    if (std::find(m.tet(t).begin(), m.tet(t).end(), nearest) != m.tet(t).end()) marked.push_back(t);
  return marked;
}

/// The smallest dihedral angle of each of `steps` refinements towards p, with each step checked
/// for conformity (flat: and nestedness); the final mesh into `last`.
std::vector<double> angles_towards(const TetMesh& coarse, const Point3& p, int steps, bool flat,
                                   TetMesh* last = nullptr) {
  TetMesh mesh = coarse;
  TetBisectionState s = initial_tet_bisection_state(mesh);
  std::vector<double> angles = {smallest_dihedral_angle(mesh)};
  for (int k = 0; k < steps; ++k) {
    refine_checked(mesh, s, tets_at_nearest_vertex(mesh, p), flat);
    angles.push_back(smallest_dihedral_angle(mesh));
  }
  if (last) *last = mesh;
  return angles;
}

/// Similarity classes: sorted edge lengths over the longest, to 1e−6.
std::set<std::array<long long, 6>> similarity_classes(const TetMesh& m) {
  std::set<std::array<long long, 6>> classes;
  for (int t = 0; t < m.num_tets(); ++t) {
    std::array<double, 6> len;
    int n = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        len[n++] = (m.vertex(m.tet(t)[i]) - m.vertex(m.tet(t)[j])).norm();
    std::sort(len.begin(), len.end());
    std::array<long long, 6> key;
    for (int k = 0; k < 6; ++k) key[k] = std::llround(len[k] / len[5] * 1e6);
    classes.insert(key);
  }
  return classes;
}

double smallest(const std::vector<double>& a, std::size_t from, std::size_t to) {
  return *std::min_element(a.begin() + from, a.begin() + to);
}

TEST(TetBisectionShape, ClosureOfOneTetrahedronIsLocal) {
  std::vector<int> added;
  for (int n : {4, 8, 12}) {
    const TetMesh box = make_box({n, n, n});
    const int middle = 6 * ((n / 2 * n + n / 2) * n + n / 2);  // first tetrahedron of a middle cube
    for (int first : {middle, middle + 3}) {
      const TetBisection step =
          refine_tets_by_bisection(box, initial_tet_bisection_state(box), {first});
      added.push_back(step.fine.num_tets() - box.num_tets());
    }
  }
  std::printf("tetrahedra added by one marked tetrahedron:");
  for (int a : added) std::printf(" %d", a);
  std::printf("\n");
  for (std::size_t k = 2; k < added.size(); ++k) EXPECT_EQ(added[k], added[k % 2]);
  EXPECT_LE(*std::max_element(added.begin(), added.end()), 40);
}

TEST(TetBisectionShape, KuhnBoxRefinedTowardsAPointKeepsThreeShapes) {
  for (const Point3& p : {Point3(0, 0, 0), Point3(0.3, 0.55, 0.7)}) {
    TetMesh last;
    const std::vector<double> a = angles_towards(make_box({2, 2, 2}), p, 33, true, &last);
    std::printf(
        "Kuhn box towards (%.2f %.2f %.2f): smallest dihedral angle %.4f after 3 steps, "
        "%.4f after 33 (%d tets, %zu shapes)\n",
        p.x(), p.y(), p.z(), smallest(a, 0, 4), smallest(a, 0, a.size()), last.num_tets(),
        similarity_classes(last).size());
    EXPECT_EQ(smallest(a, 0, a.size()), smallest(a, 0, 4));
    EXPECT_LE(similarity_classes(last).size(), 3u);
    EXPECT_GT(last.num_tets(), 200);  // the steps did refine
  }
}

TEST(TetBisectionShape, GmshBoxRefinedTowardsAPointStaysShapeRegular) {
  const std::vector<double> a = angles_towards(gmsh_brick(0.4), Point3(0.3, 0.0, 0.7), 33, true);
  std::printf(
      "gmsh brick, smallest dihedral angle: %.4f initially, %.4f after 12 steps, %.4f after 33\n",
      a[0], smallest(a, 0, 13), smallest(a, 0, a.size()));
  EXPECT_EQ(smallest(a, 0, a.size()), smallest(a, 0, 13)) << "still falling after 12 steps";
  EXPECT_GE(smallest(a, 0, a.size()), 0.25 * a[0]);
}

TEST(TetBisectionShape, HalfBallRefinedTowardsTheSphereStaysOnItAndShapeRegular) {
  for (bool quarter : {false, true}) {
    HalfBallSpec spec;
    spec.cells = 2;
    spec.quarter = quarter;
    const TetMesh ball = make_half_ball(spec);
    for (const Point3& p :
         {Point3(0, 0, -1), Point3(0.25, 0.35, -std::sqrt(1 - 0.25 * 0.25 - 0.35 * 0.35))}) {
      TetMesh last;
      const std::vector<double> a = angles_towards(ball, p, 33, false, &last);
      std::printf(
          "%s ball towards (%.2f %.2f %.2f): smallest angle %.4f initially, %.4f after 12, %.4f "
          "after 33 (%d tets)\n",
          quarter ? "quarter" : "half", p.x(), p.y(), p.z(), a[0], smallest(a, 0, 13),
          smallest(a, 0, a.size()), last.num_tets());
      EXPECT_GE(smallest(a, 0, a.size()), 0.25 * a[0]);
      double off = 0.0;
      for (int f = 0; f < last.num_faces(); ++f)
        if (last.is_boundary_face(f) && last.group_surface(last.face_group(f)).curved())
          for (int v : last.face(f)) off = std::max(off, std::abs(last.vertex(v).norm() - 1.0));
      EXPECT_LT(off, 1e-14) << "a sphere group's vertex off the sphere";
      EXPECT_LT((last.vertex(last.num_vertices() - 1) - p).norm(), 0.5);
    }
  }
}

}  // namespace
}  // namespace fosls
