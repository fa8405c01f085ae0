#pragma once
// What a solver reports after every iteration, and the hooks of the solve loop.

#include <functional>

namespace fosls {

/// One iteration of a solver (also one entry of the result's `history`).
struct IterationRecord {
  int iteration = 0;
  double energy = 0.0;        ///< J(x_k)
  double correction = 0.0;    ///< energy norm ‖x_k − x_{k−1}‖_A
  double kkt_residual = 0.0;  ///< ‖x − P_K(x − (Ax − b))‖₂
  int active = 0;             ///< size of the active set
  int changed = 0;            ///< DOFs whose active/inactive state changed
  double time_s = 0.0;        ///< since the start of the solve
};

/// Observer of the solve loop. Every member is optional.
struct SolverObserver {
  /// After every iteration (including iteration 0, the initial iterate).
  std::function<void(const IterationRecord&)> on_iteration;
  /// Polled once per iteration; returning true stops the solve (reported as cancelled).
  std::function<bool()> cancelled;
  /// Polled once per iteration; returning true stops the solve at the last iterate (reported
  /// as time_limited: the case's solver.time_limit_s ran out).
  std::function<bool()> out_of_time;
  /// After every fine-level smoother sweep, with J of the current iterate (for tests of the
  /// monotonicity invariant; costs an O(n) energy evaluation per sweep when set).
  std::function<void(double energy)> on_sweep;
};

}  // namespace fosls
