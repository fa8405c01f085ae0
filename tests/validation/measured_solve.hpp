#pragma once
// A linear problem (no contact) solved directly on its finest level, with the FOSLS
// functional per triangle (the estimator η_T²) next to the true error against an exact
// solution: what the validation programs compare (docs/validation.md, "Error estimator"
// and §11).

#include <Eigen/CholmodSupport>
#include <array>
#include <stdexcept>
#include <vector>

#include "assembly/discretization.hpp"
#include "post/fe_field.hpp"

namespace fosls::testing {

struct MeasuredSolve {
  FunctionalParts parts;  ///< the functional, element by element (η_T²)
  /// Σ_T of ‖u − u_h‖², ‖∇(u − u_h)‖², ‖σ − σ_h‖², ‖div(σ − σ_h)‖² (element_error).
  std::array<double, 4> total = {0, 0, 0, 0};
  std::vector<double> element_error;  ///< e_T², the four parts summed
  /// The true error (‖u − u_h‖²_H¹ + ‖σ − σ_h‖²_H(div))^½.
  double error() const { return std::sqrt(total[0] + total[1] + total[2] + total[3]); }
};

/// Solves the discrete problem with CHOLMOD (exactly, so no algebraic error enters) and
/// measures it against `exact`.
inline MeasuredSolve measure_linear_solve(const Discretization<2>& disc,
                                          const ExactSolution& exact) {
  const auto& p = disc.problem();
  Eigen::CholmodSupernodalLLT<SparseMatrix> llt(p.qp.A);
  if (llt.info() != Eigen::Success) throw std::runtime_error("CHOLMOD factorisation failed");
  const Vector full = disc.assembler().full_vector(p, llt.solve(p.qp.b));
  MeasuredSolve m;
  m.parts = disc.assembler().functional(full);
  const FeField field(disc.finest_space(), full, p.stress_scale);
  const int nt = disc.meshes().finest().num_triangles();
  m.element_error.resize(nt);
  for (int t = 0; t < nt; ++t) {
    const auto e = element_error(field, exact, t);
    for (int k = 0; k < 4; ++k) m.total[k] += e[k];
    m.element_error[t] = e[0] + e[1] + e[2] + e[3];
  }
  return m;
}

}  // namespace fosls::testing
