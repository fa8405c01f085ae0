#pragma once
// Level transfers P_j : X_{j−1} → X_j, the natural embeddings of docs/method.md §4.

#include <Eigen/Sparse>

#include "fem/fosls_space.hpp"
#include "mesh/refinement.hpp"

namespace fosls {

/// Prolongation of full Cartesian DOF vectors: P1 interpolation for u; for σ a fine edge that
/// halves a coarse edge gets half the coarse flux and a kept coarse edge all of it (sign by
/// orientation), and an edge inside a coarse triangle gets the exact flux of the coarse
/// (linear) RT0 field, evaluated on the coarse triangle's geometry (midpoints at their
/// unsnapped positions). Serves red refinement and newest-vertex bisection alike.
Eigen::SparseMatrix<double> cartesian_prolongation(const Mesh& coarse, const Mesh& fine,
                                                   const RefinementMaps& maps);

/// The same transfer between the free DOFs of two levels in their rotated contact coordinates:
/// rows of fixed fine DOFs and columns of fixed coarse DOFs are dropped.
Eigen::SparseMatrix<double> free_prolongation(const FoslsSpace& coarse, const FoslsSpace& fine,
                                              const Eigen::SparseMatrix<double>& cartesian);

}  // namespace fosls
