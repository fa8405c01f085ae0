// The `sweep` section: one number of the case takes a list of values, solved in order, each
// point starting from the previous point's solution (docs/case-format.md, "Sweeps").

#include "case/format/case_reader.hpp"
#include "case/format/case_sections.hpp"
#include "case/format/rule_checker.hpp"

namespace fosls {

namespace {

using nlohmann::json;

constexpr std::size_t kMaxSweepValues = 100;

/// Continuation needs one mesh for every point, and the sweep cannot sweep itself.
void check_sweep(const json& j, const std::string& pointer, RuleChecker& checker) {
  if (!j.contains("pointer") || !j.contains("values") ||
      !checker.usable(j, pointer, {"pointer", "values"}))
    return;
  const std::string target = j["pointer"];
  for (const char* fixed : {"/sweep", "/mesh", "/name", "/dimension"}) {
    const std::string prefix = fixed;
    if (target == prefix || target.rfind(prefix + "/", 0) == 0)
      checker.error(child_pointer(pointer, "pointer"),
                    "a sweep cannot change " + prefix +
                        ": every point is solved on the same mesh, starting from the previous "
                        "point's solution; run one case per mesh instead");
  }
  if (j["values"].empty())
    checker.error(child_pointer(pointer, "values"), "give at least one value");
}

}  // namespace

ObjectRulePtr sweep_rule(const CaseReadOptions& options) {
  auto r = std::make_shared<ObjectRule>();
  r->title = "the sweep";
  r->anchor = "sweep";
  r->fields = {
      required_field("pointer", string_value(options.limits.max_path_length, "a JSON pointer"),
                     "JSON pointer (RFC 6901) to a number given in the case, e.g. "
                     "/boundary/contact/obstacle/displacement/1"),
      required_field("values", array_value(number_value(), kMaxSweepValues, "an array of numbers"),
                     "the values it takes, solved in this order"),
  };
  r->hook = check_sweep;
  r->notes = "not /mesh, /name, /dimension or /sweep; at least one value";
  return r;
}

void read_sweep_section(const json& case_json, const CaseReadOptions& options, CaseSpec& spec,
                        std::vector<CaseError>& errors) {
  const json& sweep = case_json["sweep"];
  const std::string text = sweep["pointer"];
  json::json_pointer target;
  try {
    target = json::json_pointer(text);
  } catch (const json::exception&) {
    errors.push_back({"/sweep/pointer", "'" + text +
                                            "' is not a JSON pointer: it starts with / and "
                                            "escapes ~ and / as ~0 and ~1"});
    return;
  }
  if (!case_json.contains(target) || !case_json.at(target).is_number()) {
    errors.push_back({"/sweep/pointer", "'" + text +
                                            "' must name a number given in the case; write the "
                                            "field with the sweep's first value"});
    return;
  }
  json point_json = case_json;
  point_json.erase("sweep");
  spec.sweep = SweepSpec{text, {}};
  for (std::size_t i = 0; i < sweep["values"].size(); ++i) {
    point_json[target] = sweep["values"][i];
    CaseReadResult point = read_case(point_json, options);
    const std::string where = "/sweep/values/" + std::to_string(i);
    for (const CaseError& e : point.errors)
      errors.push_back(
          {where, "with this value, " + (e.pointer.empty() ? "/" : e.pointer) + ": " + e.detail});
    if (point.spec) {
      spec.sweep->values.push_back(sweep["values"][i].get<double>());
      spec.sweep_points.push_back(std::move(*point.spec));
    }
  }
}

}  // namespace fosls
