#pragma once
// A mesh's boundary groups in the order of their names, so that a group is found by name in
// O(log G): a case may name thousands of groups of a mesh that has as many, and a linear search
// per name made that quadratic (issue 50). It keeps indices, not a second copy of the names,
// since every level of a hierarchy holds a copy of its mesh.

#include <string>
#include <string_view>
#include <vector>

namespace fosls {

class GroupNameIndex {
 public:
  GroupNameIndex() = default;
  explicit GroupNameIndex(const std::vector<std::string>& names);

  /// The first group called `name` in `names` (the names the index was built from), −1 when
  /// there is none.
  int find(const std::vector<std::string>& names, std::string_view name) const;

 private:
  std::vector<int> order_;  ///< group indices sorted by (name, index)
};

}  // namespace fosls
