#pragma once
// Checks shared by the tetrahedron bisection tests: conformity, nestedness, the refinement maps.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "mesh/tet_bisection.hpp"

namespace fosls {

inline double total_volume(const TetMesh& m) {
  double v = 0.0;
  for (int t = 0; t < m.num_tets(); ++t) v += m.tet_volume(t);
  return v;
}

/// Barycentric coordinates of p in tetrahedron t of m.
inline Eigen::Vector4d barycentric(const TetMesh& m, int t, const Point3& p) {
  const auto& x = m.tet(t);
  Eigen::Matrix3d j;
  for (int k = 0; k < 3; ++k) j.col(k) = m.vertex(x[k + 1]) - m.vertex(x[0]);
  const Eigen::Vector3d l = j.inverse() * (p - m.vertex(x[0]));
  return {1.0 - l.sum(), l[0], l[1], l[2]};
}

/// The sorted vertex pairs of m's tetrahedra.
inline std::set<std::pair<int, int>> edges_of(const TetMesh& m) {
  std::set<std::pair<int, int>> edges;
  for (int t = 0; t < m.num_tets(); ++t)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.insert(std::minmax(m.tet(t)[i], m.tet(t)[j]));
  return edges;
}

/// Conformity of a refinement of `coarse`: every fine face with one tetrahedron lies in a coarse
/// boundary face (a hanging vertex leaves faces inside the body with one tetrahedron), and no fine
/// edge has a fine vertex at its midpoint (where bisection would leave one hanging); the TetMesh
/// constructor has already refused a face in three tetrahedra.
inline void expect_conforming(const TetMesh& coarse, const TetMesh& fine,
                              const TetRefinementMaps& maps, bool flat = true) {
  int inner_boundary = 0;
  for (int f = 0; f < fine.num_faces(); ++f)
    if (fine.is_boundary_face(f)) {
      const int p = maps.parent_face[f];
      inner_boundary += p < 0 || !coarse.is_boundary_face(p);
    }
  EXPECT_EQ(inner_boundary, 0) << "fine faces with one tetrahedron inside the body";
  if (!flat) return;
  std::map<std::array<long long, 3>, int> at;
  auto key = [](const Point3& x) {
    return std::array<long long, 3>{std::llround(x[0] * 1e9), std::llround(x[1] * 1e9),
                                    std::llround(x[2] * 1e9)};
  };
  for (int v = 0; v < fine.num_vertices(); ++v) at[key(fine.vertex(v))] = v;
  int hanging = 0;
  for (const auto& [a, b] : edges_of(fine))
    hanging += at.count(key(0.5 * (fine.vertex(a) + fine.vertex(b))));
  EXPECT_EQ(hanging, 0) << "fine vertices at midpoints of fine edges";
}

/// Nestedness and the maps: each fine tetrahedron inside its parent, each new vertex the midpoint
/// of its coarse edge, each fine face's share of its parent face its exact area ratio.
inline void expect_nested_maps(const TetMesh& coarse, const TetMesh& fine,
                               const TetRefinementMaps& maps) {
  ASSERT_EQ(maps.num_coarse_vertices, coarse.num_vertices());
  ASSERT_EQ(fine.num_vertices(), coarse.num_vertices() + int(maps.midpoint_ends.size()));
  const auto coarse_edges = edges_of(coarse);
  for (int v = 0; v < coarse.num_vertices(); ++v) EXPECT_EQ(fine.vertex(v), coarse.vertex(v));
  for (std::size_t k = 0; k < maps.midpoint_ends.size(); ++k) {
    const auto& e = maps.midpoint_ends[k];
    EXPECT_TRUE(coarse_edges.count({e[0], e[1]})) << "midpoint of a pair that is no coarse edge";
    EXPECT_EQ(fine.vertex(coarse.num_vertices() + int(k)),
              0.5 * (coarse.vertex(e[0]) + coarse.vertex(e[1])));
  }
  for (int t = 0; t < fine.num_tets(); ++t) {
    const int parent = maps.tet_parent[t];
    // 1e−12, or the rounding of coordinates of the body's size on a tetrahedron far smaller.
    const double rounding =
        std::max(1e-12, 1e-15 * coarse.diameter() / std::cbrt(coarse.tet_volume(parent)));
    for (int v : fine.tet(t))
      EXPECT_GE(barycentric(coarse, parent, fine.vertex(v)).minCoeff(), -rounding)
          << "a fine tetrahedron outside its parent";
  }
  for (int f = 0; f < fine.num_faces(); ++f) {
    const int p = maps.parent_face[f];
    EXPECT_NE(p < 0, maps.parent_tet_of_face[f] < 0) << "face " << f << " in both or neither";
    if (p < 0) {
      const Point3 c = fine.face_centroid(f);
      EXPECT_GE(barycentric(coarse, maps.parent_tet_of_face[f], c).minCoeff(), -1e-12);
      continue;
    }
    const double share = maps.parent_face_share[f];
    // Areas from cross products lose digits as faces shrink against the coordinates.
    const double rounding = 1e-14 * coarse.diameter() / std::sqrt(fine.face_area(f));
    EXPECT_NEAR(share, fine.face_area(f) / coarse.face_area(p), rounding);
    EXPECT_EQ(share, std::exp2(std::round(std::log2(share)))) << "not a power of two";
  }
}

/// One adaptive step as refine_finest_tet_level takes it, each part checked (flat: nestedness
/// too) and the marks honoured: every descendant of a tetrahedron marked k times is k generations
/// finer. Replaces mesh and state; returns the number of parts (levels).
inline int refine_checked(TetMesh& mesh, TetBisectionState& state, const std::vector<int>& marked,
                          bool flat = true) {
  std::vector<int> target(mesh.num_tets(), 0), ancestor(mesh.num_tets());
  for (int t = 0; t < mesh.num_tets(); ++t) target[t] = state.generation[t], ancestor[t] = t;
  for (int t : marked) ++target[t];
  std::vector<int> todo = marked, remaining;
  int parts = 0;
  do {
    const TetBisection part = refine_tets_by_bisection_in_part(mesh, state, todo, remaining);
    expect_conforming(mesh, part.fine, part.maps, flat);
    if (flat) expect_nested_maps(mesh, part.fine, part.maps);
    std::vector<int> fine_ancestor(part.fine.num_tets());
    for (int t = 0; t < part.fine.num_tets(); ++t)
      fine_ancestor[t] = ancestor[part.maps.tet_parent[t]];
    ancestor.swap(fine_ancestor);
    mesh = part.fine;
    state = part.state;
    todo.swap(remaining);
    ++parts;
  } while (!todo.empty() && parts < 10);
  EXPECT_TRUE(todo.empty()) << "marks still open after 10 parts";
  for (int t = 0; t < mesh.num_tets(); ++t)
    EXPECT_GE(state.generation[t], target[ancestor[t]]) << "a mark not honoured";
  return parts;
}

}  // namespace fosls
