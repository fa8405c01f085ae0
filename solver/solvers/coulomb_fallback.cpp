#include "solvers/coulomb_fallback.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/solve_loop.hpp"

namespace fosls {

bool StallTest::stalled(const std::vector<IterationRecord>& history) const {
  const int k = static_cast<int>(history.size()) - 1;
  if (window <= 0 || k < std::max(earliest, window)) return false;
  auto best = [&](int from, int to) {  // min of kkt_residual over history[from..to)
    double b = history[from].kkt_residual;
    for (int i = from + 1; i < to; ++i) b = std::min(b, history[i].kkt_residual);
    return b;
  };
  return best(k - window + 1, k + 1) > std::pow(rate, window) * best(0, k - window + 1);
}

void append_fallback(SolverReport& mmg, const SolverReport& pdas) {
  const int switched_at = mmg.iterations;
  for (std::size_t i = 1; i < pdas.history.size(); ++i) {
    IterationRecord rec = pdas.history[i];
    rec.iteration += switched_at;
    rec.time_s += mmg.solve_s;
    mmg.history.push_back(rec);
  }
  mmg.switched_at = switched_at;
  mmg.iterations += pdas.iterations;
  mmg.converged = pdas.converged;
  mmg.converged_by = pdas.converged_by;
  mmg.cancelled = pdas.cancelled;
  mmg.time_limited = pdas.time_limited;
  mmg.final_kkt = pdas.final_kkt;
  mmg.asymptotic_rate = pdas.asymptotic_rate;
  mmg.algebraic_error = pdas.algebraic_error;
  mmg.estimator = pdas.estimator;
  mmg.active = pdas.active;
  mmg.setup_s += pdas.setup_s;
  mmg.solve_s += pdas.solve_s;
  mmg.setup_mib = std::max(mmg.setup_mib, pdas.setup_mib);
  mmg.update_changes.insert(mmg.update_changes.end(), pdas.update_changes.begin(),
                            pdas.update_changes.end());
  mmg.message = pdas.message;
}

}  // namespace fosls
