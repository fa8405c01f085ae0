#pragma once
// Assembly of the FOSLS functional (docs/method.md §2–3, §11) into a bound-constrained QP on the
// free DOFs of a FoslsSpace, in 2D and 3D, and element-wise evaluation of the functional (the
// error estimator).

#include <Eigen/Core>
#include <vector>

#include "assembly/assembly_pattern.hpp"
#include "assembly/friction_terms.hpp"
#include "assembly/problem_data.hpp"
#include "core/box_qp.hpp"
#include "core/deadline.hpp"
#include "fem/fosls_space.hpp"

namespace fosls {

/// The discrete problem of one level.
struct AssembledProblem {
  BoxQp qp;             ///< over the free DOFs, rotated contact coordinates, scaled stresses
  Vector fixed_values;  ///< full vector: values of the fixed DOFs, zero elsewhere
  /// Stresses are computed in units of μ (σ = stress_scale · σ_scaled) so that the default
  /// weights are balanced whatever units the user works in.
  double stress_scale = 1.0;
  /// Gap g(v) at every vertex (every displacement node at order 2) of a contact facet along its
  /// constraint direction, +inf elsewhere.
  std::vector<double> vertex_gap;
  /// Frictional contact edges and the kinks of their slip (friction_terms.hpp, 2D); empty
  /// without friction. Coulomb's bounds in qp and kinks are those of S_n = 0 until updated.
  FrictionLayout friction;
  Kinks kinks;
};

/// The functional split into its terms; `element` holds the C1 + C2 + C4 terms of each cell
/// plus the contact term of its contact facet, if it has one.
struct FunctionalParts {
  double momentum = 0.0;      ///< C1 ‖div σ + f‖²
  double constitutive = 0.0;  ///< C2 ‖Aσ − ε(u)‖² (volumetric part × c2_volumetric)
  double contact = 0.0;       ///< C3 ⟨u·n − g, σ_nn⟩
  double asymmetry = 0.0;     ///< C4 ‖as σ‖²
  /// C3 ∫ (σ_nt Δu_t + s |Δu_t|)/μ on frictional edges (docs/method.md §8; not in `element`).
  double friction = 0.0;
  std::vector<double> element;
  double total() const { return momentum + constitutive + contact + asymmetry + friction; }
};

template <int dim>
class FoslsAssembler {
 public:
  /// Evaluates the data (not thread-safe functions) once, sequentially.
  FoslsAssembler(const FoslsSpace<dim>& space, const ProblemData<dim>& data);

  /// A, b, bounds and constant of J on the free DOFs; O(N), element loop on every core
  /// (assembly_pattern.hpp). The element loop polls `deadline` and throws TimeLimitReached once
  /// it has passed.
  AssembledProblem assemble_system(const Deadline& deadline = {}) const;

  /// Full (rotated, scaled) DOF vector from the free DOFs of a solution.
  Vector full_vector(const AssembledProblem& p, const Vector& x_free) const;

  /// Mean penetration u·n − g over contact facet f (negative where the gap is open), with u·n
  /// linear between its vertices (U_n at a contact vertex, n_f·u at a Dirichlet one): the factor
  /// of S_n in the contact term.
  double facet_mean_penetration(const Vector& x_full, int f) const;
  double edge_mean_penetration(const Vector& x_full, int e) const requires(dim == 2) {
    return facet_mean_penetration(x_full, e);
  }

  /// The functional and its element-wise split at a full DOF vector.
  FunctionalParts functional(const Vector& x_full) const;

  const FoslsSpace<dim>& space() const { return space_; }
  const ProblemData<dim>& data() const { return data_; }

 private:
  using Local = LocalSystem<FoslsSpace<dim>::kCellDofs>;
  void element_kernel(int t, Local& out) const;
  void rotate_local(int t, Local& loc) const;
  /// assemble_system's steps. The full vector of the fixed DOFs' values (Dirichlet
  /// displacements, Neumann fluxes scaled by μ, S_t = 0), zero elsewhere.
  Vector essential_values() const;
  /// The prescribed displacement components of Dirichlet groups into xd: first the groups that
  /// prescribe every component, then the rollers at the vertices those do not hold (a full
  /// group's data win), on the contact boundary as the frame's fixed tangential U_t.
  void set_dirichlet_values(Vector& xd) const;
  /// The flux of the traction through Neumann facet f, in units of μ.
  void set_neumann_values(int f, const GroupData<dim>& g, Vector& xd) const;
  /// weight · S · (u·d)_v for the free flux DOF s into A, symmetric, or, where u is fixed, into
  /// b: u·d at a contact vertex is its rotated component `component` (U_n: 0, U_t: 1), elsewhere
  /// d·u.
  void couple_flux_with_vertex(int s, int v, int component, const Vec<dim>& d, double weight,
                               const Vector& xd, SparseMatrix& a, Vector& b) const;
  /// The contact term C3 ⟨u·n − g, σ_nn⟩ of every contact facet.
  void add_contact_terms(const Vector& xd, SparseMatrix& a, Vector& b) const;
  /// On frictional contact edges (2D) the bilinear part C3 ⟨Δu_t, σ_nt⟩ of the friction term,
  /// Δu_t the slip from the reference state (friction_terms.hpp).
  void add_friction_coupling(const Vector& xd, SparseMatrix& a, Vector& b) const requires(dim == 2);
  /// U_n ≤ g at contact vertices, S_n ≤ 0 on contact facets.
  void set_contact_bounds(Vector& upper) const;

  const FoslsSpace<dim>& space_;
  const ProblemData<dim>& data_;
  double mu_ = 1.0;
  double kappa_ = 0.5;  ///< λ / (dλ + 2μ), → 1/d as λ → ∞
  /// Scaled f at the d + 1 quadrature points of each cell; empty when f = 0.
  std::vector<std::array<double, dim*(dim + 1)>> body_force_;
  Vec<dim> body_force(int t, int q) const;
  std::vector<double> vertex_gap_;
};

extern template class FoslsAssembler<2>;
extern template class FoslsAssembler<3>;

/// The full DOF vector of a solution: the fixed DOFs' values with the free ones put in place
/// (every space's full_vector).
Vector full_from_free(const Vector& fixed_values, const std::vector<int>& free_to_full,
                      const Vector& x_free);

}  // namespace fosls
