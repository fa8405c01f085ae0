#include "solvers/algebraic_error.hpp"

#include <algorithm>
#include <limits>

namespace fosls {

double energy_error_estimate(const std::vector<IterationRecord>& history) {
  constexpr double kUnknown = std::numeric_limits<double>::infinity();
  const int k = static_cast<int>(history.size()) - 1;
  if (k < 3) return kUnknown;
  auto decrease = [&](int i) { return history[i - 1].energy - history[i].energy; };
  const double d0 = decrease(k - 2), d1 = decrease(k - 1), d2 = decrease(k);
  if (d2 == 0.0) return 0.0;
  if (d0 <= 0.0 || d1 <= 0.0 || d2 < 0.0) return kUnknown;
  const double q = std::max(d2 / d1, d1 / d0);
  if (q >= 1.0) return kUnknown;
  return d2 * q / (1.0 - q);
}

bool algebraic_error_is_small(const std::vector<IterationRecord>& history, double fraction) {
  if (history.empty()) return false;
  const double energy = std::max(0.0, history.back().energy);
  return energy_error_estimate(history) <= fraction * fraction * energy;
}

}  // namespace fosls
