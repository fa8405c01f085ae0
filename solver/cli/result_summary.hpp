#pragma once
// The summary `fosls-contact solve` prints after a solve: the outcome line, the numbers an
// engineer looks for (force, peak pressure, contact zone, estimator, in the case's declared
// units), why an adaptive run stopped, a sweep's curve, and whether the answer needs review.

#include <nlohmann/json.hpp>
#include <ostream>

namespace fosls {

/// Prints the summary of `result` (docs/result-format.md) to `out`.
void print_result_summary(std::ostream& out, const nlohmann::json& result);
/// The same for a 3D result (docs/result-format.md, "3D results").
void print_result_summary_3d(std::ostream& out, const nlohmann::json& result);

/// The exit code for a written result: kExitNotConverged when it did not converge, else
/// kExitReviewRequired when a warning says the answer needs review, else kExitOk.
int result_exit_code(const nlohmann::json& result);

}  // namespace fosls
