#pragma once
// The non-smooth part of a frictional problem (docs/method.md §8): J(x) + Σ_k w_k |x_{d_k} − o_k|,
// one kink per tangential contact displacement, separable like the bounds.

#include <cmath>
#include <vector>

#include "core/box_qp.hpp"

namespace fosls {

struct Kinks {
  std::vector<int> dof;        ///< the DOF of each kink
  std::vector<double> weight;  ///< w_k ≥ 0
  std::vector<double> at;      ///< o_k, where the kink is
  /// The kinks' value at fixed DOFs (a roller through a frictional zone), part of J.
  double constant = 0.0;

  bool empty() const { return dof.empty(); }
  int size() const { return static_cast<int>(dof.size()); }
  /// Σ_k w_k |x_{d_k} − o_k| + constant.
  double energy(const Vector& x) const {
    double e = constant;
    for (int k = 0; k < size(); ++k) e += weight[k] * std::abs(x[dof[k]] - at[k]);
    return e;
  }
};

}  // namespace fosls
