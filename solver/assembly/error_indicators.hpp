#pragma once
// The FOSLS functional as an a posteriori error estimator, and Dörfler (bulk) marking.
//
// The functional vanishes only at the exact solution and is equivalent to the error in the
// norm of the first-order system, so its share on a triangle is a local error indicator that
// costs one element loop: η_T² = C1 ‖div σ + f‖²_T + C2 ‖Aσ − ε(u)‖²_T + C4 ‖as σ‖²_T plus
// the contact term C3 ⟨u·n − g, σ_nn⟩ of T's contact edge. The global estimator is
// η = (Σ η_T²)^½ = J^½; its measured efficiency is in docs/validation.md.

#include <vector>

#include "assembly/fosls_assembler.hpp"

namespace fosls {

/// The indicators of one solution.
struct ErrorEstimate {
  std::vector<double> indicators;  ///< η_T² per triangle (never negative)
  double total = 0.0;              ///< Σ η_T² = J
  double estimator() const;        ///< J^½
};

/// η_T² from the element-wise split of the functional (FoslsAssembler::functional). A
/// contact term is ≥ 0 at every feasible iterate (u·n ≤ g and σ_nn ≤ 0); negative round-off
/// is clipped so that marking never sees a negative share.
ErrorEstimate error_estimate(const FunctionalParts& parts);

/// Dörfler marking: the fewest triangles whose indicators sum to at least θ·Σ η_T², taken in
/// decreasing order of η_T² (ties by index, so the result is deterministic); θ in (0, 1].
/// Returns their indices in that order; empty when every indicator is zero.
std::vector<int> dorfler_marking(const std::vector<double>& indicators, double theta);

}  // namespace fosls
