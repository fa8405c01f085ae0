// Newest-vertex bisection of tetrahedra (Arnold–Mukherjee–Pouly): conforming, nested, new
// vertices at midpoints of input edges, exact face shares, the prolongation exact on linear u and
// constant σ; built-in and gmsh meshes.
#include "tet_bisection_checks.hpp"

#include <cstdio>
#include <random>

#include "assembly/tet_hierarchy.hpp"
#include "tet_bisection_meshes.hpp"

namespace fosls {
namespace {

std::vector<int> all_tets(const TetMesh& m, int times = 1) {
  std::vector<int> marked;
  for (int k = 0; k < times; ++k)
    for (int t = 0; t < m.num_tets(); ++t) marked.push_back(t);
  return marked;
}

/// Every check of a step on a flat mesh from `coarse` with `state`.
void expect_good_step(const TetMesh& coarse, const TetBisectionState& state,
                      const TetBisection& step) {
  expect_conforming(coarse, step.fine, step.maps);
  expect_nested_maps(coarse, step.fine, step.maps);
  EXPECT_NEAR(total_volume(step.fine), total_volume(coarse), 1e-13 * total_volume(coarse));
  ASSERT_EQ(int(step.state.labels.size()), step.fine.num_tets());
  for (int t = 0; t < step.fine.num_tets(); ++t) {
    const int parent = step.maps.tet_parent[t];
    const int bisections = step.state.generation[t] - state.generation[parent];
    EXPECT_GE(bisections, 0);
    EXPECT_LE(bisections, kMaxBisectionsPerStep);
    EXPECT_NEAR(step.fine.tet_volume(t) * std::exp2(bisections), coarse.tet_volume(parent),
                1e-12 * coarse.tet_volume(parent))
        << "volume against generation";
  }
}

TEST(TetBisection, InitialMarkingOfAKuhnBoxCutsTheCubeDiagonals) {
  const TetMesh box = make_box({2, 2, 2});
  const TetBisectionState s = initial_tet_bisection_state(box);
  for (int t = 0; t < box.num_tets(); ++t) {
    const auto& x = box.tet(t);
    const auto& o = s.labels[t].order;
    EXPECT_NEAR((box.vertex(x[o[0]]) - box.vertex(x[o[1]])).norm(), std::sqrt(3.0) / 2, 1e-15);
    EXPECT_NE(s.labels[t].peak[0], s.labels[t].peak[1]) << "a Kuhn tetrahedron is not planar";
  }
}

TEST(TetBisection, OneMarkedTetrahedronOfABoxIsBisectedWithClosure) {
  const TetMesh box = make_box({3, 3, 3});
  const TetBisectionState s = initial_tet_bisection_state(box);
  const TetBisection step = refine_tets_by_bisection(box, s, {50});
  expect_good_step(box, s, step);
  EXPECT_GT(step.fine.num_tets(), box.num_tets() + 1);
  // The marked tetrahedron's refinement edge is cut: its two halves are in the fine mesh.
  int children = 0;
  for (int t = 0; t < step.fine.num_tets(); ++t) children += step.maps.tet_parent[t] == 50;
  EXPECT_EQ(children, 2);
  // Kept tetrahedra keep their vertices in order, and their labels.
  for (int t = 0; t < step.fine.num_tets(); ++t)
    if (step.state.generation[t] == 0) {
      EXPECT_EQ(step.fine.tet(t), box.tet(step.maps.tet_parent[t]));
      EXPECT_EQ(step.state.labels[t].order, s.labels[step.maps.tet_parent[t]].order);
    }
}

TEST(TetBisection, MarkingEveryTetrahedronThreeTimesHalvesEveryEdge) {
  for (const TetMesh& coarse : {make_box({2, 3, 2}, Point3(1.0, 1.3, 0.7)), gmsh_brick(0.4)}) {
    const TetBisectionState s = initial_tet_bisection_state(coarse);
    const TetBisection step = refine_tets_by_bisection(coarse, s, all_tets(coarse, 3));
    expect_good_step(coarse, s, step);
    EXPECT_EQ(step.maps.midpoint_ends.size(), edges_of(coarse).size());
    ASSERT_EQ(step.fine.num_tets(), 8 * coarse.num_tets());
    for (int t = 0; t < step.fine.num_tets(); ++t) {
      EXPECT_EQ(step.state.generation[t], 3);
      EXPECT_NEAR(step.fine.tet_volume(t), coarse.tet_volume(step.maps.tet_parent[t]) / 8,
                  1e-14 * coarse.tet_volume(step.maps.tet_parent[t]));
    }
  }
}

TEST(TetBisection, ThreeUniformStepsEqualOneStepOfThree) {
  const TetMesh box = make_box({2, 2, 2});
  TetHierarchy h{{box}, {{}}};
  TetBisectionState s = initial_tet_bisection_state(box);
  for (int k = 0; k < 3; ++k) refine_finest_tet_level(h, s, all_tets(h.finest()));
  const TetBisection once =
      refine_tets_by_bisection(box, initial_tet_bisection_state(box), all_tets(box, 3));
  ASSERT_EQ(h.num_levels(), 4);
  EXPECT_EQ(h.finest().num_tets(), once.fine.num_tets());
  EXPECT_EQ(edges_of(h.finest()).size(), edges_of(once.fine).size());
  for (int t = 0; t < h.finest().num_tets(); ++t) EXPECT_EQ(s.generation[t], 3);
}

TEST(TetBisection, RandomAdaptiveStepsStayConformingAndNested) {
  std::mt19937 random(7);
  int split = 0;
  for (const TetMesh& start : {make_box({3, 2, 2}), gmsh_brick(0.6)}) {
    TetMesh mesh = start;
    TetBisectionState s = initial_tet_bisection_state(mesh);
    for (int step = 0; step < 4; ++step) {
      std::vector<int> marked;
      for (int t = 0; t < mesh.num_tets(); ++t)
        if (random() % 10 == 0) marked.push_back(t);
      if (step % 3 == 0) marked.push_back(0), marked.push_back(0);
      split += refine_checked(mesh, s, marked) > 1;
    }
  }
  std::printf("random steps split into parts: %d of 8\n", split);
}

/// Where generations differ by three around an edge the whole step needs a vertex that is no
/// midpoint of an input edge: refine_tets_by_bisection refuses it, naming the tetrahedron, and
/// the part that refine_tets_by_bisection_in_part does leaves marks for a next level.
TEST(TetBisection, AStepOffTheInputEdgesIsRefusedOrSplit) {
  std::mt19937 random(7);
  TetHierarchy h{{gmsh_brick(0.6)}, {{}}};
  TetBisectionState s = initial_tet_bisection_state(h.finest());
  int refused = 0;
  for (int step = 0; step < 5; ++step) {
    const TetMesh& mesh = h.finest();
    std::vector<int> marked;
    for (int t = 0; t < mesh.num_tets(); ++t)
      if (random() % 10 == 0) marked.push_back(t);
    try {
      refine_tets_by_bisection(mesh, s, marked);
    } catch (const std::runtime_error& e) {
      ++refused;
      EXPECT_NE(std::string(e.what()).find("not the midpoint of an edge of the input mesh"),
                std::string::npos);
      std::vector<int> remaining;
      refine_tets_by_bisection_in_part(mesh, s, marked, remaining);
      EXPECT_FALSE(remaining.empty());
      EXPECT_GT(refine_finest_tet_level(h, s, marked), 1);
      continue;
    }
    EXPECT_EQ(refine_finest_tet_level(h, s, marked), 1);
  }
  EXPECT_GT(refused, 0);
}

TEST(TetBisection, RefineFinestLevelAppendsNestedLevels) {
  TetMesh mesh = gmsh_brick(0.4);
  TetHierarchy h{{mesh}, {{}}};
  TetBisectionState s = initial_tet_bisection_state(mesh);
  int levels = 0;
  for (int step = 0; step < 4; ++step) {
    std::vector<int> marked;
    for (int t = 0; t < h.finest().num_tets(); t += 11) marked.push_back(t);
    levels += refine_finest_tet_level(h, s, marked);
  }
  // Nothing marked: one more level, the same mesh (as 2D's refine_finest_level).
  levels += refine_finest_tet_level(h, s, {});
  EXPECT_EQ(h.finest().num_tets(), h.meshes[h.num_levels() - 2].num_tets());
  ASSERT_EQ(h.num_levels(), levels + 1);
  ASSERT_EQ(int(s.labels.size()), h.finest().num_tets());
  for (int l = 1; l < h.num_levels(); ++l) {
    expect_conforming(h.meshes[l - 1], h.meshes[l], h.maps[l]);
    expect_nested_maps(h.meshes[l - 1], h.meshes[l], h.maps[l]);
  }
}

TEST(TetBisection, BoundaryGroupsAreInheritedByTheHalvesOfTheirFaces) {
  const TetMesh coarse = gmsh_brick(0.4);
  TetHierarchy h{{coarse}, {{}}};
  TetBisectionState s = initial_tet_bisection_state(coarse);
  for (int step = 0; step < 4; ++step)
    refine_finest_tet_level(h, s, {0, 1, 2, h.finest().num_tets() - 1});
  for (int l = 1; l < h.num_levels(); ++l)
    for (int f = 0; f < h.meshes[l].num_faces(); ++f)
      if (h.meshes[l].is_boundary_face(f)) {
        ASSERT_GE(h.maps[l].parent_face[f], 0);
        EXPECT_EQ(h.meshes[l].face_group(f), h.meshes[l - 1].face_group(h.maps[l].parent_face[f]));
      }
  const TetMesh& mesh = h.finest();
  std::vector<double> area(coarse.group_names().size()), fine_area(area.size());
  for (int f = 0; f < coarse.num_faces(); ++f)
    if (coarse.is_boundary_face(f)) area[coarse.face_group(f)] += coarse.face_area(f);
  for (int f = 0; f < mesh.num_faces(); ++f)
    if (mesh.is_boundary_face(f)) fine_area[mesh.face_group(f)] += mesh.face_area(f);
  for (std::size_t g = 0; g < area.size(); ++g) EXPECT_NEAR(fine_area[g], area[g], 1e-13);
}

/// P u_H on the fine mesh for a linear u, and P σ_H for a constant σ, against their exact values.
TEST(TetBisection, ProlongationIsExactOnLinearDisplacementsAndConstantStresses) {
  const TetMesh coarse = gmsh_brick(0.4);
  TetBisectionState s = initial_tet_bisection_state(coarse);
  std::vector<int> marked;
  for (int t = 0; t < coarse.num_tets(); t += 3) marked.push_back(t);
  marked.push_back(4), marked.push_back(4);
  const TetBisection step = refine_tets_by_bisection(coarse, s, marked);
  const TetMesh& fine = step.fine;
  Eigen::Matrix3d a, sigma;
  a << 0.3, -1.1, 0.7, 0.2, 0.5, -0.4, 1.3, 0.1, -0.6;
  sigma << 2.0, -0.5, 0.3, 0.7, -1.2, 0.9, -0.4, 0.8, 1.5;
  const Eigen::Vector3d b(0.2, -0.3, 0.5);
  auto dofs = [&](const TetMesh& m) {
    Eigen::VectorXd x(3 * m.num_vertices() + 3 * m.num_faces());
    for (int v = 0; v < m.num_vertices(); ++v) x.segment<3>(3 * v) = a * m.vertex(v) + b;
    for (int f = 0; f < m.num_faces(); ++f)  // RT0: the flux of each row through the face
      x.segment<3>(3 * m.num_vertices() + 3 * f) = sigma * m.face_normal(f) * m.face_area(f);
    return x;
  };
  const Eigen::VectorXd fine_exact = dofs(fine);
  const Eigen::VectorXd prolonged = tet_prolongation(coarse, fine, step.maps) * dofs(coarse);
  EXPECT_LT((prolonged - fine_exact).lpNorm<Eigen::Infinity>(), 1e-14);
}

TEST(TetBisection, RedRefinementSharesAreQuarters) {
  const TetMesh box = make_box({2, 1, 1});
  const TetRefinement red = refine_tets_uniformly(box);
  expect_nested_maps(box, red.fine, red.maps);
  for (int f = 0; f < red.fine.num_faces(); ++f)
    if (red.maps.parent_face[f] >= 0) {
      EXPECT_EQ(red.maps.parent_face_share[f], 0.25);
    }
}

/// A sphere group far too curved for its face: the midpoint of the face's long edge goes onto the
/// sphere past a half's opposite face, and the step is refused rather than folding that half.
TEST(TetBisection, AMidpointThatWouldInvertATetrahedronOnItsSphereIsRefused) {
  const std::vector<Point3> x = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0.1}};
  const SphereSurface tight{Point3(0.5, 3.0, 0.0), 3.2}, loose{Point3(0.5, 100.5, 0.0), 100.0};
  for (const SphereSurface& sphere : {tight, loose}) {
    const TetMesh one(x, {{0, 1, 2, 3}}, {{{0, 1, 2}, 0}}, {"curved"}, {sphere});
    const TetBisectionState s = initial_tet_bisection_state(one);
    std::string outcome = "accepted";
    try {
      refine_tets_by_bisection(one, s, {0});
    } catch (const std::runtime_error& e) {
      outcome = e.what();
    }
    if (sphere.radius < 10) {
      EXPECT_NE(outcome.find("onto its sphere inverted a tetrahedron"), std::string::npos);
    } else {
      EXPECT_EQ(outcome, "accepted");
    }
  }
}

TEST(TetBisection, BadInputIsRefusedWithItsReason) {
  const TetMesh box = make_box({1, 1, 1});
  const TetBisectionState s = initial_tet_bisection_state(box);
  auto message = [&](const TetBisectionState& state, const std::vector<int>& marked) {
    try {
      refine_tets_by_bisection(box, state, marked);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(s, {6}).find("tetrahedron 6 does not exist"), std::string::npos);
  EXPECT_NE(message(s, {-1}).find("does not exist"), std::string::npos);
  EXPECT_NE(message(s, {2, 2, 2, 2}).find("marked more than 3 times"), std::string::npos);
  EXPECT_NE(message(initial_tet_bisection_state(make_box({2, 1, 1})), {0}).find("state"),
            std::string::npos);
  TetBisectionState broken = s;
  broken.labels[3].peak[0] = broken.labels[3].order[0];
  EXPECT_NE(message(broken, {0}).find("label of tetrahedron 3"), std::string::npos);
  EXPECT_EQ(message(s, {0, 0, 0}), "accepted");
}

}  // namespace
}  // namespace fosls
