#pragma once
// The algebraic error of an iterate of a monotone method, estimated from its energy history,
// and the stopping rule that compares it with the discretisation error (docs/method.md §5.1).
//
// J is the FOSLS functional itself (BoxQp::energy = the functional), convex on the feasible
// set with minimiser x_h, so J(x_k) − J(x_h) ≥ ‖x_k − x_h‖² in the functional's norm: the
// energy excess E_k bounds the algebraic error. With a contraction E_k = q E_{k−1}, the
// decrease d_k = J(x_{k−1}) − J(x_k) = E_k (1 − q)/q, hence E_k = d_k q/(1 − q).

#include <vector>

#include "solvers/iteration_record.hpp"

namespace fosls {

/// Estimate of E_k = J(x_k) − J(x_h) from the last iterations of `history` (iteration 0
/// first): q is the largest of the last two ratios d_k/d_{k−1}, so that a lucky iteration does
/// not stop the solve early. Infinite while it cannot be estimated (fewer than three
/// iterations, J not decreasing, or q ≥ 1); 0 when the last iteration did not move J.
double energy_error_estimate(const std::vector<IterationRecord>& history);

/// Whether the algebraic error (E_k^½) is at most `fraction` times the discretisation error
/// estimated by J(x_k)^½: E_k ≤ fraction² J(x_k).
bool algebraic_error_is_small(const std::vector<IterationRecord>& history, double fraction);

}  // namespace fosls
