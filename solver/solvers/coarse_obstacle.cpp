#include "solvers/coarse_obstacle.hpp"

#include <algorithm>

namespace fosls {

void project_defect(const Level& fine_level, CoarseProjection projection, const Vector& defect,
                    Vector& coarse_hi, const std::vector<std::array<double, 2>>* sn_weights) {
  auto d = [&](int i) { return i < 0 ? kNoBound : defect[i]; };
  for (std::size_t index = 0; index < fine_level.links.size(); ++index) {
    const ContactLink& l = fine_level.links[index];
    const std::array<double, 2>& weight = sn_weights ? (*sn_weights)[index] : l.sn_weight;
    const double va = d(l.fine_un_a), vm = d(l.fine_un_mid), vb = d(l.fine_un_b);
    double ta = 0.0, tb = 0.0;
    switch (projection) {
      case CoarseProjection::kA:
        ta = std::min(va, std::max(vm, 2.0 * vm - vb));
        tb = std::min(vb, std::max(vm, 2.0 * vm - va));
        break;
      case CoarseProjection::kB:
        ta = std::min(va, vm);
        tb = std::min(vb, vm);
        break;
      case CoarseProjection::kC:
        ta = tb = std::min({va, vm, vb});
        break;
    }
    if (l.coarse_un_a >= 0) coarse_hi[l.coarse_un_a] = std::min(coarse_hi[l.coarse_un_a], ta);
    if (l.coarse_un_b >= 0) coarse_hi[l.coarse_un_b] = std::min(coarse_hi[l.coarse_un_b], tb);
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
