// The result's sections of the runs that refine: the adaptive loop's `adaptivity` and the
// accuracy loop's `accuracy` (docs/result-format.md).

#include "case/result/result_rule_parts.hpp"

namespace fosls::result_parts {

namespace {

/// The force of a step: [x, y] in 2D, [x, y, z] in 3D.
ValueRule force_value(int dim) {
  return dim == 2 ? tuple_value(number(), 2, "an array of 2 numbers [x, y]")
                  : tuple_value(number(), 3, "an array of 3 numbers [x, y, z]");
}

/// The 3D objects' anchors end in 3d: docs/result-format.md holds both.
std::string anchor(const char* name, int dim) { return dim == 2 ? name : std::string(name) + "3d"; }

ObjectRulePtr adaptive_step_rule(int dim) {
  return object_rule(
      "an adaptive step", anchor("adaptive_step", dim),
      {output_field("step", count(), "1", "0 for the solve on the starting mesh, then 1, 2, ..."),
       output_field("levels", count(), "1",
                    "levels of the hierarchy: the coarse mesh, its uniform refinements and one "
                    "per bisection step so far"),
       output_field("dofs", count(), "1", "unknowns solved for"),
       output_field("dofs_total", count(), "1", "all DOFs of the level (what max_dofs limits)"),
       dim == 2 ? output_field("triangles", count(), "1", "triangles of the mesh")
                : output_field("tetrahedra", count(), "1", "tetrahedra of the mesh"),
       output_field("estimator", number(), "scaled",
                    "the error estimator J^½ at this step's solution"),
       output_field("force", force_value(dim), dim == 2 ? "S·L" : "S·L²",
                    "the contact force at this step's solution (as contact.force)"),
       output_field("iterations", count(), "1", "iterations of this step's solve"),
       output_field("converged", boolean_value(), "", "this step's solve met its stopping rule"),
       output_field("converged_by", converged_by_value(), "",
                    "the test this step's solve met, as stopping.converged_by"),
       output_field("algebraic_error", number_or_null(), "scaled",
                    "this step's estimated algebraic error, as stopping.algebraic_error"),
       output_field("marked", count(), "1",
                    std::string(dim == 2 ? "triangles" : "tetrahedra") +
                        " marked by Dörfler marking for the next step (0 on the last)"),
       output_field("time_s", number(), "s",
                    "assembly, solve, estimation, marking and refinement of this step")});
}

}  // namespace

ObjectRulePtr adaptivity_result_rule(int dim) {
  return object_rule(
      "the adaptive run", anchor("adaptivity_result", dim),
      {output_field("theta", number(), "1", "adaptivity.theta used"),
       output_field("max_dofs", count(), "1", "adaptivity.max_dofs used"),
       output_field("target", number(), "1",
                    "adaptivity.target used: the loop stops once the estimator J^½ has fallen "
                    "to target times its first value (a relative reduction, not an accuracy)"),
       output_field("stop_reason",
                    choice_value({"steps", "max_dofs", "target", "not_converged", "time_limit",
                                  "cancelled"}),
                    "",
                    "why the loop stopped: the steps were made, the next refinement would exceed "
                    "max_dofs, the estimator reached target (or vanished), a solve did not "
                    "converge, solver.time_limit_s ran out, or the job was cancelled"),
       output_field("steps", list_value(object_value(adaptive_step_rule(dim)), "one per solve"), "",
                    "every solve of the loop, the last one being the result's"),
       output_field("estimator_reduction", number(), "1",
                    "the last step's estimator J^½ over the first step's: the quantity target "
                    "is compared with (a reduction of the estimator, not an accuracy)"),
       output_field("last_force_change", number_or_null(), "1",
                    "|F_k − F_(k−1)| / |F_k| of the contact force in the last step: about how "
                    "much one more step would change it (null with one step or a zero force)"),
       output_field("stop_message", text(), "",
                    "why the loop stopped, in words, with the estimator's reduction and what "
                    "target means (the CLI prints it)")});
}

namespace {

ObjectRulePtr accuracy_step_rule(int dim) {
  return object_rule(
      "a level of the accuracy loop", anchor("accuracy_step", dim),
      {output_field("refinements", count(), "1",
                    "the hierarchy's levels less one: uniform refinements of the coarse mesh, "
                    "and with accuracy.refinement \"adaptive\" one more per bisection step (a "
                    "3D step may add two)"),
       output_field("dofs", count(), "1", "unknowns solved for"),
       output_field("dofs_total", count(), "1", "all DOFs of the level (what max_dofs limits)"),
       output_field("force", force_value(dim), dim == 2 ? "S·L" : "S·L²",
                    "the contact force at this level's solution (as contact.force)"),
       output_field("change", number_or_null(), "1",
                    "|F_k − F_j| / |F_k|: the force's change from the level before (uniform), or "
                    "from the last level with at most half the unknowns (adaptive: a span); "
                    "null before one exists or for a zero force"),
       output_field("ratio", number_or_null(), "1",
                    "ρ, the factor by which the change is taken to shrink per refinement: the "
                    "ratio of the last two changes limited to [2, 4], or 2 before two changes "
                    "are known; adaptive: 2^(dim·p) for the order p in the unknowns, "
                    "N^(−p), p within [1/dim, 2/dim] (docs/method.md §9)"),
       output_field("ratio_observed", boolean_value(), "",
                    "ratio is the observed one (false: the assumed 2)"),
       output_field("monotone", boolean_value(), "",
                    "the last two changes of the force point the same way (false: they have "
                    "opposite signs, errors cancel in a change, and the estimate is the larger "
                    "of the two changes)"),
       output_field("estimate", number_or_null(), "1",
                    "the estimated relative error of |F| at this level: change / (ratio − 1), or "
                    "the larger of the last two changes when not monotone"),
       output_field("iterations", count(), "1", "iterations of this level's solve"),
       output_field("converged", boolean_value(), "", "this level's solve met its stopping rule"),
       output_field("time_s", number(), "s", "assembly, solve and refinement of this level")});
}

}  // namespace

ObjectRulePtr accuracy_result_rule(int dim) {
  return object_rule(
      "the requested accuracy", anchor("accuracy_result", dim),
      {output_field("force", number(), "1", "accuracy.force requested (relative)"),
       output_field("max_dofs", count(), "1", "accuracy.max_dofs used"),
       output_field("reached", boolean_value(), "",
                    "the last level's estimated error is within accuracy.force"),
       output_field("stop_reason",
                    choice_value({"reached", "no_force", "max_dofs", "not_converged", "time_limit",
                                  "cancelled"}),
                    "",
                    "why the refinement stopped: the accuracy was reached, the force is zero on "
                    "two levels (no relative accuracy exists), the next level would exceed "
                    "max_dofs, a "
                    "solve did not converge, solver.time_limit_s ran out, or the job was "
                    "cancelled"),
       output_field("estimate", number_or_null(), "1",
                    "the last level's estimated relative error of |F| (null with one level, or "
                    "when the last level's solve did not converge)"),
       output_field("steps", list_value(object_value(accuracy_step_rule(dim)), "one per level"), "",
                    "every level solved, coarsest first, the last one being the result's"),
       output_field("stop_message", text(), "",
                    "why the refinement stopped, in words (the CLI prints it)")});
}

}  // namespace fosls::result_parts
