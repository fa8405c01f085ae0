#include "case/format/published_formats.hpp"

#include "case/format/case_reader.hpp"
#include "case/format/rules_markdown.hpp"
#include "case/format/rules_schema.hpp"
#include "case/format/solver_methods.hpp"
#include "case/result/result_rules.hpp"
#include "post/tet_vtu_writer.hpp"
#include "post/vtu_writer.hpp"

namespace fosls {

namespace {

void collect_objects(const ValueRule& rule, std::map<std::string, const ObjectRule*>& out);

void collect_objects(const ObjectRule& rule, std::map<std::string, const ObjectRule*>& out) {
  if (!out.emplace(rule.anchor, &rule).second) return;
  for (const auto& f : rule.fields) collect_objects(f.value, out);
  for (const auto& v : rule.variants)
    for (const auto& f : v.fields) collect_objects(f.value, out);
}

void collect_objects(const ValueRule& rule, std::map<std::string, const ObjectRule*>& out) {
  if (rule.object) collect_objects(*rule.object, out);
  if (rule.element) collect_objects(*rule.element, out);
  for (const auto& a : rule.alternatives) collect_objects(a, out);
}

std::string methods_table() {
  std::string s = "| method | uses | what it does |\n|---|---|---|\n";
  for (const auto& m : solver_methods()) {
    std::vector<std::string> uses;
    for (const auto option : m.options)
      uses.push_back(std::string("`") + option_field(option) + "`");
    s += std::string("| `") + m.name + "` | " + (uses.empty() ? "—" : join_words(uses, ", ")) +
         " | " + m.summary + " |\n";
  }
  s += "\n| smoother | what it does |\n|---|---|\n";
  for (const auto& sm : smoothers())
    s += std::string("| `") + sm.name + "` | " + sm.summary + " |\n";
  s += "\n| coarse_obstacle | the obstacle of a coarse contact edge |\n|---|---|\n";
  for (const auto& c : coarse_obstacles())
    s += std::string("| `") + c.name + "` | " + c.summary + " |\n";
  return s;
}

std::string limits_table() {
  std::string s = "| limit | value |\n|---|---|\n";
  for (const auto& row : case_limit_table()) s += "| " + row.what + " | " + row.value + " |\n";
  return s;
}

std::string vtu_table(std::span<const VtuArray> arrays) {
  std::string s = "| array | data | components | unit | meaning |\n|---|---|---|---|---|\n";
  for (const auto& a : arrays) {
    std::vector<std::string> components;
    for (const char* c : a.components) components.emplace_back(c);
    s += std::string("| `") + a.name + "` | " + (a.point_data ? "point" : "cell") + " | " +
         (components.empty() ? "1" : join_words(components, ", ")) + " | " + a.unit + " | " +
         a.meaning + " |\n";
  }
  return s;
}

std::map<std::string, std::string> object_tables(const ObjectRule& root, TableKind kind) {
  std::map<std::string, const ObjectRule*> objects;
  collect_objects(root, objects);
  std::map<std::string, std::string> blocks;
  for (const auto& [anchor, rule] : objects)
    blocks["fields:" + anchor] = rules_markdown_table(*rule, kind);
  return blocks;
}

}  // namespace

nlohmann::json result_json_schema() {
  return rules_json_schema(*result_rule(), "https://fosls-contact.invalid/schemas/result.json",
                           "The result of a fosls-contact solve (docs/result-format.md).");
}

nlohmann::json result3d_json_schema() {
  return rules_json_schema(*result_rule(3), "https://fosls-contact.invalid/schemas/result3d.json",
                           "The result of a 3D case (docs/result-format.md, \"3D results\").");
}

std::map<std::string, std::string> result_format_blocks() {
  auto blocks = object_tables(*result_rule(), TableKind::kOutput);
  // The 3D result's own objects; history, warning and material are 2D's tables.
  blocks.merge(object_tables(*result_rule(3), TableKind::kOutput));
  blocks["vtu"] = vtu_table(vtu_arrays());
  blocks["vtu_3d"] = vtu_table(tet_vtu_arrays());
  return blocks;
}

nlohmann::json case_json_schema() {
  return rules_json_schema_by_dimension(
      *case_rule({}, 2), *case_rule({}, 3), "https://fosls-contact.invalid/schemas/case.json",
      "A contact case of fosls-contact, 2D or 3D (docs/case-format.md).");
}

std::map<std::string, std::string> case_format_blocks() {
  // The rules of both dimensions in one table each (docs/architecture.md, "One case path for
  // 2D and 3D").
  auto blocks = object_tables(*case_rule({}, 0), TableKind::kInput);
  blocks["methods"] = methods_table();
  blocks["limits"] = limits_table();
  return blocks;
}

}  // namespace fosls
