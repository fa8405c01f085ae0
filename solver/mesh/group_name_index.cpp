#include "mesh/group_name_index.hpp"

#include <algorithm>
#include <numeric>

namespace fosls {

GroupNameIndex::GroupNameIndex(const std::vector<std::string>& names) : order_(names.size()) {
  std::iota(order_.begin(), order_.end(), 0);
  std::stable_sort(order_.begin(), order_.end(),
                   [&names](int a, int b) { return names[a] < names[b]; });
}

int GroupNameIndex::find(const std::vector<std::string>& names, std::string_view name) const {
  const auto it = std::lower_bound(order_.begin(), order_.end(), name,
                                   [&names](int g, std::string_view n) { return names[g] < n; });
  return it != order_.end() && names[*it] == name ? *it : -1;
}

}  // namespace fosls
