#pragma once
// The solve of a case's finest mesh in the order-2 space P2 × RT1 (docs/method.md §10): the
// lowest-order discretisation of the same meshes gives the levels below it, and its output
// (contact, VTU) is written from the order-2 solution's lowest-order interpolant.

#include "assembly/discretization.hpp"
#include "fem/p2_rt1_space.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

struct Order2Solution {
  Vector x;  ///< the order-2 space's free DOFs
  Vector
      interpolant;  ///< its lowest-order interpolant: full, rotated DOFs of lowest.finest_space()
  FunctionalParts parts;  ///< the functional of the order-2 solution (`element` per triangle)
  SolverReport report;
  double assembly_s = 0.0;  ///< the order-2 assembly and the level hierarchy
  double assembly_mib = 0.0, hierarchy_mib = 0.0;
};

/// Assembles the order-2 problem on lowest.meshes().finest() and solves it with
/// options.method (mmg on the lowest-order hierarchy with the order-2 level on top, or pdas).
/// Throws IndefiniteSystemError when the weights make the matrix indefinite.
Order2Solution solve_order2(const Discretization<2>& lowest, const P2Rt1Space& space,
                            const SolverOptions& options, const SolverObserver& observer);

}  // namespace fosls
