#pragma once
// Level transfers P_j : X_{j−1} → X_j, the natural embeddings of docs/method.md §4.

#include <Eigen/Sparse>
#include <utility>
#include <vector>

#include "fem/fosls_space.hpp"
#include "mesh/refinement.hpp"

namespace fosls {

/// Prolongation of full Cartesian DOF vectors: P1 interpolation for u; for σ a fine edge that
/// halves a coarse edge gets half the coarse flux and a kept coarse edge all of it (sign by
/// orientation), and an edge inside a coarse triangle gets the exact flux of the coarse
/// (linear) RT0 field, evaluated on the coarse triangle's geometry (midpoints at their
/// unsnapped positions). Serves red refinement and newest-vertex bisection alike.
///
/// On a curved boundary this keeps two properties that matter more than reproducing the
/// coarse field where the fine mesh bulges out of it: a fine boundary half's flux depends on
/// its parent edge's coarse flux only (so fixing or truncating it touches no other coarse
/// function), and every fine triangle's divergence is the coarse one times an area ratio (so
/// divergence-free coarse fields stay divergence-free). Evaluating the coarse field on the
/// snapped geometry instead slows the multilevel method on the Hertz mesh (docs/performance.md,
/// "Measurements behind choices in the code"): the other coarse edges' fields then carry flux
/// through curved Neumann halves, whose fixed fluxes drop it.
Eigen::SparseMatrix<double> cartesian_prolongation(const Mesh& coarse, const Mesh& fine,
                                                   const RefinementMaps& maps);

/// The fine edges that a flux crosses on its way from the fine triangle of boundary edge `from`
/// to the fine triangle of boundary edge `to` (the two halves of one coarse edge) through the
/// interior of their coarse triangle, in order, each with the sign of its global normal
/// relative to the direction of travel. Empty when there is no such path.
std::vector<std::pair<int, int>> flux_path(const Mesh& fine, const RefinementMaps& maps, int from,
                                           int to);

/// The same transfer between the free DOFs of two levels in their rotated contact coordinates:
/// rows of fixed fine DOFs and columns of fixed coarse DOFs are dropped. On a curved contact
/// edge the halves' normals differ from the coarse edge's, so the coarse field has tangential
/// flux through them that σ_nt = 0 (S_t fixed) forbids; instead of dropping it, which would
/// change the divergence of the halves' fine triangles by O(h/R)/|T| and make the coarse
/// contact functions too stiff to represent tractions on the curve, the two halves' tangential
/// fluxes are routed into each other through the coarse triangle's interior (they cancel up to
/// O((h/R)²)).
Eigen::SparseMatrix<double> free_prolongation(const FoslsSpace<2>& coarse,
                                              const FoslsSpace<2>& fine, const RefinementMaps& maps,
                                              const Eigen::SparseMatrix<double>& cartesian);

}  // namespace fosls
