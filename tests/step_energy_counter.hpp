#pragma once
// The adaptive loop's observer for tests: counts the fine-level sweeps of every step's solve and
// the sweeps after which J increased within that solve (each step starts afresh from its
// prolongated iterate, so J is compared within a step only).
#include <cmath>
#include <limits>

#include "strategy/level_loop.hpp"

namespace fosls::testing {

struct StepEnergyCounter {
  int sweeps = 0, increases = 0;
  double last_energy = 0.0;

  /// Refers to this counter, which must outlive the solve.
  LevelLoopObserver observer() {
    LevelLoopObserver o;
    o.on_step = [this](int, long long) { last_energy = std::numeric_limits<double>::infinity(); };
    o.solver.on_sweep = [this](double energy) {
      if (energy > last_energy + 1e-13 * (std::abs(last_energy) + 1.0)) ++increases;
      last_energy = energy;
      ++sweeps;
    };
    return o;
  }
};

}  // namespace fosls::testing
