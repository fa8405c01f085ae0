// The `adaptivity` section: the adaptive loop's limits and its marking parameter.

#include <algorithm>

#include "case/format/case_sections.hpp"

namespace fosls {

ValueRule finest_level_dofs_value(const CaseLimits& limits) {
  ValueRule max_dofs = integer_value(Range::closed(1, static_cast<double>(limits.max_dofs)));
  max_dofs.range_note = " (the case limit of DOFs of the finest level)";
  return max_dofs;
}

ObjectRulePtr adaptivity_rule(const CaseReadOptions& options) {
  const AdaptivitySpec a;
  auto r = std::make_shared<ObjectRule>();
  r->title = "the adaptivity settings";
  r->anchor = "adaptivity";
  r->fields = {
      optional_field("steps", integer_value(Range::closed(0, 50)), a.steps,
                     "refinement steps at most: the case is solved steps + 1 times"),
      optional_field("max_dofs", finest_level_dofs_value(options.limits),
                     std::min(a.max_dofs, options.limits.max_dofs),
                     "DOFs of the finest level (2 per vertex and edge in 2D, 3 per vertex and face "
                     "in 3D; fixed ones "
                     "included) that a refinement may not exceed: a refinement that would give "
                     "more is not made and the loop stops"),
      optional_field(
          "theta", number_value({0.0, 1.0, true, false}), a.theta,
          "Dörfler parameter: each step refines the fewest triangles (tetrahedra) whose error "
          "indicators make up theta of the functional J"),
      optional_field("target", number_value({0.0, 1.0, false, true}), a.target,
                     "stop once the estimator J^½ has fallen to target times its value on the "
                     "starting mesh (0: no target, only steps and max_dofs stop the loop)"),
  };
  return r;
}

AdaptivitySpec read_adaptivity_section(const nlohmann::json& j, const CaseLimits& limits) {
  AdaptivitySpec a;
  a.steps = j.value("steps", a.steps);
  a.max_dofs = j.value("max_dofs", std::min(a.max_dofs, limits.max_dofs));
  a.theta = j.value("theta", a.theta);
  a.target = j.value("target", a.target);
  return a;
}

}  // namespace fosls
