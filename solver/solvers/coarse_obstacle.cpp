#include "solvers/coarse_obstacle.hpp"

#include <algorithm>

namespace fosls {

namespace {

/// The coarse bounds ṽ_i ≤ v_i of the ends i (weight w_i > 0) of one link's U_n point m, with
/// Σ w_i ṽ_i ≤ v_m: (a) each end as high as the others at their own defects allow, but not below
/// v_m (feasible: if one end is above v_m, all the others at most their defects, the sum is at
/// most v_m; else every end is at most v_m); (b) no end above v_m; (c) every end at the least
/// defect. With two ends at ½ this is (v_m − ½ v_b) / ½ = 2 v_m − v_b, exactly.
std::array<double, 3> un_bounds(CoarseProjection projection, const std::array<double, 3>& v,
                                double vm, const std::array<double, 3>& w) {
  std::array<double, 3> t = {0.0, 0.0, 0.0};
  double least = vm;
  for (int i = 0; i < 3; ++i)
    if (w[i] > 0.0) least = std::min(least, v[i]);
  for (int i = 0; i < 3; ++i) {
    if (w[i] <= 0.0) continue;
    switch (projection) {
      case CoarseProjection::kA: {
        double others = 0.0;
        for (int j = 0; j < 3; ++j)
          if (j != i && w[j] > 0.0) others += w[j] * v[j];
        t[i] = std::min(v[i], std::max(vm, (vm - others) / w[i]));
        break;
      }
      case CoarseProjection::kB:
        t[i] = std::min(v[i], vm);
        break;
      case CoarseProjection::kC:
        t[i] = least;
        break;
    }
  }
  return t;
}

}  // namespace

void project_defect(const Level& fine_level, CoarseProjection projection, const Vector& defect,
                    Vector& coarse_hi, const std::vector<std::array<double, 2>>* sn_weights) {
  auto d = [&](int i) { return i < 0 ? kNoBound : defect[i]; };
  for (std::size_t index = 0; index < fine_level.links.size(); ++index) {
    const ContactLink& l = fine_level.links[index];
    const std::array<double, 2>& weight = sn_weights ? (*sn_weights)[index] : l.sn_weight;
    const std::array<double, 3> t =
        un_bounds(projection, {d(l.fine_un_a), d(l.fine_un_b), d(l.fine_un_c)}, d(l.fine_un_mid),
                  l.un_weight);
    const std::array<int, 3> coarse_un = {l.coarse_un_a, l.coarse_un_b, l.coarse_un_c};
    for (int i = 0; i < 3; ++i)
      if (coarse_un[i] >= 0 && l.un_weight[i] > 0.0)
        coarse_hi[coarse_un[i]] = std::min(coarse_hi[coarse_un[i]], t[i]);
    if (l.coarse_sn >= 0) {
      // Pressure: the coarse S_n may not exceed any child's defect, measured per unit of the
      // prolongation weight (the minimum over the children of the σ_nn defects).
      double bound = kNoBound;
      for (int k = 0; k < 2; ++k) {
        if (l.fine_sn[k] < 0) continue;
        bound = std::min(bound, weight[k] > 0 ? d(l.fine_sn[k]) / weight[k] : 0.0);
      }
      coarse_hi[l.coarse_sn] = std::min(coarse_hi[l.coarse_sn], bound);
    }
  }
  for (int i = 0; i < coarse_hi.size(); ++i) coarse_hi[i] = std::max(0.0, coarse_hi[i]);
}

}  // namespace fosls
