#include "assembly/error_indicators.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace fosls {

double ErrorEstimate::estimator() const { return std::sqrt(std::max(0.0, total)); }

ErrorEstimate error_estimate(const FunctionalParts& parts) {
  ErrorEstimate e;
  e.indicators.reserve(parts.element.size());
  for (double eta2 : parts.element) e.indicators.push_back(std::max(0.0, eta2));
  e.total = std::accumulate(e.indicators.begin(), e.indicators.end(), 0.0);
  return e;
}

std::vector<int> dorfler_marking(const std::vector<double>& indicators, double theta) {
  if (!(theta > 0.0 && theta <= 1.0))
    throw std::invalid_argument("dorfler_marking: theta must be in (0, 1]");
  const double total = std::accumulate(indicators.begin(), indicators.end(), 0.0);
  if (!(total > 0.0)) return {};
  std::vector<int> order(indicators.size());
  std::iota(order.begin(), order.end(), 0);
  // A full sort is O(N log N), a small part of a solve; it makes the marked set the minimal one.
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return indicators[a] > indicators[b] || (indicators[a] == indicators[b] && a < b);
  });
  // Summing in decreasing order and stopping at θ·total leaves no rounding gap at θ = 1: the
  // last positive indicator is taken when the partial sum falls short by round-off.
  double sum = 0.0;
  std::size_t count = 0;
  while (count < order.size() && sum < theta * total && indicators[order[count]] > 0.0)
    sum += indicators[order[count++]];
  order.resize(count);
  return order;
}

}  // namespace fosls
