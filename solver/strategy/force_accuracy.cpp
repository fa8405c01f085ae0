#include "strategy/force_accuracy.hpp"

#include <algorithm>
#include <cmath>

namespace fosls {

namespace {

double distance(const ForceComponents& a, const ForceComponents& b) {
  ForceComponents d = a;
  for (std::size_t i = 0; i < d.size(); ++i) d[i] -= b[i];
  return force_norm(d);
}

/// (a − b)·c.
double dot_of_difference(const ForceComponents& a, const ForceComponents& b,
                         const ForceComponents& c) {
  double s = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) s += (a[i] - b[i]) * c[i];
  return s;
}

}  // namespace

double force_norm(const ForceComponents& f) {
  return f.size() == 3 ? std::hypot(f[0], f[1], f[2]) : std::hypot(f[0], f[1]);
}

ForceErrorEstimate estimate_force_error(const std::vector<ForceComponents>& forces) {
  ForceErrorEstimate e;
  const std::size_t k = forces.size();
  if (k < 2) return e;
  const double size = force_norm(forces[k - 1]);
  if (!(size > 0)) return e;
  const double change = distance(forces[k - 1], forces[k - 2]);
  e.change = change / size;
  e.ratio = kAssumedForceRatio;
  e.estimate = e.change / (e.ratio - 1.0);
  if (k < 3 || !(change > 0)) return e;
  const double previous = distance(forces[k - 2], forces[k - 3]);
  e.ratio = std::clamp(previous / change, kMinForceRatio, kMaxForceRatio);
  e.ratio_observed = true;
  e.estimate = e.change / (e.ratio - 1.0);
  // The changes' components along F_k: of opposite signs, the errors cancel in a change.
  const auto along = [&](const ForceComponents& a, const ForceComponents& b) {
    return dot_of_difference(a, b, forces[k - 1]);
  };
  if (along(forces[k - 1], forces[k - 2]) * along(forces[k - 2], forces[k - 3]) < 0) {
    e.monotone = false;
    e.estimate = std::max(change, previous) / size;
  } else if (change > previous) {
    e.growing = true;
    e.estimate = ForceErrorEstimate::kNone;
  }
  return e;
}

namespace {

/// The last level before `k` with at most 1/kAdaptiveSpan of its unknowns, or −1.
int span_start(const std::vector<long long>& dofs, int k) {
  for (int j = k - 1; j >= 0; --j)
    if (static_cast<double>(dofs[j]) * kAdaptiveSpan <= static_cast<double>(dofs[k])) return j;
  return -1;
}

/// The order p in [lo, hi] at which C N^(−p) changes `ratio` times more over (ni, nj) than over
/// (nj, nk), the limit nearer to it outside; the ratio grows with p.
double observed_order(double ni, double nj, double nk, double ratio, double lo, double hi) {
  const auto ratio_at = [&](double p) {
    return (std::pow(ni, -p) - std::pow(nj, -p)) / (std::pow(nj, -p) - std::pow(nk, -p));
  };
  if (ratio <= ratio_at(lo)) return lo;
  if (ratio >= ratio_at(hi)) return hi;
  for (int halvings = 0; halvings < 50; ++halvings) {
    const double mid = 0.5 * (lo + hi);
    (ratio_at(mid) < ratio ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The spans ending at level k (span_start), and what the forces show over them.
struct Spans {
  int i = -1, j = -1;  ///< i → j → k; −1: none
  double change = 0.0, previous = 0.0;
  bool monotone = true, growing = false;
  double order = 0.0;  ///< p observed over both spans, in [slowest, fastest]; 0: none
};

Spans spans_to(const std::vector<ForceComponents>& forces, const std::vector<long long>& dofs,
               int k, double slowest, double fastest) {
  Spans s;
  s.j = k >= 1 ? span_start(dofs, k) : -1;
  if (s.j < 0) return s;
  s.change = distance(forces[k], forces[s.j]);
  s.i = span_start(dofs, s.j);
  if (s.i < 0 || !(s.change > 0)) return s;
  s.previous = distance(forces[s.j], forces[s.i]);
  const double ni = static_cast<double>(dofs[s.i]), nj = static_cast<double>(dofs[s.j]),
               nk = static_cast<double>(dofs[k]);
  const auto along = [&](int a, int b) {
    return dot_of_difference(forces[a], forces[b], forces[k]);
  };
  if (along(k, s.j) * along(s.j, s.i) < 0)
    s.monotone = false;
  else if (s.previous < s.change * std::log(nj / ni) / std::log(nk / nj))
    s.growing = true;  // the change per factor of unknowns grew (the ratio's limit as p → 0)
  else
    s.order = observed_order(ni, nj, nk, s.previous / s.change, slowest, fastest);
  return s;
}

}  // namespace

ForceErrorEstimate estimate_adaptive_force_error(const std::vector<ForceComponents>& forces,
                                                 const std::vector<long long>& dofs, int dim) {
  ForceErrorEstimate e;
  const int k = static_cast<int>(forces.size()) - 1;
  // h-orders 1 and 2 on N unknowns of dim dimensions; the slowest until one is observed.
  const double slowest = 1.0 / dim, fastest = 2.0 / dim;
  const Spans s = spans_to(forces, dofs, k, slowest, fastest);
  if (s.j < 0) return e;
  const double size = force_norm(forces[k]);
  if (!(size > 0)) return e;
  e.change = s.change / size;
  e.ratio_observed = s.i >= 0 && s.change > 0;
  e.single_span = s.i < 0;
  e.monotone = s.monotone;
  e.growing = s.growing;
  if (s.growing) return e;
  if (!s.monotone) {
    e.ratio = 2.0;
    e.estimate = std::max(s.change, s.previous) / size;
    return e;
  }
  double p = slowest;
  if (s.order > 0) {
    // The slower of this order and the last level's: one lucky span does not make the rate.
    const Spans last = spans_to(forces, dofs, k - 1, slowest, fastest);
    p = std::min(s.order, last.order > 0 ? last.order : slowest);
  }
  e.ratio = std::pow(2.0, dim * p);
  e.estimate = e.change / (std::pow(static_cast<double>(dofs[k]) / dofs[s.j], p) - 1.0);
  return e;
}

std::string accuracy_stop_reason(const ForceErrorEstimate& e, double tolerance,
                                 const std::vector<ForceComponents>& forces) {
  // A zero force on the first level may be a contact the coarse mesh does not resolve.
  const auto zero = [](const ForceComponents& f) { return !(force_norm(f) > 0); };
  if (forces.size() >= 2 && zero(forces.back()) && zero(forces[forces.size() - 2]))
    return "no_force";
  if (e.available() && !e.single_span && e.estimate <= tolerance) return "reached";
  return "";
}

}  // namespace fosls
