// The `load_steps` section: quasi-static steps, each a set of changes (JSON pointer → value)
// applied to the case as the previous step left it, solved from the previous step's state, with
// friction acting on the slip of the step (docs/case-format.md, "Load steps").

#include <algorithm>
#include <utility>

#include "case/format/case_reader.hpp"
#include "case/format/case_sections.hpp"
#include "case/format/rule_checker.hpp"

namespace fosls {

namespace {

using nlohmann::json;

constexpr std::size_t kMaxLoadSteps = 100;
constexpr std::size_t kMaxChanges = 50;

/// "/load_steps/k/<pointer escaped as one reference token>".
std::string change_pointer(std::size_t k, const std::string& target) {
  std::string token;
  for (char c : target) token += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return "/load_steps/" + std::to_string(k) + "/" + token;
}

/// Why a step may not change `target`, or empty.
std::string forbidden(const std::string& target) {
  for (const char* fixed :
       {"/load_steps", "/sweep", "/adaptivity", "/mesh", "/name", "/units", "/dimension"}) {
    const std::string prefix = fixed;
    if (target == prefix || target.rfind(prefix + "/", 0) == 0)
      return "a load step cannot change " + prefix +
             ": every step is solved on the same mesh from the previous step's state";
  }
  return "";
}

bool has_contact(const json& case_json) {
  for (const auto& [name, condition] : case_json["boundary"].items())
    if (condition.value("type", "") == "contact") return true;
  return false;
}

/// Applies step k's changes to `state`; problems go to `errors`.
void apply_step(const json& step, std::size_t k, json& state, std::vector<CaseError>& errors) {
  for (const auto& [text, value] : step.items()) {
    const std::string where = change_pointer(k, text);
    if (const std::string why = forbidden(text); !why.empty()) {
      errors.push_back({where, why});
      continue;
    }
    json::json_pointer target;
    try {
      target = json::json_pointer(text);
    } catch (const json::exception&) {
      errors.push_back({where, "'" + text +
                                   "' is not a JSON pointer: it starts with / and escapes ~ and / "
                                   "as ~0 and ~1"});
      continue;
    }
    // A new member of an existing object may be added; array entries must exist.
    const bool exists = state.contains(target);
    const bool new_member = !exists && !target.empty() && state.contains(target.parent_pointer()) &&
                            state.at(target.parent_pointer()).is_object();
    if (!exists && !new_member) {
      errors.push_back({where, "'" + text +
                                   "' names nothing in the case as the previous step left it "
                                   "(a new field may be added to an existing object only)"});
      continue;
    }
    state[target] = value;
  }
}

}  // namespace

ValueRule load_steps_rule(const CaseReadOptions& options) {
  const std::size_t n = options.limits.max_expression_length;
  // A string is any text here (an expression, a method name, ...): the field it lands in
  // decides, when the step's state is read as a case.
  ValueRule scalar =
      one_of_value({number_value(), string_value(n, "a string")}, "a number or string");
  ValueRule item = one_of_value({scalar, null_value()}, "a number, string or null");
  ValueRule value = one_of_value({scalar, boolean_value(), null_value(),
                                  list_value(item, "an array of numbers, strings or null")},
                                 "a number, string, boolean, null or an array of them");
  ValueRule step =
      map_value(name_value(options.limits.max_path_length, "a JSON pointer"), value, kMaxChanges,
                "an object mapping JSON pointers to their new values", "changes");
  return array_value(step, kMaxLoadSteps, "an array of steps");
}

void read_load_steps_section(const json& case_json, const CaseReadOptions& options, CaseSpec& spec,
                             std::vector<CaseError>& errors) {
  if (case_json.contains("sweep") || case_json.contains("adaptivity")) {
    errors.push_back({"/load_steps", "load steps cannot be combined with a sweep or adaptivity"});
    return;
  }
  if (!has_contact(case_json)) {
    errors.push_back({"/load_steps",
                      "load steps need a contact condition: without contact "
                      "every step is a linear problem of its own"});
    return;
  }
  json state = case_json;
  state.erase("load_steps");
  const json& steps = case_json["load_steps"];
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const std::size_t before = errors.size();
    apply_step(steps[k], k, state, errors);
    if (errors.size() > before) continue;
    CaseReadResult step = read_case(state, options);
    for (const CaseError& e : step.errors)
      errors.push_back(
          {"/load_steps/" + std::to_string(k),
           "after this step, " + (e.pointer.empty() ? "/" : e.pointer) + ": " + e.detail});
    if (step.spec) {
      // Steps cannot change the mesh: the case keeps it once (the runner gives it back to each
      // step), so a large mesh is not held once per step.
      // (Swapped out, not assigned: assigning an empty string keeps the text's buffer.)
      MeshSpec none;
      std::swap(step.spec->mesh, none);
      spec.load_step_changes.push_back(steps[k]);
      spec.load_step_points.push_back(std::move(*step.spec));
    }
  }
}

}  // namespace fosls
