#include "case/format/rule_checker.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "case/format/expression.hpp"
#include "case/format/units.hpp"

namespace fosls {

namespace {

using nlohmann::json;

bool looks_like_number(const std::string& s) {
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size();
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

/// Whether an alternative of a kOneOf rule takes values of j's JSON type.
bool takes_type(const ValueRule& rule, const json& j) {
  switch (rule.kind) {
    case ValueKind::kNumber:
    case ValueKind::kInteger:
      return j.is_number();
    case ValueKind::kString:
    case ValueKind::kName:
    case ValueKind::kChoice:
      return j.is_string();
    case ValueKind::kScalar:
      return j.is_number() || j.is_string();
    case ValueKind::kNull:
      return j.is_null();
    case ValueKind::kBoolean:
      return j.is_boolean();
    case ValueKind::kArray:
      return j.is_array();
    case ValueKind::kMap:
    case ValueKind::kObject:
      return j.is_object();
    case ValueKind::kOneOf:
      return std::any_of(rule.alternatives.begin(), rule.alternatives.end(),
                         [&](const ValueRule& a) { return takes_type(a, j); });
  }
  return false;
}

std::string count_text(const Range& range) { return format_number(range.hi); }

}  // namespace

void RuleChecker::error(std::string pointer, std::string detail) {
  errors_.push_back({std::move(pointer), std::move(detail)});
}

bool RuleChecker::check(const json& j, const ValueRule& rule, const std::string& pointer) {
  const std::size_t before = errors_.size();
  bool ok = false;
  switch (rule.kind) {
    case ValueKind::kNumber:
    case ValueKind::kInteger:
      ok = check_number(j, rule, pointer);
      break;
    case ValueKind::kString:
    case ValueKind::kName:
      ok = check_string(j, rule, pointer);
      break;
    case ValueKind::kChoice:
      ok = check_choice(j, rule, pointer);
      break;
    case ValueKind::kScalar:
      ok = check_scalar(j, rule, pointer);
      break;
    case ValueKind::kNull:
      ok = j.is_null();
      if (!ok) error(pointer, "expected null, got " + describe_value(j));
      break;
    case ValueKind::kBoolean:
      ok = j.is_boolean();
      if (!ok) error(pointer, "expected true or false, got " + describe_value(j));
      break;
    case ValueKind::kArray:
      ok = check_array(j, rule, pointer);
      break;
    case ValueKind::kMap:
      ok = check_map(j, rule, pointer);
      break;
    case ValueKind::kObject:
      ok = check_object(j, *rule.object, pointer);
      break;
    case ValueKind::kOneOf:
      ok = check_one_of(j, rule, pointer);
      break;
  }
  if (ok && rule.hook) ok = rule.hook(j, pointer, *this);
  ok = ok && errors_.size() == before;
  passed_[pointer] = ok;
  return ok;
}

bool RuleChecker::passed(const std::string& pointer) const {
  auto it = passed_.find(pointer);
  return it != passed_.end() && it->second;
}

bool RuleChecker::usable(const json& object, const std::string& pointer,
                         const std::vector<std::string>& keys) const {
  for (const auto& key : keys)
    if (object.contains(key) && !passed(child_pointer(pointer, key))) return false;
  return true;
}

bool RuleChecker::check_number(const json& j, const ValueRule& rule, const std::string& pointer) {
  const bool integer = rule.kind == ValueKind::kInteger;
  if (!j.is_number()) {
    error(pointer, "expected " + value_noun(rule) + ", got " + describe_value(j) + unit_hint(j));
    return false;
  }
  const double v = j.get<double>();
  if (integer && (!std::isfinite(v) || v != std::floor(v))) {
    error(pointer, "expected an integer, got " + format_number(v));
    return false;
  }
  if (!std::isfinite(v) || !rule.range.contains(v)) {
    const Range& r = rule.range;
    const std::string bounds =
        !integer ? r.text()
        : r.has_lo() && r.has_hi()
            ? "an integer from " + format_number(r.lo) + " to " + format_number(r.hi)
            : "an integer " + r.text();
    error(pointer, "must be " + bounds + ", got " + format_number(v) + rule.range_note);
    return false;
  }
  return true;
}

bool RuleChecker::check_string(const json& j, const ValueRule& rule, const std::string& pointer) {
  if (!j.is_string()) {
    error(pointer, "expected a string, got " + describe_value(j));
    return false;
  }
  const auto& s = j.get_ref<const std::string&>();
  const std::string what = rule.what.empty() ? "the string" : rule.what;
  if (rule.kind == ValueKind::kName && s.empty()) {
    error(pointer, what + " is empty; give a non-empty name");
    return false;
  }
  if (static_cast<double>(s.size()) > rule.range.hi) {
    error(pointer, what + " is " + std::to_string(s.size()) + " characters long; at most " +
                       count_text(rule.range) + " are allowed");
    return false;
  }
  if (rule.kind == ValueKind::kName)
    for (unsigned char c : s)
      if (c < 0x20 || c == 0x7f) {
        error(pointer, what + " contains a control character; use printable characters");
        return false;
      }
  return true;
}

bool RuleChecker::check_choice(const json& j, const ValueRule& rule, const std::string& pointer) {
  const std::string names = join_words(rule.choices, ", ");
  if (!j.is_string()) {
    error(pointer, "expected a string (one of " + names + "), got " + describe_value(j));
    return false;
  }
  const auto& s = j.get_ref<const std::string&>();
  if (std::find(rule.choices.begin(), rule.choices.end(), s) != rule.choices.end()) return true;
  for (const auto& [value, why] : rule.refused_choices)
    if (s == value) {
      error(pointer, why);
      return false;
    }
  const std::string value =
      s.size() > 40 ? describe_value(j) : j.dump(-1, ' ', false, json::error_handler_t::replace);
  if (rule.choices.size() == 1)
    error(pointer, "unknown value " + value + ", expected the string " + quoted(rule.choices[0]) +
                       rule.range_note);
  else
    error(pointer, "unknown value " + value + ", expected one of: " + names);
  return false;
}

bool RuleChecker::check_scalar(const json& j, const ValueRule& rule, const std::string& pointer) {
  if (j.is_number()) return check_number(j, number_value(), pointer);
  if (!j.is_string()) {
    error(pointer, "expected " + value_noun(rule) + ", got " + describe_value(j));
    return false;
  }
  if (auto reason = check_expression(j.get<std::string>(), static_cast<std::size_t>(rule.range.hi),
                                     rule.variables)) {
    error(pointer, *reason + unit_hint(j));
    return false;
  }
  return true;
}

bool RuleChecker::check_array(const json& j, const ValueRule& rule, const std::string& pointer) {
  const bool tuple = rule.range.lo == rule.range.hi;
  if (!j.is_array() || static_cast<double>(j.size()) < rule.range.lo ||
      (tuple && static_cast<double>(j.size()) != rule.range.hi)) {
    const bool hinted = j.is_array() && rule.hint_count > 0 && j.size() == rule.hint_count;
    error(pointer, "expected " + std::string(tuple || rule.range.lo < 1 ? "" : "a non-empty ") +
                       value_noun(rule) + ", got " + describe_value(j) +
                       (hinted ? rule.count_hint : ""));
    return false;
  }
  if (static_cast<double>(j.size()) > rule.range.hi) {
    error(pointer, "has " + std::to_string(j.size()) + " " + rule.entries + "; at most " +
                       count_text(rule.range) + " are allowed");
    return false;
  }
  bool ok = true;
  for (std::size_t i = 0; i < j.size(); ++i)
    ok = check(j[i], *rule.element, child_pointer(pointer, i)) && ok;
  return ok;
}

bool RuleChecker::check_map(const json& j, const ValueRule& rule, const std::string& pointer) {
  if (!j.is_object() || static_cast<double>(j.size()) < rule.range.lo) {
    error(pointer, "expected a non-empty " + value_noun(rule) + ", got " + describe_value(j));
    return false;
  }
  if (static_cast<double>(j.size()) > rule.range.hi) {
    error(pointer, "has " + std::to_string(j.size()) + " " + rule.entries + "; at most " +
                       count_text(rule.range) + " are allowed");
    return false;
  }
  bool ok = true;
  for (const auto& [key, value] : j.items()) {
    const std::string p = child_pointer(pointer, key);
    ok = check(json(key), *rule.key, p) && ok;
    ok = check(value, *rule.element, p) && ok;
  }
  return ok;
}

bool RuleChecker::check_one_of(const json& j, const ValueRule& rule, const std::string& pointer) {
  for (const auto& alternative : rule.alternatives) {
    // A number written as a string ("0.5" for 0.5) is a mistyped number, not a misspelt word:
    // name every alternative rather than the words alone.
    const bool quoted_number = alternative.kind == ValueKind::kChoice && j.is_string() &&
                               looks_like_number(j.get<std::string>()) &&
                               std::find(alternative.choices.begin(), alternative.choices.end(),
                                         j.get<std::string>()) == alternative.choices.end();
    if (takes_type(alternative, j) && !quoted_number) return check(j, alternative, pointer);
  }
  error(pointer, "expected " + value_noun(rule) + ", got " + describe_value(j));
  return false;
}

void RuleChecker::check_exclusive(const json& j, const ExclusiveFields& rule,
                                  const std::string& pointer) {
  std::vector<std::string> given;
  int sets_given = 0;
  for (const auto& set : rule.sets) {
    bool any = false;
    for (const auto& key : set)
      if (j.contains(key)) {
        given.push_back(key);
        any = true;
      }
    sets_given += any ? 1 : 0;
  }
  if (sets_given == 0) {
    error(rule.missing_at.empty() ? pointer : child_pointer(pointer, rule.missing_at),
          rule.missing);
  } else if (sets_given > 1) {
    std::string message = rule.several;
    if (auto at = message.find("{given}"); at != std::string::npos)
      message.replace(at, 7, join_words(given, " and "));
    error(pointer, message);
  }
}

bool RuleChecker::check_object(const json& j, const ObjectRule& rule, const std::string& pointer) {
  if (!j.is_object()) {
    error(pointer, "expected an object (" + rule.title + "), got " + describe_value(j));
    return false;
  }
  const std::size_t before = errors_.size();
  const ObjectVariant* variant = nullptr;
  if (!rule.discriminator.empty()) {
    auto it = j.find(rule.discriminator);
    if (it == j.end()) {
      error(child_pointer(pointer, rule.discriminator),
            "missing field " + quoted(rule.discriminator) + ": " + rule.discriminator_meaning);
      return false;
    }
    ValueRule values = choice_value({});
    for (const auto& v : rule.variants)
      if (v.refused.empty())
        values.choices.push_back(v.value);
      else
        values.refused_choices.emplace_back(v.value, v.refused);
    if (!check(*it, values, child_pointer(pointer, rule.discriminator))) return false;
    variant = rule.variant(it->get<std::string>());
  }

  // Refused fields are known (their own sentence, not "unknown field") but not offered.
  std::vector<std::string> known, offered;
  auto know = [&](const std::string& key, bool refused) {
    known.push_back(key);
    if (!refused) offered.push_back(key);
  };
  if (!rule.discriminator.empty()) know(rule.discriminator, false);
  for (const auto& f : rule.fields) know(f.key, !f.refused.empty());
  if (variant)
    for (const auto& f : variant->fields) know(f.key, !f.refused.empty());
  const std::string title = variant ? variant->title : rule.title;
  for (const auto& [key, value] : j.items())
    if (std::find(known.begin(), known.end(), key) == known.end())
      error(child_pointer(pointer, key), "unknown field " + quoted(key) + " in " + title +
                                             ", expected one of: " + join_words(offered, ", "));

  std::vector<ExclusiveFields> exclusives = rule.exclusive;
  if (variant)
    exclusives.insert(exclusives.end(), variant->exclusive.begin(), variant->exclusive.end());
  for (const auto& exclusive : exclusives) check_exclusive(j, exclusive, pointer);
  auto required = [&](const FieldRule& f) {
    if (f.required) return true;
    for (const auto& exclusive : exclusives)
      for (const auto& set : exclusive.sets)
        if (std::find(set.begin(), set.end(), f.key) != set.end())
          for (const auto& member : set)
            if (j.contains(member)) return true;
    return false;
  };
  auto check_fields = [&](const std::vector<FieldRule>& fields) {
    for (const auto& f : fields) {
      auto it = j.find(f.key);
      if (it != j.end() && !f.refused.empty())
        error(child_pointer(pointer, f.key), f.refused);
      else if (it != j.end())
        check(*it, f.value, child_pointer(pointer, f.key));
      else if (f.refused.empty() && required(f))
        error(child_pointer(pointer, f.key), "missing field " + quoted(f.key) + ": " + f.meaning);
    }
  };
  check_fields(rule.fields);
  if (variant) check_fields(variant->fields);

  // The hooks run even when some fields failed: each checks the fields it needs with usable(),
  // so that every problem of a case shows at once.
  if (rule.hook) rule.hook(j, pointer, *this);
  if (variant && variant->hook) variant->hook(j, pointer, *this);
  const bool ok = errors_.size() == before;
  passed_[pointer] = ok;
  return ok;
}

}  // namespace fosls
