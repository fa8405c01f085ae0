// The `accuracy` section: the contact force's requested relative error and the largest level
// the refinement towards it may build.

#include <algorithm>

#include "case/format/case_sections.hpp"

namespace fosls {

ObjectRulePtr accuracy_rule(const CaseReadOptions& options) {
  const AccuracySpec a;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the requested accuracy";
  r->anchor = "accuracy";
  r->fields = {
      required_field("force", number_value({0.0, 0.5, true, false}),
                     "the requested relative error of the contact force |F|: the mesh is "
                     "refined uniformly, level by level from mesh.refinements, until the "
                     "estimated error is below it"),
      optional_field("max_dofs", finest_level_dofs_value(options.limits),
                     std::min(a.max_dofs, options.limits.max_dofs),
                     "DOFs of the finest level (2 per vertex and edge in 2D, 3 per vertex and face "
                     "in 3D; fixed ones "
                     "included) that a refinement may not exceed: a refinement that would give "
                     "more is not made and the run stops without the accuracy"),
  };
  return r;
}

AccuracySpec read_accuracy_section(const nlohmann::json& j, const CaseLimits& limits) {
  AccuracySpec a;
  a.force = j.at("force").get<double>();
  a.max_dofs = j.value("max_dofs", std::min(a.max_dofs, limits.max_dofs));
  return a;
}

}  // namespace fosls
