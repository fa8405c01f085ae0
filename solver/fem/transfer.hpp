#pragma once
// Level transfers P_j : X_{j−1} → X_j, the natural embeddings of docs/method.md §4 and §11, for
// triangles and tetrahedra.

#include <Eigen/Sparse>
#include <cmath>
#include <utility>
#include <vector>

#include "fem/fosls_space.hpp"

namespace fosls {

/// Prolongation of full Cartesian DOF vectors: P1 interpolation for u; for σ a fine facet inside
/// a coarse facet carries its share of the coarse flux (RT0's normal component is constant on a
/// facet: a half of an edge ½, a kept edge 1, a quarter of a face ¼; parent_facet_share) with
/// the sign of the two normals' agreement, and a facet inside a coarse cell gets the exact flux
/// of the coarse (linear) RT0 field. Serves red refinement and newest-vertex bisection alike.
///
/// In 2D that flux is evaluated on the coarse triangle's geometry (midpoints at their unsnapped
/// positions). On a curved boundary this keeps two properties that matter more than
/// reproducing the coarse field where the fine mesh bulges out of it: a fine boundary half's
/// flux depends on its parent edge's coarse flux only (so fixing or truncating it touches no
/// other coarse function), and every fine triangle's divergence is the coarse one times an area
/// ratio (so divergence-free coarse fields stay divergence-free). Evaluating the coarse field
/// on the snapped geometry instead slows the multilevel method on the Hertz mesh
/// (docs/performance.md, "Measurements behind choices in the code"): the other coarse edges'
/// fields then carry flux through curved Neumann halves, whose fixed fluxes drop it. 3D
/// evaluates it on the fine faces as they are (docs/method.md §11).
template <int dim>
Eigen::SparseMatrix<double> cartesian_prolongation(const SimplexMesh<dim>& coarse,
                                                   const SimplexMesh<dim>& fine,
                                                   const SimplexRefinementMaps<dim>& maps);

/// The share of its parent's flux that fine facet f (inside a coarse facet) carries: ½ for a
/// half of an edge, 1 for a kept edge; in 3D the exact fraction of the parent face's area that the
/// refinement maps hold (¼ for red refinement's quarters; ½, ¼, … or 1 under bisection).
double parent_facet_share(const Mesh& fine, const RefinementMaps& maps, int f);
double parent_facet_share(const TetMesh& fine, const TetRefinementMaps& maps, int f);

/// The fine edges that a flux crosses on its way from the fine triangle of boundary edge `from`
/// to the fine triangle of boundary edge `to` (the two halves of one coarse edge) through the
/// interior of their coarse triangle, in order, each with the sign of its global normal
/// relative to the direction of travel. Empty when there is no such path. (2D: the tangential
/// routing of free_prolongation and the contact links' flux moves.)
std::vector<std::pair<int, int>> flux_path(const Mesh& fine, const RefinementMaps& maps, int from,
                                           int to);

/// The entries of a full transfer `rotated` (rows: the fine space's DOFs, columns: the coarse
/// space's, both in their rotated coordinates) that map a free coarse DOF to a free fine one,
/// as triplets between free indices in column order; entries of magnitude `drop` or less are
/// left out (rounding left by the rotations, or exact zeros with drop = 0). Every level's
/// restriction to free DOFs — the lowest order's transfers and order 2's embedding.
template <class FineSpace, class CoarseSpace>
std::vector<Eigen::Triplet<double>> free_triplets(const Eigen::SparseMatrix<double>& rotated,
                                                  const FineSpace& fine, const CoarseSpace& coarse,
                                                  double drop) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(rotated.nonZeros());
  for (int col = 0; col < rotated.outerSize(); ++col) {
    const int cf = coarse.free_index(col);
    if (cf < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(rotated, col); it; ++it)
      if (const int rf = fine.free_index(static_cast<int>(it.row()));
          rf >= 0 && std::abs(it.value()) > drop)
        t.emplace_back(rf, cf, it.value());
  }
  return t;
}

/// Rounding noise below which an entry of the lowest order's free transfer is dropped.
constexpr double kTransferNoise = 1e-15;

/// The transfer between the free DOFs of two levels in their rotated contact coordinates:
/// rows of fixed fine DOFs and columns of fixed coarse DOFs are dropped. On a curved contact
/// edge (2D) the halves' normals differ from the coarse edge's, so the coarse field has
/// tangential flux through them that σ_nt = 0 (S_t fixed) forbids; instead of dropping it,
/// which would change the divergence of the halves' fine triangles by O(h/R)/|T| and make the
/// coarse contact functions too stiff to represent tractions on the curve, the two halves'
/// tangential fluxes are routed into each other through the coarse triangle's interior (they
/// cancel up to O((h/R)²)). In 3D that part falls on the fixed S_t and is dropped
/// (docs/method.md §11).
template <int dim>
Eigen::SparseMatrix<double> free_prolongation(const FoslsSpace<dim>& coarse,
                                              const FoslsSpace<dim>& fine,
                                              const SimplexRefinementMaps<dim>& maps,
                                              const Eigen::SparseMatrix<double>& cartesian);

}  // namespace fosls
