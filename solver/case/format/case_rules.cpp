#include "case/format/case_rules.hpp"

#include <cmath>
#include <sstream>
#include <utility>

namespace fosls {

// ---- Range ------------------------------------------------------------------------------------

bool Range::contains(double v) const {
  return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
}

bool Range::has_lo() const { return std::isfinite(lo); }
bool Range::has_hi() const { return std::isfinite(hi); }

std::string Range::text() const {
  if (has_lo() && has_hi())
    return std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " +
           format_number(hi) + (hi_open ? ")" : "]");
  if (has_lo()) return std::string(lo_open ? "> " : ">= ") + format_number(lo);
  if (has_hi()) return std::string(hi_open ? "< " : "<= ") + format_number(hi);
  return "finite";
}

// ---- ObjectRule -------------------------------------------------------------------------------

const FieldRule* ObjectRule::field(const std::string& key, const ObjectVariant* v) const {
  for (const auto& f : fields)
    if (f.key == key) return &f;
  if (v)
    for (const auto& f : v->fields)
      if (f.key == key) return &f;
  return nullptr;
}

const ObjectVariant* ObjectRule::variant(const std::string& value) const {
  for (const auto& v : variants)
    if (v.value == value) return &v;
  return nullptr;
}

// ---- building rules ---------------------------------------------------------------------------

ValueRule number_value(Range range) {
  ValueRule r;
  r.kind = ValueKind::kNumber;
  r.range = range;
  return r;
}

ValueRule integer_value(Range range) {
  ValueRule r;
  r.kind = ValueKind::kInteger;
  r.range = range;
  return r;
}

ValueRule string_value(std::size_t max_length, std::string what) {
  ValueRule r;
  r.kind = ValueKind::kString;
  r.range = Range::at_most(static_cast<double>(max_length));
  r.what = std::move(what);
  return r;
}

ValueRule name_value(std::size_t max_length, std::string what) {
  ValueRule r = string_value(max_length, std::move(what));
  r.kind = ValueKind::kName;
  r.range.lo = 1;
  return r;
}

ValueRule choice_value(std::vector<std::string> choices) {
  ValueRule r;
  r.kind = ValueKind::kChoice;
  r.choices = std::move(choices);
  return r;
}

ValueRule scalar_value(std::size_t max_expression_length) {
  ValueRule r;
  r.kind = ValueKind::kScalar;
  r.range = Range::at_most(static_cast<double>(max_expression_length));
  return r;
}

ValueRule scalar_value_in(int dim, std::size_t max_expression_length) {
  ValueRule r = scalar_value(max_expression_length);
  r.variables = dim == 2 ? 2 : 3;
  return r;
}

ValueRule vector_value(int dim, ValueRule element, const std::string& what2,
                       const std::string& what3) {
  if (dim == 0) {
    ValueRule r = tuple_value(std::move(element), 2, in_dimension(0, what2, what3));
    r.range.hi = 3;
    return r;
  }
  ValueRule r = tuple_value(std::move(element), dim, dim == 2 ? what2 : what3);
  r.hint_count = dim == 2 ? 3 : 2;
  r.count_hint = dim == 2 ? std::string(" (") + kNeedsDimension3 + ")"
                          : " (a 3D case has three components: x, y and z)";
  return r;
}

std::string in_dimension(int dim, const std::string& two, const std::string& three,
                         const std::string& joint) {
  if (dim == 2) return two;
  if (dim == 3) return three;
  return two + " (2D)" + joint + three + " (3D)";
}

ValueRule null_value() {
  ValueRule r;
  r.kind = ValueKind::kNull;
  return r;
}

ValueRule boolean_value() {
  ValueRule r;
  r.kind = ValueKind::kBoolean;
  return r;
}

ValueRule tuple_value(ValueRule element, std::size_t count, std::string what) {
  ValueRule r;
  r.kind = ValueKind::kArray;
  r.element = std::make_shared<const ValueRule>(std::move(element));
  r.range = Range::closed(static_cast<double>(count), static_cast<double>(count));
  r.what = std::move(what);
  return r;
}

ValueRule array_value(ValueRule element, std::size_t max_entries, std::string what) {
  ValueRule r = tuple_value(std::move(element), 1, std::move(what));
  r.range.hi = static_cast<double>(max_entries);
  return r;
}

ValueRule list_value(ValueRule element, std::string what) {
  ValueRule r = tuple_value(std::move(element), 0, std::move(what));
  r.range.hi = std::numeric_limits<double>::infinity();
  return r;
}

ValueRule map_value(ValueRule key, ValueRule element, std::size_t max_entries, std::string what,
                    std::string entries) {
  ValueRule r;
  r.kind = ValueKind::kMap;
  r.key = std::make_shared<const ValueRule>(std::move(key));
  r.element = std::make_shared<const ValueRule>(std::move(element));
  r.range = Range::closed(1, static_cast<double>(max_entries));
  r.what = std::move(what);
  r.entries = std::move(entries);
  return r;
}

ValueRule object_value(ObjectRulePtr object) {
  ValueRule r;
  r.kind = ValueKind::kObject;
  r.object = std::move(object);
  return r;
}

ValueRule one_of_value(std::vector<ValueRule> alternatives, std::string what) {
  ValueRule r;
  r.kind = ValueKind::kOneOf;
  r.alternatives = std::move(alternatives);
  r.what = std::move(what);
  return r;
}

ValueRule point_value() { return tuple_value(number_value(), 2, "an array of 2 numbers [x, y]"); }

FieldRule required_field(std::string key, ValueRule value, std::string meaning) {
  FieldRule f;
  f.key = std::move(key);
  f.value = std::move(value);
  f.required = true;
  f.meaning = std::move(meaning);
  return f;
}

FieldRule optional_field(std::string key, ValueRule value, nlohmann::json default_value,
                         std::string meaning) {
  FieldRule f;
  f.key = std::move(key);
  f.value = std::move(value);
  f.default_value = std::move(default_value);
  f.meaning = std::move(meaning);
  return f;
}

FieldRule output_field(std::string key, ValueRule value, std::string unit, std::string meaning) {
  FieldRule f = required_field(std::move(key), std::move(value), std::move(meaning));
  f.unit = std::move(unit);
  return f;
}

FieldRule refused_field(std::string key, std::string why) {
  FieldRule f;
  f.key = std::move(key);
  f.refused = std::move(why);
  return f;
}

ObjectVariant refused_variant(std::string value, std::string why) {
  ObjectVariant v;
  v.value = std::move(value);
  v.refused = std::move(why);
  return v;
}

// ---- words ------------------------------------------------------------------------------------

std::string format_number(double v) {
  // Whole numbers in full (4194304, not 4.1943e+06): limits and counts read exactly.
  if (std::isfinite(v) && v == std::floor(v) && std::abs(v) < 1e15)
    return std::to_string(static_cast<long long>(v));
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string describe_value(const nlohmann::json& j) {
  using nlohmann::json;
  switch (j.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return std::string("the boolean ") + (j.get<bool>() ? "true" : "false");
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return "the number " + format_number(j.get<double>());
    case json::value_t::string: {
      const auto& s = j.get_ref<const std::string&>();
      if (s.size() > 40) return "a string of " + std::to_string(s.size()) + " characters";
      return "the string " + j.dump(-1, ' ', false, json::error_handler_t::replace);
    }
    case json::value_t::array:
      return "an array of " + std::to_string(j.size()) + " element" + (j.size() == 1 ? "" : "s");
    case json::value_t::object:
      return "an object";
    default:
      return "a value of an unsupported type";
  }
}

std::string join_words(const std::vector<std::string>& words, const std::string& last) {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) s += i + 1 == words.size() ? last : ", ";
    s += words[i];
  }
  return s;
}

std::string value_noun(const ValueRule& rule) {
  if (!rule.what.empty()) return rule.what;
  switch (rule.kind) {
    case ValueKind::kNumber:
      return "a number";
    case ValueKind::kInteger:
      return "an integer";
    case ValueKind::kString:
    case ValueKind::kName:
      return "a string";
    case ValueKind::kChoice:
      return "a string (one of " + join_words(rule.choices, ", ") + ")";
    case ValueKind::kScalar:
      return rule.variables == 3 ? "a number or a string with an expression of x, y and z"
                                 : "a number or a string with an expression of x and y";
    case ValueKind::kNull:
      return "null";
    case ValueKind::kBoolean:
      return "true or false";
    case ValueKind::kArray:
      return "an array";
    case ValueKind::kMap:
    case ValueKind::kObject:
      return rule.object ? "an object (" + rule.object->title + ")" : "an object";
    case ValueKind::kOneOf: {
      std::vector<std::string> nouns;
      for (const auto& a : rule.alternatives) nouns.push_back(value_noun(a));
      return join_words(nouns);
    }
  }
  return "a value";
}

}  // namespace fosls
