#include "core/level_hierarchy.hpp"

namespace fosls {

namespace {

bool inside(int dof, int size, bool fixed_allowed) {
  return (fixed_allowed && dof == -1) || (dof >= 0 && dof < size);
}

std::string link_inconsistency(const ContactLink& l, int coarse, int fine, int links) {
  for (const LinkPartner& p : l.partners)
    if (p.link < 0 || p.link >= links) return "a contact link's partner is not a link";
  for (int d : {l.coarse_un_a, l.coarse_un_b, l.coarse_un_c, l.coarse_sn})
    if (!inside(d, coarse, true)) return "a contact link's coarse DOF is outside its level";
  for (int d : {l.fine_un_a, l.fine_un_mid, l.fine_un_b, l.fine_un_c, l.fine_sn[0], l.fine_sn[1]})
    if (!inside(d, fine, true)) return "a contact link's fine DOF is outside its level";
  double weights = 0.0;
  for (double w : l.un_weight) {
    if (w < 0.0) return "a contact link's U_n weight is negative";
    weights += w;
  }
  if (weights > 1.0) return "a contact link's U_n weights add up to more than 1";
  for (const auto& move : l.flux_moves)
    for (const auto& [dof, weight] : move)
      if (!inside(dof, fine, false)) return "a flux move's DOF is outside the fine level";
  return {};
}

}  // namespace

std::string hierarchy_inconsistency(const LevelHierarchy& hierarchy, int finest_size) {
  const int nl = hierarchy.num_levels();
  if (nl == 0) return "no levels";
  if (hierarchy.levels.back().num_dofs != finest_size)
    return "the finest level's size differs from the problem's";
  for (int j = 0; j < nl; ++j) {
    const Level& level = hierarchy.levels[j];
    const int n = level.num_dofs;
    if (j > 0) {
      const int coarse = hierarchy.levels[j - 1].num_dofs;
      if (level.prolongation.rows() != n || level.prolongation.cols() != coarse)
        return "P_" + std::to_string(j) + " does not map level " + std::to_string(j - 1) +
               " to level " + std::to_string(j);
      const int links = static_cast<int>(level.links.size());
      for (const ContactLink& link : level.links)
        if (auto why = link_inconsistency(link, coarse, n, links); !why.empty())
          return why + " (level " + std::to_string(j) + ")";
    }
    for (const auto& patch : level.patches)
      for (int d : patch)
        if (!inside(d, n, false)) return "a patch DOF is outside level " + std::to_string(j);
    for (int d : level.contact_strip)
      if (!inside(d, n, false)) return "a strip DOF is outside level " + std::to_string(j);
  }
  return {};
}

}  // namespace fosls
