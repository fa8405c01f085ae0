#include "case/format/rules_markdown.hpp"

namespace fosls {

namespace {

std::string code(const std::string& s) { return "`" + s + "`"; }

/// Pipes would end a table cell.
std::string cell(std::string s) {
  for (std::size_t at = s.find('|'); at != std::string::npos; at = s.find('|', at + 2))
    s.replace(at, 1, "\\|");
  return s;
}

std::string number_text(double v) { return format_number(v); }

std::string count_range(const Range& r, const std::string& unit) {
  if (!r.has_hi()) return r.lo > 0 ? "at least " + number_text(r.lo) + " " + unit : "";
  if (r.lo == r.hi) return "exactly " + number_text(r.lo) + " " + unit;
  if (r.has_lo() && r.lo > 0) return number_text(r.lo) + " to " + number_text(r.hi) + " " + unit;
  return "at most " + number_text(r.hi) + " " + unit;
}

/// "`builtin` or `msh`", "`point` and `normal` or `obstacle`".
std::string exclusive_text(const ExclusiveFields& e) {
  std::vector<std::string> sets;
  for (const auto& set : e.sets) {
    std::vector<std::string> keys;
    for (const auto& k : set) keys.push_back(code(k));
    sets.push_back(join_words(keys, " and "));
  }
  return join_words(sets, " or ");
}

}  // namespace

std::string value_type_text(const ValueRule& rule) {
  switch (rule.kind) {
    case ValueKind::kNumber:
      return "number";
    case ValueKind::kInteger:
      return "integer";
    case ValueKind::kString:
      return "string";
    case ValueKind::kName:
      return "name";
    case ValueKind::kChoice:
      return rule.choices.size() == 1 ? code("\"" + rule.choices[0] + "\"") : "string";
    case ValueKind::kScalar:
      return "scalar";
    case ValueKind::kNull:
      return code("null");
    case ValueKind::kBoolean:
      return "boolean";
    case ValueKind::kArray: {
      const std::string element = value_type_text(*rule.element);
      auto tuple = [&element](int n) {
        std::string s = "[";
        for (int i = 0; i < n; ++i) s += (i ? ", " : "") + element;
        return s + "]";
      };
      if (rule.range.lo == rule.range.hi) return tuple(static_cast<int>(rule.range.lo));
      // A vector of the case's dimension: 2 numbers in 2D, 3 in 3D.
      if (rule.range.lo == 2 && rule.range.hi == 3)
        return tuple(2) + " (2D) or " + tuple(3) + " (3D)";
      return "array of " + element;
    }
    case ValueKind::kMap:
      return "object: name → " + value_type_text(*rule.element);
    case ValueKind::kObject:
      return "object (" + rule.object->anchor + ")";
    case ValueKind::kOneOf: {
      std::vector<std::string> kinds;
      for (const auto& a : rule.alternatives) kinds.push_back(value_type_text(a));
      return join_words(kinds);
    }
  }
  return "";
}

std::string value_allowed_text(const ValueRule& rule) {
  std::string s;
  switch (rule.kind) {
    case ValueKind::kNumber:
      s = rule.range.text();
      break;
    case ValueKind::kInteger:
      s = rule.range.has_lo() && rule.range.has_hi()
              ? number_text(rule.range.lo) + " to " + number_text(rule.range.hi)
              : rule.range.text();
      break;
    case ValueKind::kString:
    case ValueKind::kName:
      s = count_range(rule.range, "characters");
      break;
    case ValueKind::kChoice: {
      std::vector<std::string> quoted;
      for (const auto& c : rule.choices) quoted.push_back(code(c));
      s = join_words(quoted, ", ");
      break;
    }
    case ValueKind::kScalar:
      s = "a number, or an expression of at most " + number_text(rule.range.hi) + " characters";
      break;
    case ValueKind::kNull:
    case ValueKind::kBoolean:
      break;
    case ValueKind::kArray: {
      const std::string element = value_allowed_text(*rule.element);
      s = rule.range.lo == rule.range.hi
              ? element
              : count_range(rule.range, "entries") + (element.empty() ? "" : "; each " + element);
      break;
    }
    case ValueKind::kMap:
      s = count_range(rule.range, "entries") + "; names of " +
          count_range(rule.key->range, "characters");
      break;
    case ValueKind::kObject:
      break;
    case ValueKind::kOneOf: {
      std::vector<std::string> parts;
      for (const auto& a : rule.alternatives)
        if (auto t = value_allowed_text(a); !t.empty()) parts.push_back(t);
      s = join_words(parts);
      break;
    }
  }
  if (!rule.notes.empty()) s += (s.empty() ? "" : "; ") + rule.notes;
  return s;
}

std::string rules_markdown_table(const ObjectRule& rule, TableKind kind) {
  if (kind == TableKind::kOutput) {
    std::string s = "| field | type | unit | meaning |\n|---|---|---|---|\n";
    for (const auto& f : rule.fields)
      if (f.refused.empty())
        s += "| " + code(f.key) + " | " +
             cell(f.value.kind == ValueKind::kChoice ? "one of " + value_allowed_text(f.value)
                                                     : value_type_text(f.value)) +
             " | " + f.unit + " | " + cell(f.meaning) + (f.required ? "" : " (optional)") + " |\n";
    return s;
  }
  auto default_text = [](const FieldRule& f) {
    if (f.required) return std::string("required");
    if (f.default_value.is_null()) return std::string("optional");
    return code(f.default_value.dump());
  };
  auto row = [&](const std::string& lead, const FieldRule& f) {
    return "|" + lead + " " + code(f.key) + " | " + cell(value_type_text(f.value)) + " | " +
           default_text(f) + " | " + cell(value_allowed_text(f.value)) + " | " + cell(f.meaning) +
           " |\n";
  };
  std::string s;
  const bool variants = !rule.discriminator.empty();
  if (variants) {
    s += "| " + code(rule.discriminator) + " | field | type | default | allowed | meaning |\n";
    s += "|---|---|---|---|---|---|\n";
    for (const auto& f : rule.fields)
      if (f.refused.empty()) s += row(" (all) |", f);
    for (const auto& v : rule.variants) {
      if (!v.refused.empty()) continue;
      s += "| " + code("\"" + v.value + "\"") + " | | | | | " + cell(v.meaning) + " |\n";
      for (const auto& f : v.fields)
        if (f.refused.empty()) s += row(" |", f);
      for (const auto& e : v.exclusive)
        s += "| | | | | | give exactly one of: " + cell(exclusive_text(e)) + " |\n";
      if (!v.notes.empty()) s += "| | | | | | checked: " + cell(v.notes) + " |\n";
    }
  } else {
    s += "| field | type | default | allowed | meaning |\n";
    s += "|---|---|---|---|---|\n";
    for (const auto& f : rule.fields)
      if (f.refused.empty()) s += row("", f);
  }
  for (const auto& e : rule.exclusive) s += "\nGive exactly one of: " + exclusive_text(e) + ".\n";
  if (!rule.notes.empty()) s += "\nAlso checked: " + rule.notes + ".\n";
  return s;
}

}  // namespace fosls
