#include "assembly/contact_weight.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "assembly/fosls_assembler.hpp"

namespace fosls {

namespace {

/// The matrix of J on `space` with the given contact weight.
template <int dim>
SparseMatrix functional_matrix(const FoslsSpace<dim>& space, ProblemData<dim> data, double c3) {
  data.weights.c3 = c3;
  return FoslsAssembler<dim>(space, data).assemble_system().qp.A;
}

/// Cholesky factor of A0. Without a Neumann boundary an incompressible A0 can be singular (the
/// constant pressure); a shift of 1e-12 of its diagonal then keeps the factorisation defined
/// and moves c3* by a relative 1e-12 at most.
struct A0Solver {
  explicit A0Solver(const SparseMatrix& a0) {
    llt.compute(a0);
    if (llt.info() == Eigen::Success) return;
    SparseMatrix shifted = a0;
    for (int i = 0; i < shifted.rows(); ++i) shifted.coeffRef(i, i) *= 1.0 + 1e-12;
    llt.compute(shifted);
  }
  Eigen::SimplicialLLT<SparseMatrix> llt;
};

/// The smallest eigenvalue μ_min of B x = μ A0 x by Lanczos on A0⁻¹B, which is self-adjoint in
/// the A0 inner product; full reorthogonalisation (the steps are few and the vectors short).
/// Stops once the smallest Ritz value's residual is below 1e-3 of it (the limit is then within
/// about 0.1 %), or after 80 steps. Ritz values lie inside the spectrum, so an early stop errs
/// towards a larger c3*; the rule's factor ½ covers that. `broke_down` is set when a Lanczos
/// vector lost its A0 norm to rounding (A0 nearly singular: the iteration cannot go on).
double smallest_pencil_eigenvalue(const SparseMatrix& a0, const SparseMatrix& b, int& steps,
                                  bool& broke_down) {
  const int n = static_cast<int>(a0.rows());
  A0Solver solver(a0);
  if (solver.llt.info() != Eigen::Success) return -std::numeric_limits<double>::infinity();
  std::mt19937 random(20191105);  // deterministic: the same case gives the same c3
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vector v(n);
  for (int i = 0; i < n; ++i) v[i] = uniform(random);
  std::vector<Vector> basis, a0_basis;
  std::vector<double> alpha, beta;
  double theta = 0.0;
  const int max_steps = std::min(80, n);
  for (steps = 0; steps < max_steps; ++steps) {
    Vector a0v = a0 * v;
    const double norm = std::sqrt(v.dot(a0v));
    if (!(norm > 0)) {
      broke_down = true;
      break;
    }
    v /= norm, a0v /= norm;
    if (steps > 0) beta.push_back(norm);
    basis.push_back(v), a0_basis.push_back(a0v);
    const Vector bv = b * v;
    alpha.push_back(v.dot(bv));
    Vector w = solver.llt.solve(bv);
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t i = 0; i < basis.size(); ++i) w -= a0_basis[i].dot(w) * basis[i];
    const int k = static_cast<int>(alpha.size());
    Eigen::MatrixXd t = Eigen::MatrixXd::Zero(k, k);
    for (int i = 0; i < k; ++i) t(i, i) = alpha[i];
    for (int i = 0; i + 1 < k; ++i) t(i, i + 1) = t(i + 1, i) = beta[i];
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz(t);
    theta = ritz.eigenvalues()[0];
    const double next_beta = std::sqrt(std::max(0.0, w.dot(a0 * w)));
    const double residual = next_beta * std::abs(ritz.eigenvectors()(k - 1, 0));
    if (k >= 5 && residual <= 1e-3 * std::abs(theta)) break;
    v = w;
  }
  ++steps;
  return theta;
}

/// The largest c3 in [10⁻⁶, 1] for which A0 + c3 B has a Cholesky factorisation, by bisection
/// in log c3 to 0.3 %: the definition of c3* itself, used where Lanczos cannot run. Frictional
/// contact on a body that is mostly contact boundary (the wedge of docs/validation.md §13) leaves
/// σ_nn and σ_nt free on most of the boundary, and A0 is then too near singular for A0⁻¹.
double definiteness_limit_by_bisection(const SparseMatrix& a0, const SparseMatrix& b) {
  const auto definite = [&](double c3) {
    const SparseMatrix a = a0 + c3 * b;
    Eigen::SimplicialLLT<SparseMatrix> llt(a);
    return llt.info() == Eigen::Success;
  };
  if (definite(1.0)) return std::numeric_limits<double>::infinity();  // the rule caps c3 anyway
  if (!definite(1e-6)) return 0.0;
  double lo = -6.0, hi = 0.0;  // log10 c3
  for (int k = 0; k < 12; ++k) {
    const double mid = 0.5 * (lo + hi);
    (definite(std::pow(10.0, mid)) ? lo : hi) = mid;
  }
  return std::pow(10.0, lo);
}

}  // namespace

template <int dim>
ContactWeightLimit contact_weight_limit(const SimplexHierarchy<dim>& meshes,
                                        const ProblemData<dim>& data, int max_dofs) {
  const auto roles = data.boundary_roles();
  ContactWeightLimit out;
  std::unique_ptr<FoslsSpace<dim>> chosen;
  for (int level = 0; level < meshes.num_levels(); ++level) {
    const SimplexMesh<dim>& mesh = meshes.meshes[level];
    auto space =
        std::make_unique<FoslsSpace<dim>>(mesh, roles, obstacle_vertex_normals(mesh, data));
    if (chosen && space->num_free() > max_dofs) break;
    chosen = std::move(space);
    out.level = level;
  }
  out.dofs = chosen->num_free();
  const SparseMatrix a0 = functional_matrix(*chosen, data, 0.0);
  const SparseMatrix b = functional_matrix(*chosen, data, 1.0) - a0;
  bool broke_down = false;
  const double mu_min = smallest_pencil_eigenvalue(a0, b, out.lanczos_steps, broke_down);
  out.limit = mu_min < 0 ? -1.0 / mu_min : std::numeric_limits<double>::infinity();
  // A breakdown before a negative Ritz value says nothing about definiteness.
  if (broke_down && !(mu_min < 0)) out.limit = definiteness_limit_by_bisection(a0, b);
  return out;
}

template ContactWeightLimit contact_weight_limit<2>(const SimplexHierarchy<2>&,
                                                    const ProblemData<2>&, int);
template ContactWeightLimit contact_weight_limit<3>(const SimplexHierarchy<3>&,
                                                    const ProblemData<3>&, int);

double automatic_contact_weight(const ContactWeightLimit& limit) {
  return std::min(kDefaultContactWeight, 0.5 * limit.limit);
}

}  // namespace fosls
