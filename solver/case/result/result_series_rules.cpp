// The result's objects of a series of solves — a sweep's points and the load steps — described
// field by field for both dimensions (result_rules.cpp).

#include "case/result/result_rule_parts.hpp"
#include "case/result/result_warnings.hpp"

namespace fosls::result_parts {

namespace {

/// The zone's extent at a sweep point: a length and a width along a 2D contact boundary, the
/// radius of the zone's area on a 3D one.
std::vector<FieldRule> sweep_point_extent(int dim) {
  if (dim == 3)
    return {
        output_field("force", tuple_value(number_value(), 3, "[F_x, F_y, F_z]"), "S·L²",
                     "contact.force at this point"),
        output_field("peak_pressure", number(), "S", "contact.zone.peak_pressure at this point"),
        output_field("contact_radius", number(), "L", "contact.zone.radius at this point")};
  return {output_field("force", point_value(), "S·L", "contact.force at this point"),
          output_field("peak_pressure", number(), "S", "contact.zone.peak_pressure at this point"),
          output_field("contact_length", number(), "L", "contact.zone.length at this point"),
          output_field("contact_width", number(), "L", "contact.zone.width at this point")};
}

ObjectRulePtr sweep_point_rule(ValueRule reasons, int dim) {
  std::vector<FieldRule> fields = {
      output_field("value", number(), "", "the value of the swept number (its unit)")};
  for (FieldRule& f : sweep_point_extent(dim)) fields.push_back(std::move(f));
  for (FieldRule& f : std::vector<FieldRule>{
           output_field("converged", boolean_value(), "", "this point converged"),
           output_field("stop_reason", std::move(reasons), "",
                        "why this point's iteration stopped"),
           output_field("iterations", count(), "1",
                        "finest-level iterations of this point (from the previous point's "
                        "solution)"),
           output_field("warning_codes", list_value(choice_value(warning_codes()), "codes"), "",
                        "the codes of this point's warnings (warning_details.code), e.g. "
                        "no_contact at an indentation that does not reach the body")})
    fields.push_back(std::move(f));
  fields.insert(fields.end() - 2,
                output_field("converged_by", converged_by_value(), "",
                             "the test this point's solve met, as stopping.converged_by"));
  return object_rule(dim == 3 ? "a 3D sweep point" : "a sweep point",
                     dim == 3 ? "sweep_point3d" : "sweep_point", std::move(fields));
}

/// A load step's result: the result's own fields but the history, with its number and changes.
ObjectRulePtr load_step_rule(const std::vector<FieldRule>& result_fields, int dim) {
  ValueRule changes =
      map_value(name_value(4096, "a JSON pointer"),
                one_of_value({number_value(), text(), boolean_value(), null_value(),
                              list_value(one_of_value({number_value(), text(), null_value()},
                                                      "a number, string or null"),
                                         "an array")},
                             "a JSON value"),
                50, "object mapping JSON pointers to values", "changes");
  changes.range.lo = 0;  // step 0, the case as given, changes nothing
  std::vector<FieldRule> fields = {
      output_field("step", count(), "1", "the step's number, 0 for the case as given"),
      output_field("changes", changes, "",
                   "the step's changes as the case gave them (empty for step 0)")};
  for (const FieldRule& f : result_fields)
    if (f.key != "history") fields.push_back(f);
  return object_rule(dim == 3 ? "a 3D load step" : "a load step",
                     dim == 3 ? "load_step3d" : "load_step", std::move(fields));
}

ObjectRulePtr stopped_before_rule() {
  return object_rule(
      "where load steps stopped", "stopped_before",
      {output_field("step", count(), "1", "the first step not solved"),
       output_field("reason", choice_value({"time_limit", "step_failed", "cancelled"}), "",
                    "time_limit: solver.time_limit_s, which bounds the whole run, ran out; "
                    "step_failed: the step's state could not be solved (the message says why); "
                    "cancelled: the run (a service job) was cancelled during the step")});
}

}  // namespace

ObjectRulePtr sweep_result_rule(ValueRule reasons, int dim) {
  return object_rule(
      dim == 3 ? "the 3D sweep" : "the sweep", dim == 3 ? "sweep3d" : "sweep",
      {output_field("pointer", text(), "", "the case's sweep.pointer"),
       output_field("points",
                    list_value(object_value(sweep_point_rule(std::move(reasons), dim)),
                               "one per value, in order"),
                    "", "each point of the sweep")});
}

ObjectRulePtr load_steps_result_rule(const std::vector<FieldRule>& result_fields, int dim) {
  return object_rule(
      dim == 3 ? "the 3D load steps" : "the load steps", dim == 3 ? "load_steps3d" : "load_steps",
      {output_field("count", count(), "1", "steps solved, the case as given included"),
       output_field("steps",
                    list_value(object_value(load_step_rule(result_fields, dim)), "one per step"),
                    "", "each step's result (as a result without load steps, without its history)"),
       optional_field("stopped_before", object_value(stopped_before_rule()), nullptr,
                      "the run stopped before this step could be solved: the steps solved before "
                      "it are kept, the result is marked not converged with warning "
                      "load_steps_partial")});
}

}  // namespace fosls::result_parts
