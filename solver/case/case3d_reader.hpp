#pragma once
// 3D case JSON ("dimension": 3) → Case3dSpec, every problem reported at once with its JSON
// pointer, by the same rule machinery as the 2D case (case_rules.hpp). The format is documented
// in docs/case-format.md, "3D cases"; its field tables are generated from case3d_rule().

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "case/case3d_spec.hpp"
#include "case/case_error.hpp"
#include "case/case_limits.hpp"
#include "case/case_rules.hpp"

namespace fosls {

/// Refinements of a 3D mesh at most: each multiplies the unknowns by about 8.
constexpr int kMax3dRefinements = 5;

/// Whether `j` declares itself a 3D case (an object with "dimension": 3).
bool is_3d_case(const nlohmann::json& j);

struct Case3dReadResult {
  std::optional<Case3dSpec> spec;  ///< set when errors is empty
  std::vector<CaseError> errors;
};

ObjectRulePtr case3d_rule(const CaseReadOptions& options = {});
/// Reads and validates a parsed 3D case. Never throws for bad input.
Case3dReadResult read_case_3d(const nlohmann::json& j, const CaseReadOptions& options = {});

}  // namespace fosls
