#include "core/friction_law.hpp"

#include <algorithm>
#include <cmath>

namespace fosls {

bool FrictionLayout::coulomb() const {
  return std::any_of(edges.begin(), edges.end(),
                     [](const FrictionEdge& f) { return f.coefficient > 0.0; });
}

double slip_bound(const FrictionEdge& f, const Vector& x) {
  return f.coefficient > 0.0 ? f.coefficient * std::max(0.0, -x[f.sn]) : f.tresca;
}

void set_kink_weights(const FrictionLayout& layout, const std::vector<double>& bounds,
                      Kinks& kinks) {
  std::fill(kinks.weight.begin(), kinks.weight.end(), 0.0);
  kinks.constant = 0.0;
  for (std::size_t e = 0; e < layout.edges.size(); ++e) {
    const FrictionEdge& f = layout.edges[e];
    for (int k = 0; k < 2; ++k) {
      if (f.kink[k] >= 0)
        kinks.weight[f.kink[k]] += 0.5 * layout.c3 * bounds[e];
      else
        kinks.constant += 0.5 * layout.c3 * bounds[e] * std::abs(f.fixed_slip[k]);
    }
  }
}

double set_friction_bounds(const FrictionLayout& layout, const Vector& x, BoxQp& qp, Kinks& kinks,
                           const BoundChoice& choose) {
  const std::size_t n = layout.edges.size();
  double largest = 0.0, change = 0.0;
  bool first = false;
  Vector before(n), at_x(n);
  for (std::size_t e = 0; e < n; ++e) {
    const FrictionEdge& f = layout.edges[e];
    const double s = slip_bound(f, x);
    first |= !is_bounded_above(qp.upper[f.st]);
    if (is_bounded_above(qp.upper[f.st])) change = std::max(change, std::abs(s - qp.upper[f.st]));
    largest = std::max(largest, s);
    before[e] = qp.upper[f.st];
    at_x[e] = s;
  }
  const Vector set = choose ? choose(before, at_x, first) : at_x;
  std::vector<double> bounds(n);
  for (std::size_t e = 0; e < n; ++e) {
    qp.lower[layout.edges[e].st] = -set[e];
    qp.upper[layout.edges[e].st] = set[e];
    bounds[e] = set[e];
  }
  set_kink_weights(layout, bounds, kinks);
  if (first) return 1.0;
  return largest > 0.0 ? change / largest : 0.0;
}

double friction_functional(const FrictionLayout& layout, const Kinks& kinks, const Vector& x) {
  double sum = kinks.energy(x);
  for (const FrictionEdge& f : layout.edges) {
    double slip = 0.0;
    for (int k = 0; k < 2; ++k)
      slip += f.kink[k] >= 0 ? x[kinks.dof[f.kink[k]]] - kinks.at[f.kink[k]] : f.fixed_slip[k];
    sum += 0.5 * layout.c3 * x[f.st] * slip;
  }
  return sum;
}

}  // namespace fosls
