#pragma once
// The result JSON of a solve as rules (case_rules.hpp): every field, its type, unit and
// meaning. docs/result-format.md and the result's JSON Schema are generated from it, and a
// test checks every result the shipped examples produce against it.

#include "case/case_rules.hpp"

namespace fosls {

/// Why the iteration stopped.
enum class StopReason { kConverged, kMaxIterations, kTimeLimit, kCancelled };
const char* stop_reason_name(StopReason reason);

/// The rules of the result JSON of one solve.
ObjectRulePtr result_rule();
/// The rules of a 3D case's result (result3d_rules.cpp; docs/result-format.md, "3D results").
ObjectRulePtr result3d_rule();

}  // namespace fosls
