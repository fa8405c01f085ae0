#pragma once
// Coulomb's fallback (issue 49, docs/method.md §8.4): where mmg's Coulomb iteration stalls, pdas
// (semismooth Newton on a CHOLMOD factorisation, the comparison solver on the same discrete
// problem) takes over from mmg's iterate and finishes the solve. This file holds when mmg counts
// as stalled and how the two solves' reports become one.

#include <string>
#include <vector>

#include "solvers/iteration_record.hpp"

namespace fosls {

struct SolverReport;

/// mmg has stalled at iteration k ≥ `earliest` when the best Coulomb residual of the last
/// `window` iterations is above `rate`^window times the best one before them: it fell more
/// slowly than `rate` per iteration on average (updates make the residual jump, so single
/// iterations say little; the best of a window does not jump). The defaults are measured
/// (docs/validation.md §13, "Robustness cases with Coulomb friction"): every case that reaches
/// the 40 iterations falls faster than 0.8 per iteration over every such window after
/// its 20th iteration, and a case that falls more slowly there needs more than 40. `window` 0
/// never stalls.
struct StallTest {
  int earliest = 15;
  int window = 10;
  double rate = 0.85;
  static StallTest never() { return {0, 0, 0.0}; }
  bool stalled(const std::vector<IterationRecord>& history) const;
};

/// Where the fallback may be used: pdas factorises the whole problem (CHOLMOD) in every step,
/// and its time and memory grow faster than mmg's. The hard cases it is for are small; on a
/// large mesh where the stall test fires (cattaneo_mindlin's press step at refinements 5)
/// finishing with pdas cost more time and several times the memory of letting mmg go on
/// (docs/performance.md, "The fallback where mmg stalls"). Above this many unknowns mmg goes on
/// to its max_iterations instead (docs/method.md §8.4).
inline constexpr int kFallbackMaxUnknowns = 200000;

/// `mmg`, stalled after its iterations, continued by `pdas` from its last iterate: one report
/// whose history, iterations, updates and times are both solves' in order (pdas's iteration 0,
/// mmg's last iterate, is not repeated), its outcome pdas's, and `switched_at` mmg's count.
void append_fallback(SolverReport& mmg, const SolverReport& pdas);

}  // namespace fosls
