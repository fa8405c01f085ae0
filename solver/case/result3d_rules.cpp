// The result of a 3D case (case3d_result.cpp) described field by field, as the 2D result is
// (result_rules.cpp): the source of docs/result-format.md's "3D results" tables and of
// docs/schemas/result3d.schema.json, and the check that every field a 3D solve emits is
// documented (tests/solver/case3d_test.cpp). history, warning_details and material are 2D's.

#include "case/result_rule_parts.hpp"
#include "case/result_rules.hpp"

namespace fosls {

namespace {

using namespace result_parts;

ObjectRulePtr zone3d_rule() {
  const ValueRule where = one_of_value({tuple_value(number_value(), 3, "[x, y, z]"), null_value()},
                                       "[x, y, z] or null");
  return object_rule(
      "the 3D contact zone", "zone3d",
      {output_field("faces", count(), "1", "contact faces in contact (pressure > 0)"),
       output_field("radius", number(), "L",
                    "√(area/π): the radius of the disc of the zone's area (for Hertz, a)"),
       output_field("box_min", where, "L",
                    "the smallest x, y and z of the faces in contact; null without contact"),
       output_field("box_max", where, "L", "the largest x, y and z of the faces in contact"),
       output_field("peak_pressure", number(), "S",
                    "the largest face pressure (= max_pressure; 0 without contact)"),
       output_field("peak_location", where, "L",
                    "centroid [x, y, z] of the face with the peak pressure; null without one")});
}

ObjectRulePtr contact3d_rule() {
  return object_rule(
      "the 3D contact output", "contact3d",
      {output_field("force", tuple_value(number_value(), 3, "[F_x, F_y, F_z]"), "S·L²",
                    "∫σn dA over the contact groups: the plane's force on the body"),
       output_field("max_pressure", number(), "S",
                    "the largest face pressure −σ_nn (RT0: one value per face)"),
       output_field("area", number(), "L²", "the area of the contact faces with pressure > 0"),
       output_field("faces", count(), "1", "faces of the contact groups"),
       output_field("faces_in_contact", count(), "1", "of those, the faces with pressure > 0"),
       output_field("zone", object_value(zone3d_rule()), "",
                    "where the body touches the obstacle: its extent and peak, as 2D's zone")});
}

ObjectRulePtr functional3d_rule() {
  return object_rule(
      "the 3D functional", "functional3d",
      {output_field("total", number(), "scaled", "J at the solution (stresses over μ)"),
       output_field("estimator", number(), "scaled", "J^½")});
}

ObjectRulePtr timing3d_rule() {
  return object_rule(
      "the 3D timing", "timing3d",
      {output_field("mesh_s", number(), "s", "coarse mesh, refinements and the groups' checks"),
       output_field("assembly_s", number(), "s",
                    "problem data, spaces and assembly of every level"),
       output_field("solve_s", number(), "s",
                    "the solver's set-up and iterations (of an adaptive or accuracy run: "
                    "every step's, with the estimation and refinement between them)"),
       output_field("total_s", number(), "s", "the whole run")});
}

std::vector<FieldRule> outcome3d_fields() {
  return {output_field("name", text(), "", "the case's name"),
          output_field("dimension", integer_value(Range::closed(3, 3)), "", "3"),
          output_field("method", choice_value({"mmg", "pdas"}), "", "the solver method"),
          output_field("converged", boolean_value(), "",
                       "final_kkt_residual ≤ tolerance · the initial KKT residual (or the residual "
                       "reached its rounding level first)"),
          output_field("stop_reason", choice_value(stop_reason_names()), "",
                       "why the iteration stopped, as in 2D"),
          output_field("cancelled", boolean_value(), "",
                       "false in a stored result: a cancelled 3D job keeps none"),
          output_field("iterations", count(), "1", "iterations on the finest level"),
          output_field("tolerance", number(), "1", "solver.tolerance of the case"),
          output_field("final_kkt_residual", number(), "scaled", "KKT residual at the end"),
          output_field("relative_kkt_residual", number(), "1",
                       "final over initial KKT residual (0 when the initial one is 0)"),
          output_field("asymptotic_rate", number(), "1",
                       "geometric mean of the last (up to) 5 reductions of the KKT residual"),
          output_field("levels", count(), "1", "levels of the hierarchy: mesh.refinements + 1"),
          output_field("dofs", count(), "1",
                       "unknowns of the finest level (3 per vertex, 3 per face, Dirichlet ones "
                       "excluded)"),
          output_field("tetrahedra", count(), "1", "tetrahedra of the finest mesh"),
          output_field("vertices", count(), "1", "vertices of the finest mesh")};
}

std::vector<FieldRule> solution3d_fields() {
  return {output_field("material", object_value(material_echo_rule()), "",
                       "the material as used (μ, λ)"),
          output_field("weights", object_value(weights_echo_rule()), "",
                       "the weights as used, as in 2D (c3 chosen when the case gives \"auto\")"),
          output_field("functional", object_value(functional3d_rule()), "",
                       "the FOSLS functional at the solution"),
          output_field("contact", object_value(contact3d_rule()), "",
                       "the contact output (zeros when the case has no contact group)"),
          optional_field("message", text(), nullptr,
                         "why a run of load steps or sweep points did not converge or stopped "
                         "early (also in warnings), as in 2D"),
          output_field("warnings", list_value(text(), "list of sentences"), "",
                       "what the user should know: the messages of warning_details, in order"),
          output_field(
              "warning_details", list_value(object_value(warning_rule()), "one per warning"), "",
              "the warnings with their codes: units_implausible, no_contact, initial_penetration, "
              "contact_zone_underresolved, tangential_load_frictionless, "
              "roller_overrides_contact and the solver's own as in 2D (not_converged, "
              "time_limit, rounding_level, coarse_corrections_shortened)"),
          output_field("review_required", boolean_value(), "",
                       "a warning says the answer may be physically empty or wrong although it "
                       "converged; fosls-contact solve then exits with code 4"),
          output_field("history", list_value(object_value(history_rule()), "one per iteration"), "",
                       "the initial iterate and every iteration, as in 2D"),
          output_field("solver_statistics", object_value(statistics_rule()), "",
                       "counts and times of the multilevel method's parts, as in 2D (the contact "
                       "strip's exact solves in strip_s)"),
          output_field("timing", object_value(timing3d_rule()), "", "wall-clock times"),
          optional_field("adaptivity", object_value(adaptivity_result_rule(3)), nullptr,
                         "the adaptive loop, step by step, as in 2D (only when the case has an "
                         "adaptivity section; the other fields describe its last step)"),
          optional_field("accuracy", object_value(accuracy_result_rule(3)), nullptr,
                         "the refinement towards the requested force accuracy, level by level, "
                         "as in 2D (only when the case has an accuracy section; the other fields "
                         "describe its last level)")};
}

}  // namespace

ObjectRulePtr result3d_rule() {
  std::vector<FieldRule> fields = outcome3d_fields();
  for (FieldRule& f : solution3d_fields()) fields.push_back(std::move(f));
  // The series of solves as in 2D; a load step's fields are the 3D result's.
  fields.push_back(optional_field(
      "sweep", object_value(sweep_result_rule(choice_value(stop_reason_names()), 3)), nullptr,
      "a case with a sweep: every point's force and convergence, as in 2D"));
  fields.push_back(
      optional_field("load_steps", object_value(load_steps_result_rule(fields, 3)), nullptr,
                     "a case with load steps: every step's result in order, as in 2D"));
  return object_rule("the 3D result", "result3d", std::move(fields));
}

}  // namespace fosls
