// The refinement maps between non-neighbouring levels of a bisection hierarchy
// (mesh/composed_refinement.hpp) and the solver levels built from them
// (assembly/solver_levels.hpp): where two bisection levels compose, the composed maps give the
// product of the two levels' transfers exactly (straight boundaries: the meshes are nested);
// where a vertex halves an edge that the skipped level made, there is no composition; a uniform
// hierarchy keeps every level, and a bisection hierarchy keeps levels a factor apart.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>

#include "assembly/solver_levels.hpp"
#include "fem/transfer.hpp"
#include "mesh/bisection.hpp"
#include "mesh/builtin_meshes.hpp"
#include "mesh/composed_refinement.hpp"
#include "mesh/local_refinement.hpp"

namespace fosls {
namespace {

/// Bisection steps of a mesh's cells with a vertex within `radius` of a corner, `steps` times:
/// the refinement concentrates there, as the adaptive loop's does at a contact zone's edge.
template <int dim>
SimplexHierarchy<dim> bisected_towards_corner(SimplexHierarchy<dim> h, int steps, double radius) {
  SimplexBisectionState<dim> state = initial_bisection_state(h.finest(), 0);
  for (int step = 0; step < steps; ++step) {
    const SimplexMesh<dim>& mesh = h.finest();
    std::vector<int> marked;
    for (int t = 0; t < mesh.num_cells(); ++t)
      for (int v : mesh.cell(t))
        if (mesh.vertex(v).norm() <= radius) {
          marked.push_back(t);
          break;
        }
    bisect_finest_level(h, state, marked);
  }
  return h;
}

/// The largest entry of |A − B|.
double max_difference(const Eigen::SparseMatrix<double>& a, const Eigen::SparseMatrix<double>& b) {
  const Eigen::SparseMatrix<double> d = a - b;
  double m = 0.0;
  for (int k = 0; k < d.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(d, k); it; ++it)
      m = std::max(m, std::abs(it.value()));
  return m;
}

/// The largest relative mismatch between each coarse cell's measure and the sum of the fine
/// cells that the maps put in it (every fine cell in exactly one coarse cell, none left out).
template <int dim>
double cell_cover_mismatch(const SimplexMesh<dim>& coarse, const SimplexMesh<dim>& fine,
                           const SimplexRefinementMaps<dim>& maps) {
  std::vector<double> covered(coarse.num_cells(), 0.0);
  for (int t = 0; t < fine.num_cells(); ++t) covered[maps.cell_parent(t)] += fine.cell_measure(t);
  double m = 0.0;
  for (int t = 0; t < coarse.num_cells(); ++t)
    m = std::max(m, std::abs(covered[t] / coarse.cell_measure(t) - 1.0));
  return m;
}

/// What composing the maps across every span of two to four levels shows: how many
/// compositions are complete (every new vertex halves a coarse edge) and how many partial; the
/// largest deviation of a complete composition's transfer from the product of the levels'
/// transfers; and the largest mismatch of the composed parent cells.
struct Compositions {
  int complete = 0, partial = 0;
  double transfer_deviation = 0.0, cover_mismatch = 0.0;
};

template <int dim>
Compositions compositions(const SimplexHierarchy<dim>& h) {
  Compositions out;
  for (int fine = 2; fine < h.num_levels(); ++fine) {
    SimplexRefinementMaps<dim> maps = h.maps[fine];
    Eigen::SparseMatrix<double> product =
        cartesian_prolongation<dim>(h.meshes[fine - 1], h.meshes[fine], h.maps[fine]);
    for (int coarse = fine - 2; coarse >= std::max(0, fine - 4); --coarse) {
      maps =
          compose_refinement_maps(h.meshes[coarse], h.meshes[coarse + 1], h.maps[coarse + 1], maps);
      product = product * cartesian_prolongation<dim>(h.meshes[coarse], h.meshes[coarse + 1],
                                                      h.maps[coarse + 1]);
      const SimplexMesh<dim>& c = h.meshes[coarse];
      out.cover_mismatch =
          std::max(out.cover_mismatch, cell_cover_mismatch<dim>(c, h.meshes[fine], maps));
      if (!every_new_vertex_halves_a_coarse_edge(maps)) {
        ++out.partial;
        continue;
      }
      ++out.complete;
      out.transfer_deviation =
          std::max(out.transfer_deviation,
                   max_difference(cartesian_prolongation<dim>(c, h.meshes[fine], maps), product));
    }
  }
  return out;
}

/// Both kinds of composition occur on a hierarchy refined towards a corner over a region and
/// at a point; every complete one gives the product of the transfers, and every composition's
/// parent cells cover the coarse cells.
template <int dim>
void expect_exact_compositions(const SimplexHierarchy<dim>& wide,
                               const SimplexHierarchy<dim>& sharp) {
  const Compositions a = compositions<dim>(wide), b = compositions<dim>(sharp);
  std::printf("%dD: wide %d complete, %d partial; sharp %d complete, %d partial\n", dim, a.complete,
              a.partial, b.complete, b.partial);
  EXPECT_GE(a.complete, 2);
  EXPECT_GE(b.partial, 2);
  EXPECT_LT(std::max(a.transfer_deviation, b.transfer_deviation), 1e-12);
  EXPECT_LT(std::max(a.cover_mismatch, b.cover_mismatch), 1e-12);
}

TEST(ComposedRefinement, TrianglesCompleteCompositionsGiveTheProductOfTheTransfers) {
  // Measured: spans of two levels compose completely (7 of 7 each), longer spans halve edges
  // that a skipped level made (11 of 11).
  expect_exact_compositions<2>(
      bisected_towards_corner<2>(build_mesh_hierarchy(make_square({.size = 0.25}), 0), 8, 0.3),
      bisected_towards_corner<2>(build_mesh_hierarchy(make_square({.size = 0.25}), 0), 8, 1e-9));
}

TEST(ComposedRefinement, TetrahedraCompleteCompositionsGiveTheProductOfTheTransfers) {
  // Measured: 8 complete and 4 partial compositions, 13 and 5.
  expect_exact_compositions<3>(
      bisected_towards_corner<3>(build_tet_hierarchy(make_box({2, 2, 2}), 0), 6, 0.4),
      bisected_towards_corner<3>(build_tet_hierarchy(make_box({2, 2, 2}), 0), 8, 1e-9));
}

std::vector<long long> lowest_order_unknowns(const MeshHierarchy& h) {
  std::vector<long long> unknowns;
  for (const Mesh& m : h.meshes) unknowns.push_back(lowest_order_dofs(m));
  return unknowns;
}

const auto kNoContact = [](int, int) { return false; };

TEST(SolverLevels, AUniformHierarchyKeepsEveryLevel) {
  const MeshHierarchy h = build_mesh_hierarchy(make_square({.size = 0.5}), 3);
  const SolverLevels<2> kept = skip_close_levels<2>(h, lowest_order_unknowns(h), kNoContact, 0);
  EXPECT_EQ(kept.mesh_levels, (std::vector<int>{0, 1, 2, 3}));
}

TEST(SolverLevels, BisectionLevelsAreKeptAFactorApart) {
  const MeshHierarchy h =
      bisected_towards_corner<2>(build_mesh_hierarchy(make_square({.size = 0.25}), 0), 8, 1e-9);
  const std::vector<long long> unknowns = lowest_order_unknowns(h);
  const SolverLevels<2> kept = skip_close_levels<2>(h, unknowns, kNoContact, 0);
  ASSERT_LT(kept.mesh_levels.size(), static_cast<std::size_t>(h.num_levels()));
  EXPECT_EQ(kept.mesh_levels.front(), 0);
  EXPECT_EQ(kept.mesh_levels.back(), h.num_levels() - 1);
  for (std::size_t k = 1; k < kept.mesh_levels.size(); ++k) {
    const int below = kept.mesh_levels[k - 1], above = kept.mesh_levels[k];
    EXPECT_TRUE(below == 0 || unknowns[below] <= kMaxSolverLevelShare * unknowns[above])
        << "levels " << below << " and " << above;
    // Only the next kept level down is a factor apart: the one above it is not.
    if (above - below > 1)
      EXPECT_GT(unknowns[below + 1], kMaxSolverLevelShare * unknowns[above]) << below;
    EXPECT_EQ(kept.maps[k].num_coarse_vertices, h.meshes[below].num_vertices());
  }
}

TEST(SolverLevels, EveryVertexOnTheContactBoundaryHasCoarseWeights) {
  // Every vertex on the contact boundary: the contact zone's levels are skipped as any others,
  // and every new vertex of a kept level is a P1 combination of at most three coarse vertices
  // (weights positive, adding up to 1; ½ and ½ where it halves a coarse edge).
  const MeshHierarchy h =
      bisected_towards_corner<2>(build_mesh_hierarchy(make_square({.size = 0.25}), 0), 8, 1e-9);
  const SolverLevels<2> everywhere = skip_close_levels<2>(
      h, lowest_order_unknowns(h), [](int, int) { return true; }, 0);
  const SolverLevels<2> nowhere = skip_close_levels<2>(h, lowest_order_unknowns(h), kNoContact, 0);
  EXPECT_EQ(everywhere.mesh_levels, nowhere.mesh_levels);
  int chained = 0;
  for (const RefinementMaps& maps : everywhere.maps)
    for (int k = 0; k < static_cast<int>(maps.composed_weights.size()); ++k) {
      const CoarseVertexWeights& w = maps.composed_weights[k];
      ASSERT_TRUE(w.known());
      double sum = 0.0;
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(w.vertex[i] >= 0, w.weight[i] > 0.0);
        sum += w.weight[i];
      }
      EXPECT_EQ(sum, 1.0);
      if (halves_coarse_edge(maps, k))
        EXPECT_EQ(w.weight, (std::array<double, 3>{0.5, 0.5, 0.0}));
      else
        ++chained;
    }
  EXPECT_GT(chained, 0);
}

}  // namespace
}  // namespace fosls
