#pragma once
// Assembly of the FOSLS functional (docs/method.md §2) on the order-2 space P2 × RT1
// (docs/method.md §10) into the same bound-constrained QP as the lowest order, and the
// evaluation of the functional and the contact force at a solution.

#include <Eigen/Core>
#include <vector>

#include "assembly/fosls_assembler.hpp"
#include "fem/p2_rt1_space.hpp"

namespace fosls {

class P2Rt1Assembler {
 public:
  /// Contact groups must constrain along the body normal and be frictionless (std::logic_error
  /// otherwise: the case layer refuses such cases first).
  P2Rt1Assembler(const P2Rt1Space& space, const ProblemData<2>& data);

  /// A, b, bounds and constant of J on the free DOFs (vertex_gap holds the gap of each
  /// displacement node of a contact edge, +inf elsewhere); the lowest order's parallel scatter
  /// (assembly_pattern.hpp), under `deadline`.
  AssembledProblem assemble_system(const Deadline& deadline = {}) const;
  /// Full (rotated, scaled) DOF vector from the free DOFs of a solution.
  Vector full_vector(const AssembledProblem& p, const Vector& x_free) const;
  /// The functional's terms at a full DOF vector (`element`: per triangle, as FoslsAssembler).
  FunctionalParts functional(const Vector& x_full) const;
  /// ∫_Γ_C σn ds in physical units: the obstacle's force on the body.
  Point contact_force(const Vector& x_full) const;

  const P2Rt1Space& space() const { return space_; }

 private:
  using Local = LocalSystem<P2Rt1Space::kCellDofs>;
  void element_kernel(int t, Local& out) const;
  void rotate_local(int t, Local& loc) const;
  Vector essential_values() const;
  /// The Neumann fluxes of edge e into xd: the L² projection of the traction onto P1 on the
  /// edge, as the two end DOFs of each row.
  void set_neumann_values(int e, const GroupData<2>& g, Vector& xd) const;
  /// C3 ⟨u·d − g, σ_nn⟩ on the contact edges: a bilinear coupling of the S_n end DOFs with the
  /// normal displacements of the edge's three nodes, exact by Gauss quadrature.
  void add_contact_terms(const Vector& xd, SparseMatrix& a, Vector& b) const;
  /// Weight of (S_n at end j) × (u·d at node a of the edge: 0 = p, 1 = q, 2 = midpoint) in
  /// the contact term, divided by C3.
  static double contact_weight(int a, int j);
  /// The normal displacement of node a on contact edge e as (DOF, factor) pairs.
  std::array<std::pair<int, double>, 2> normal_displacement(int a, int e) const;

  const P2Rt1Space& space_;
  const ProblemData<2>& data_;
  double mu_ = 1.0;
  double kappa_ = 0.5;
  std::vector<double> node_gap_;
};

}  // namespace fosls
