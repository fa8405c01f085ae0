#include "mesh/mesh_error.hpp"

namespace fosls {

namespace {
std::string summary(const std::vector<MeshProblem>& problems) {
  std::string s;
  for (const auto& p : problems) {
    if (!s.empty()) s += "; ";
    s += (p.field.empty() ? std::string("mesh") : p.field) + ": " + p.detail;
  }
  return s;
}
}  // namespace

MeshError::MeshError(std::vector<MeshProblem> problems)
    : std::runtime_error(summary(problems)), problems_(std::move(problems)) {}

MeshError::MeshError(std::string field, std::string detail)
    : MeshError(std::vector<MeshProblem>{{std::move(field), std::move(detail)}}) {}

}  // namespace fosls
