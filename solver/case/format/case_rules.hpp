#pragma once
// The rules of the case format as data: for every field its type, range, default and meaning,
// stated once. The reader checks a case against them (rule_checker.hpp) and words its error
// messages from them; the JSON Schema of the case (rules_schema.hpp, `fosls-contact schema`)
// and the field tables of docs/case-format.md (rules_markdown.hpp) are generated from the same
// rules, so the three cannot disagree. Rules a table cannot state (an expression must parse, a
// geometry must be one closed loop, ...) are hooks of the section that owns them, described in
// words by `notes`.

#include <functional>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fosls {

class RuleChecker;

/// Bounds of a number, or of a count (entries of an array, characters of a string).
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;

  bool contains(double v) const;
  bool has_lo() const;
  bool has_hi() const;
  /// "in (0, 1]", "> 0", ">= 0", "<= 5", or "finite" when unbounded.
  std::string text() const;

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity()}; }
  static Range closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Range open(double lo, double hi) { return {lo, hi, true, true}; }
  static Range at_most(double hi) { return {0.0, hi}; }
};

/// What kind of JSON value a field takes.
enum class ValueKind {
  kNumber,   ///< a finite number within `range`
  kInteger,  ///< an integral number within `range`
  kString,   ///< a string whose length (bytes) is within `range`
  kName,     ///< a name: 1 to `range.hi` bytes, no control characters
  kChoice,   ///< one string of `choices`
  kScalar,   ///< a number, or a string with an expression of x and y
  kNull,     ///< null (an alternative of kOneOf)
  kBoolean,  ///< true or false
  kArray,    ///< an array of `element`, with a number of entries within `range`
  kMap,      ///< an object from names (`key`) to `element`, entries within `range`
  kObject,   ///< an object described by `object`
  kOneOf,    ///< one of `alternatives`, chosen by the JSON type of the value
};

struct ObjectRule;
struct ValueRule;
using ValueRulePtr = std::shared_ptr<const ValueRule>;
using ObjectRulePtr = std::shared_ptr<const ObjectRule>;

/// A semantic rule on a structurally valid value (called only when the value passed its
/// structural checks); reports through the checker and returns false when the value is bad.
using ValueHook = std::function<bool(const nlohmann::json& value, const std::string& pointer,
                                     RuleChecker& checker)>;

/// The rule for one JSON value.
struct ValueRule {
  ValueKind kind = ValueKind::kNumber;
  /// A noun phrase for messages and docs ("an array of 2 numbers [x, y]"); generated when empty.
  std::string what;
  Range range = Range::any();
  std::vector<std::string> choices;     ///< kChoice
  ValueRulePtr element;                 ///< kArray, kMap
  ValueRulePtr key;                     ///< kMap: the rule for its keys (a kName)
  std::string entries = "entries";      ///< kArray, kMap: the word for its entries in messages
  ObjectRulePtr object;                 ///< kObject
  std::vector<ValueRule> alternatives;  ///< kOneOf
  int variables = 2;                    ///< kScalar: expressions of x, y (2) or x, y, z (3)
  /// Appended to a range error, e.g. why the bound is there.
  std::string range_note;
  /// kChoice: values known but refused here, each with the sentence that says where it belongs
  /// (a builtin of the other dimension); absent from the docs and the schema.
  std::vector<std::pair<std::string, std::string>> refused_choices;
  /// kArray: appended to the error of an array of `hint_count` entries (a 3-vector in a 2D
  /// case: "a 3D case needs \"dimension\": 3").
  std::size_t hint_count = 0;
  std::string count_hint;
  /// A semantic rule; `notes` says it in words for the docs.
  ValueHook hook;
  std::string notes;
};

/// One field of an object.
struct FieldRule {
  std::string key;
  ValueRule value;
  bool required = false;
  nlohmann::json default_value;  ///< null when there is no default
  std::string meaning;           ///< for docs and for "missing field" messages
  std::string unit;              ///< for the docs of results ("L", "S·L", "s"); empty for none
  /// Known but not allowed in this document (a field of the other dimension): giving it is an
  /// error with this sentence. Absent from the docs and the schema.
  std::string refused = {};
};

/// A semantic rule on a whole object whose fields all passed their checks.
using ObjectHook = std::function<void(const nlohmann::json& object, const std::string& pointer,
                                      RuleChecker& checker)>;

/// Exactly one of several sets of fields must be given; the fields of the given set are then
/// all required. `missing` and `several` are the messages (`{given}` in `several` is replaced
/// by the fields given, "builtin and msh").
struct ExclusiveFields {
  std::vector<std::vector<std::string>> sets;
  std::string missing;
  std::string several;
  /// The field `missing` is reported at (as a missing field's error); empty: the object.
  std::string missing_at = {};
};

/// A variant of an object with a discriminator field ("type": "plane" → the plane's fields).
struct ObjectVariant {
  std::string value;                            ///< the discriminator's value
  std::string title;                            ///< "a plane obstacle"
  std::string meaning;                          ///< for the docs
  std::vector<FieldRule> fields;                ///< besides the object's common fields
  ObjectHook hook;                              ///< on the whole object when its fields passed
  std::string notes;                            ///< the hook's rule in words
  std::vector<ExclusiveFields> exclusive = {};  ///< of the variant's fields, as ObjectRule's
  /// A value of the other dimension: choosing it is an error with this sentence (at the
  /// discriminator). Absent from the docs and the schema.
  std::string refused = {};
};

/// The rule for a JSON object: its fields, and optionally variants chosen by a discriminator.
struct ObjectRule {
  std::string title;   ///< "the solver settings": where unknown fields are reported
  std::string anchor;  ///< a name for the docs and the schema's $defs ("solver")
  std::vector<FieldRule> fields;
  std::string discriminator;          ///< e.g. "type"; empty when there are no variants
  std::string discriminator_meaning;  ///< for "missing field" messages
  std::vector<ObjectVariant> variants;
  std::vector<ExclusiveFields> exclusive;
  ObjectHook hook;
  std::string notes;

  /// The field named `key`, among the common fields and (when given) a variant's.
  const FieldRule* field(const std::string& key, const ObjectVariant* variant = nullptr) const;
  const ObjectVariant* variant(const std::string& value) const;
};

// ---- building rules ---------------------------------------------------------------------------

ValueRule number_value(Range range = Range::any());
ValueRule integer_value(Range range);
ValueRule string_value(std::size_t max_length, std::string what);
ValueRule name_value(std::size_t max_length, std::string what);
ValueRule choice_value(std::vector<std::string> choices);
ValueRule scalar_value(std::size_t max_expression_length);
/// A scalar of a case in `dim` dimensions: a number or an expression of x and y (2D) or of x, y
/// and z (3D, and 0: the docs and the schema of both).
ValueRule scalar_value_in(int dim, std::size_t max_expression_length);
/// A vector of a case in `dim` dimensions: `dim` entries of `element`, named `what2` (2D) or
/// `what3` (3D); for `dim` 0 (the docs and the schema of both) 2 or 3 entries. An array of the
/// other dimension's length is refused with a sentence that says so.
ValueRule vector_value(int dim, ValueRule element, const std::string& what2,
                       const std::string& what3);
/// What the 2D rules say of 3D data: a case whose refusals say it is probably a 3D case without
/// its dimension (case_reader.cpp).
inline constexpr const char* kNeedsDimension3 = "a 3D case needs \"dimension\": 3";

/// Words that differ by dimension: `two` in 2D, `three` in 3D, "two (2D) or three (3D)" for the
/// docs (`dim` 0; `joint` instead of " or ").
std::string in_dimension(int dim, const std::string& two, const std::string& three,
                         const std::string& joint = " or ");
ValueRule null_value();
ValueRule boolean_value();
/// An array of exactly `count` entries.
ValueRule tuple_value(ValueRule element, std::size_t count, std::string what);
/// An array of 1 to `max_entries` entries.
ValueRule array_value(ValueRule element, std::size_t max_entries, std::string what);
/// An array of any length, possibly empty.
ValueRule list_value(ValueRule element, std::string what);
/// An object from names to `element`, 1 to `max_entries` entries.
ValueRule map_value(ValueRule key, ValueRule element, std::size_t max_entries, std::string what,
                    std::string entries);
ValueRule object_value(ObjectRulePtr object);
ValueRule one_of_value(std::vector<ValueRule> alternatives, std::string what);

/// [x, y], finite numbers.
ValueRule point_value();

FieldRule required_field(std::string key, ValueRule value, std::string meaning);
FieldRule optional_field(std::string key, ValueRule value, nlohmann::json default_value,
                         std::string meaning);
/// A field of an output document: always present, with a unit.
FieldRule output_field(std::string key, ValueRule value, std::string unit, std::string meaning);
/// A field of the other dimension: known, and refused with `why` when given.
FieldRule refused_field(std::string key, std::string why);
/// A variant of the other dimension: refused with `why` when chosen.
ObjectVariant refused_variant(std::string value, std::string why);

// ---- words --------------------------------------------------------------------------------

/// What a value is, for "expected …, got …" messages ("the number 3", "an array of 2 elements").
std::string describe_value(const nlohmann::json& j);
/// A number as the messages print it: whole numbers in full, others as %g.
std::string format_number(double v);
/// The noun phrase of a rule: its `what`, or one made from its kind.
std::string value_noun(const ValueRule& rule);
/// "a, b or c" (`last` joins the last two).
std::string join_words(const std::vector<std::string>& words, const std::string& last = " or ");

}  // namespace fosls
