#pragma once
// Parts of the result's rules shared by result_rules.cpp and the files that describe one
// section of the result each (result_refinement_rules.cpp).

#include <string>
#include <vector>

#include "case/format/case_rules.hpp"

namespace fosls::result_parts {

ValueRule count();
ValueRule number();
ValueRule numbers(std::string what);
ValueRule text();
ValueRule converged_by_value();
/// A number, or null where there is none (JSON has no NaN).
ValueRule number_or_null();
ObjectRulePtr object_rule(std::string title, std::string anchor, std::vector<FieldRule> fields);
/// One entry of `history`, of `warning_details`, the `material` echo and `solver_statistics`:
/// the same in 2D and 3D.
ObjectRulePtr history_rule();
ObjectRulePtr warning_rule();
ObjectRulePtr material_echo_rule();
ObjectRulePtr statistics_rule();
/// The `weights` echo: the weights as used, c3's rule and limit, the length scale.
ObjectRulePtr weights_echo_rule();

/// The `adaptivity` object of an adaptive run (result_refinement_rules.cpp) of dimension dim.
ObjectRulePtr adaptivity_result_rule(int dim = 2);
/// The `accuracy` object of a run to a requested force accuracy (result_refinement_rules.cpp).
ObjectRulePtr accuracy_result_rule(int dim = 2);
/// A sweep's object, with its points in `dim` dimensions (result_series_rules.cpp).
ObjectRulePtr sweep_result_rule(ValueRule reasons, int dim);
/// The `load_steps` object: every step a result of `result_fields` but its history.
ObjectRulePtr load_steps_result_rule(const std::vector<FieldRule>& result_fields, int dim);
/// The contact object's constraint direction and obstacle types, in `dim` dimensions.
std::vector<FieldRule> constraint_fields(int dim);
/// The `contact` object of a body whose contact boundary is a set of faces (3D;
/// contact_faces_rules.cpp).
ObjectRulePtr contact_faces_rule();
/// The stop reasons' names, in the order of StopReason.
std::vector<std::string> stop_reason_names();

}  // namespace fosls::result_parts
