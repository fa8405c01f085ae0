#include "post/contact_width.hpp"

#include <algorithm>
#include <cmath>

namespace fosls {

namespace {

/// Mean of √(a − t)₊ over [lo, hi].
double mean_sqrt(double lo, double hi, double a) {
  auto f = [a](double t) { return std::pow(std::max(0.0, a - t), 1.5); };
  return 2.0 / 3.0 * (f(lo) - f(hi)) / (hi - lo);
}

bool adjacent(const Mesh& mesh, int e, int f) {
  for (int v : mesh.edge(e))
    for (int w : mesh.edge(f))
      if (v == w) return true;
  return false;
}

/// The front beyond the loaded edge `outer` ([t1, t2] in the coordinate t that grows outwards)
/// with the loaded edge `inner` ([t0, t1]) next to it, as a distance beyond t1.
double front(double inner_length, double inner_pressure, double outer_length,
             double outer_pressure) {
  const double t0 = -inner_length, t1 = 0.0, t2 = outer_length;
  const double ratio = outer_pressure / inner_pressure;
  auto mismatch = [&](double a) { return mean_sqrt(t1, t2, a) / mean_sqrt(t0, t1, a) - ratio; };
  double lo = t1 + 1e-12 * outer_length, hi = t2 + 2.0 * outer_length;
  if (mismatch(lo) * mismatch(hi) > 0.0) return t2;  // the pressure does not fall like √
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mismatch(lo) * mismatch(mid) <= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double contact_width(const Mesh& mesh, const ContactResult& contact) {
  const auto& e = contact.edges;
  const int n = static_cast<int>(e.size());
  double width = 0.0;
  for (int i = 0; i < n;) {
    if (!e[i].active) {
      ++i;
      continue;
    }
    int j = i;  // the run of adjacent edges in contact is [i, j]
    while (j + 1 < n && e[j + 1].active && adjacent(mesh, e[j].edge, e[j + 1].edge)) ++j;
    double run = 0.0;
    for (int k = i; k <= j; ++k) run += e[k].length;
    // Each end: the boundary's end (no edge beyond it) or a front to place.
    const bool open_start = i > 0 && adjacent(mesh, e[i - 1].edge, e[i].edge);
    const bool open_end = j + 1 < n && adjacent(mesh, e[j].edge, e[j + 1].edge);
    if (j > i && open_start)
      run += front(e[i + 1].length, e[i + 1].pressure, e[i].length, e[i].pressure) - e[i].length;
    if (j > i && open_end)
      run += front(e[j - 1].length, e[j - 1].pressure, e[j].length, e[j].pressure) - e[j].length;
    width += std::max(0.0, run);
    i = j + 1;
  }
  return width;
}

}  // namespace fosls
