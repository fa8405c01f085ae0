#pragma once
// What admission says of a submitted case, and the validator that says it: the seam between the
// HTTP layer (submission.hpp) and the solver library (case_job_runner.hpp), which tests replace.

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "case/format/case_error.hpp"

namespace fosls::service {

/// Every problem of a parsed case with its JSON pointer, and for a case without any the time
/// its solve is estimated to take (kept with the job: the worker derives the job's time limit
/// from it without reading the case again).
struct CaseVerdict {
  std::vector<CaseError> errors;
  std::optional<double> estimate_seconds;
};

/// Checks a parsed case before it is queued.
using CaseValidator = std::function<CaseVerdict(const nlohmann::json& case_json)>;

}  // namespace fosls::service
