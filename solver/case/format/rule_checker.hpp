#pragma once
// Checks a JSON value against the rules of the case format (case_rules.hpp), collecting every
// problem with its JSON pointer instead of stopping at the first.

#include <nlohmann/json.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "case/admission/case_limits.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_rules.hpp"

namespace fosls {

class RuleChecker {
 public:
  explicit RuleChecker(const CaseReadOptions& options) : options_(options) {}

  /// Checks `value` against `rule` (and its hook); true when nothing was wrong.
  bool check(const nlohmann::json& value, const ValueRule& rule, const std::string& pointer);
  /// Checks an object: the discriminator, unknown fields, exclusive and required fields, every
  /// field's value, then the object's and its variant's hooks (which run even when a field
  /// failed; see usable()).
  bool check_object(const nlohmann::json& value, const ObjectRule& rule,
                    const std::string& pointer);

  /// Whether the value at `pointer` was checked and passed.
  bool passed(const std::string& pointer) const;
  /// Whether each of `keys` that `object` (at `pointer`) has passed its checks: an object hook
  /// uses only fields that are usable, and the fields' defaults for absent ones.
  bool usable(const nlohmann::json& object, const std::string& pointer,
              const std::vector<std::string>& keys) const;

  /// Records a problem.
  void error(std::string pointer, std::string detail);
  const CaseReadOptions& options() const { return options_; }
  const std::vector<CaseError>& errors() const { return errors_; }
  std::vector<CaseError> take_errors() { return std::move(errors_); }

 private:
  /// Numbers and integers.
  bool check_number(const nlohmann::json& j, const ValueRule& rule, const std::string& pointer);
  bool check_string(const nlohmann::json& j, const ValueRule& rule, const std::string& pointer);
  bool check_choice(const nlohmann::json& j, const ValueRule& rule, const std::string& pointer);
  bool check_scalar(const nlohmann::json& j, const ValueRule& rule, const std::string& pointer);
  bool check_array(const nlohmann::json& j, const ValueRule& rule, const std::string& pointer);
  bool check_map(const nlohmann::json& j, const ValueRule& rule, const std::string& pointer);
  bool check_one_of(const nlohmann::json& j, const ValueRule& rule, const std::string& pointer);
  void check_exclusive(const nlohmann::json& j, const ExclusiveFields& rule,
                       const std::string& pointer);

  const CaseReadOptions& options_;
  std::vector<CaseError> errors_;
  std::unordered_map<std::string, bool> passed_;
};

}  // namespace fosls
