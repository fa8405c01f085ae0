// The `accuracy` section: the contact force's requested relative error, the largest level the
// refinement towards it may build, and how the levels are refined.

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
                     "refined, level by level from mesh.refinements, until the estimated error "
                     "is below it"),
      optional_field("max_dofs", finest_level_dofs_value(options.limits),
                     std::min(a.max_dofs, options.limits.max_dofs),
                     "DOFs of the finest level (2 per vertex and edge in 2D, 3 per vertex and face "
                     "in 3D; fixed ones "
                     "included) that a refinement may not exceed: a refinement that would give "
                     "more is not made and the run stops without the accuracy"),
      optional_field("refinement", choice_value({"adaptive", "uniform"}), nullptr,
                     "how each level is made from the one before: adaptive bisects the cells "
                     "Dörfler marking picks from the functional's indicators (theta), uniform "
                     "refines every cell. Default: adaptive in 3D; uniform in 2D, where its "
                     "cheaper multilevel cycles make it as fast or faster (docs/performance.md, "
                     "\"Accuracy on demand\"), and always with friction or mesh.order 2, which "
                     "adaptive refinement does not take yet"),
      optional_field("theta", number_value({0.0, 1.0, true, false}), a.theta,
                     "Dörfler parameter of adaptive levels, as adaptivity.theta"),
  };
  return r;
}

AccuracySpec read_accuracy_section(const nlohmann::json& j, const CaseLimits& limits) {
  AccuracySpec a;
  a.force = j.at("force").get<double>();
  a.max_dofs = j.value("max_dofs", std::min(a.max_dofs, limits.max_dofs));
  a.refinement_given = j.contains("refinement");
  a.adaptive = j.value("refinement", std::string("adaptive")) == "adaptive";
  a.theta = j.value("theta", a.theta);
  return a;
}

void settle_accuracy_refinement(CaseSpec& spec, std::vector<CaseError>& errors) {
  if (!spec.accuracy) return;
  AccuracySpec& a = *spec.accuracy;
  if (!a.refinement_given) a.adaptive = spec.dimension == 3;
  const char* why = has_friction(spec)     ? "with friction"
                    : spec.mesh.order == 2 ? "with mesh.order 2"
                                           : nullptr;
  if (!why) return;
  if (a.refinement_given && a.adaptive)
    errors.push_back({"/accuracy/refinement", std::string("adaptive refinement is not available ") +
                                                  why + " yet; use \"uniform\" or leave it out"});
  a.adaptive = false;
}

}  // namespace fosls
