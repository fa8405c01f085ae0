#pragma once
// The Galerkin product PᵀAP column by column, without forming A·P (issue 12): A·P of the
// finest level was the largest matrix of a multilevel solve, and Eigen's sparse products
// keep further temporaries of their result. Each coarse column J is (PᵀA P)_{:,J} =
// Pᵀ (A P_{:,J}), accumulated in dense work vectors of the thread that owns J.

#include "core/box_qp.hpp"

namespace fosls {

/// PᵀAP for symmetric A (its columns are its rows), compressed, rows sorted. Deterministic:
/// the same result on any number of threads.
SparseMatrix galerkin_product(const SparseMatrix& A, const SparseMatrix& P);

}  // namespace fosls
