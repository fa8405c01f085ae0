#pragma once
// Assembly of the FOSLS functional (docs/method.md §2–3) into a bound-constrained QP on the free
// DOFs of a FoslsSpace, and element-wise evaluation of the functional (the error estimator).

#include <Eigen/Core>
#include <vector>

#include "assembly/friction_terms.hpp"
#include "assembly/problem_data.hpp"
#include "core/box_qp.hpp"
#include "core/deadline.hpp"
#include "fem/fosls_space.hpp"

namespace fosls {

struct AssemblyPattern;

/// The discrete problem of one level.
struct AssembledProblem {
  BoxQp qp;             ///< over the free DOFs, rotated contact coordinates, scaled stresses
  Vector fixed_values;  ///< full vector: values of the fixed DOFs, zero elsewhere
  /// Stresses are computed in units of μ (σ = stress_scale · σ_scaled) so that the default
  /// weights are balanced whatever units the user works in.
  double stress_scale = 1.0;
  /// Gap g(v) at every vertex of a contact edge along its constraint direction, +inf elsewhere.
  std::vector<double> vertex_gap;
  /// Frictional contact edges and the kinks of their slip (friction_terms.hpp); empty without
  /// friction. Coulomb's bounds in qp and kinks are those of S_n = 0 until updated.
  FrictionLayout friction;
  Kinks kinks;
};

/// The functional split into its terms; `element` holds the C1 + C2 + C4 terms of each
/// triangle plus the contact term of its contact edge, if it has one.
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

class FoslsAssembler {
 public:
  /// Evaluates the data (not thread-safe functions) once, sequentially.
  FoslsAssembler(const FoslsSpace<2>& space, const ProblemData& data);

  /// A, b, bounds and constant of J on the free DOFs; O(N), element loop on both cores. The
  /// element loop polls `deadline` and throws TimeLimitReached once it has passed.
  AssembledProblem assemble_system(const Deadline& deadline = {}) const;

  /// Full (rotated, scaled) DOF vector from the free DOFs of a solution.
  Vector full_vector(const AssembledProblem& p, const Vector& x_free) const;

  /// Mean penetration u·n − g over contact edge e (negative where the gap is open), with u·n
  /// linear between its end points (U_n at a contact vertex, n_e·u at a Dirichlet one): the
  /// factor of S_n in the contact term.
  double edge_mean_penetration(const Vector& x_full, int e) const;

  /// The functional and its element-wise split at a full DOF vector.
  FunctionalParts functional(const Vector& x_full) const;

  const FoslsSpace<2>& space() const { return space_; }
  const ProblemData& data() const { return data_; }

 private:
  struct Local;
  void element_kernel(int t, Local& out) const;
  void rotate_local(int t, Local& loc) const;
  /// assemble_system's steps. The full vector of the fixed DOFs' values (Dirichlet
  /// displacements, Neumann fluxes scaled by μ, S_t = 0), zero elsewhere.
  Vector essential_values() const;
  /// The element terms into the pattern's matrix and b (the fixed DOFs' couplings moved to b),
  /// in parallel; returns each thread's part of the constant of J.
  std::vector<double> add_element_terms(const Vector& xd, AssemblyPattern& pattern, int threads,
                                        Vector& b, const Deadline& deadline) const;
  /// The contact term C3 ⟨u·n − g, σ_nn⟩ of every contact edge, and on frictional ones the
  /// bilinear part C3 ⟨Δu_t, σ_nt⟩ of the friction term.
  void add_contact_terms(const Vector& xd, SparseMatrix& a, Vector& b) const;
  /// U_n ≤ g at contact vertices, S_n ≤ 0 on contact edges.
  void set_contact_bounds(Vector& upper) const;

  const FoslsSpace<2>& space_;
  const ProblemData& data_;
  double mu_ = 1.0;
  double kappa_ = 0.5;  ///< λ / (2λ + 2μ), → ½ as λ → ∞
  /// Scaled f at quadrature point q (edge midpoint) of triangle t.
  Eigen::Vector2d body_force(int t, int q) const {
    if (body_force_.empty()) return Eigen::Vector2d::Zero();
    return {body_force_[t][2 * q], body_force_[t][2 * q + 1]};
  }
  /// Scaled f at the 3 quadrature points of each triangle; empty when f = 0.
  std::vector<std::array<double, 6>> body_force_;
  std::vector<double> vertex_gap_;
};

/// The full DOF vector of a solution: the fixed DOFs' values with the free ones put in place
/// (every space's full_vector).
Vector full_from_free(const Vector& fixed_values, const std::vector<int>& free_to_full,
                      const Vector& x_free);

/// Constraint directions at contact vertices for groups that constrain along the obstacle
/// normal (docs/method.md §1); empty when every contact group uses the body normal.
std::vector<Point> obstacle_vertex_normals(const Mesh& mesh, const ProblemData& data);

}  // namespace fosls
