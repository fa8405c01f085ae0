#pragma once
// Case JSON → CaseSpec, 2D or 3D, with every problem reported at once. The rules of the format are
// data (case_rules.hpp, one section per file: case_sections.hpp); docs/case-format.md
// documents them.

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "case/admission/case_limits.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_rules.hpp"
#include "case/format/case_spec.hpp"

namespace fosls {

struct CaseReadResult {
  std::optional<CaseSpec> spec;  ///< set when errors is empty
  std::vector<CaseError> errors;
};

/// The rules of a whole case under `options` (its limits and whether geo_file is allowed) in
/// `dim` dimensions: 2 or 3, what the reader checks; 0, both, for the docs and tables.
ObjectRulePtr case_rule(const CaseReadOptions& options = {}, int dim = 2);

/// The dimension a case JSON declares: 3 for "dimension": 3, else 2 (a bad value is then a 2D
/// case's problem at /dimension).
int case_dimension(const nlohmann::json& j);

/// Reads and validates a parsed case JSON. Never throws for bad input.
CaseReadResult read_case(const nlohmann::json& j, const CaseReadOptions& options = {});

}  // namespace fosls
