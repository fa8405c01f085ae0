#include "case/admission/early_group_check.hpp"

#include <algorithm>

#include "case/format/case_sections.hpp"
#include "case/format/rule_checker.hpp"
#include "case/run/mesh_factory.hpp"
#include "mesh/group_name_index.hpp"

namespace fosls {

namespace {

bool under_mesh(const std::string& pointer) {
  return pointer.rfind("/mesh", 0) == 0 && (pointer.size() == 5 || pointer[5] == '/');
}

/// The mesh's group names, or false when they are not known without gmsh or an error.
bool group_names(const MeshSpec& mesh, std::vector<std::string>& names) {
  try {
    if (auto outline = gmsh_outline(mesh)) {
      for (const auto& g : outline->geometry.groups) names.push_back(g.name);
      return true;
    }
    if (mesh.kind == MeshSpec::Kind::kGeoFile) return false;
    names = build_coarse_mesh(mesh).group_names();  // square or msh: no gmsh
    return true;
  } catch (const std::exception&) {
    return false;  // the mesh's own problems come with the next round, as before
  }
}

}  // namespace

CaseError unknown_group_problem(const std::string& name, const std::vector<std::string>& groups) {
  return {child_pointer("/boundary", name),
          "the mesh has no boundary group '" + name + "'; its groups are " + quoted_names(groups)};
}

CaseError no_dirichlet_problem() {
  return {"/boundary",
          "no group has a dirichlet condition: without one the body can move freely (rigid body "
          "motions) and the problem has no unique solution; fix the displacement on at least "
          "one group"};
}

void add_unknown_group_problems(const nlohmann::json& j, const CaseReadOptions& options,
                                std::vector<CaseError>& errors) {
  if (!j.is_object() || !j.contains("mesh") || !j["mesh"].is_object() || !j.contains("boundary") ||
      !j["boundary"].is_object())
    return;
  if (std::any_of(errors.begin(), errors.end(),
                  [](const CaseError& e) { return under_mesh(e.pointer); }))
    return;
  RuleChecker checker(options);
  if (!checker.check_object(j["mesh"], *mesh_rule(options, 2), "/mesh")) return;
  std::vector<std::string> groups;
  if (!group_names(read_mesh_section(j["mesh"]), groups)) return;
  const GroupNameIndex known(groups);
  for (const auto& [name, condition] : j["boundary"].items())
    if (known.find(groups, name) < 0) errors.push_back(unknown_group_problem(name, groups));
}

}  // namespace fosls
