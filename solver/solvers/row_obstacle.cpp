#include "solvers/row_obstacle.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace fosls {

void project_row_obstacles(const TruncatedProlongation& p, const std::vector<char>& rows,
                           const std::vector<char>& truncated, const Vector& c, const Vector& lo,
                           const Vector& hi, Vector& coarse_lo, Vector& coarse_hi,
                           std::vector<char>& coarse_rows) {
  coarse_rows.assign(p.cols(), 0);
  auto counted = [&](int i) { return rows[i] && !truncated[i]; };
  std::unordered_map<int, double> weight;  // Σ_J |P_iJ| of the marked rows
  p.for_each_entry([&](int i, int, double v) {
    if (counted(i)) weight[i] += std::abs(v);
  });
  p.for_each_entry([&](int i, int col, double v) {
    if (!counted(i) || v == 0.0) return;
    const double w = weight[i];
    double l = is_bounded_below(lo[i]) ? std::min(0.0, lo[i] - c[i]) / w : -kNoBound;
    double u = is_bounded_above(hi[i]) ? std::max(0.0, hi[i] - c[i]) / w : kNoBound;
    if (v < 0.0) std::swap(l, u), l = -l, u = -u;
    coarse_lo[col] = std::max(coarse_lo[col], l);
    coarse_hi[col] = std::min(coarse_hi[col], u);
    coarse_rows[col] = 1;
  });
}

}  // namespace fosls
