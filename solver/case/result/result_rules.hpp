#pragma once
// The result JSON of a solve as rules (case_rules.hpp): every field, its type, unit and
// meaning. docs/result-format.md and the result's JSON Schema are generated from it, and a
// test checks every result the shipped examples produce against it.

#include "case/format/case_rules.hpp"

namespace fosls {

/// Why the iteration stopped.
enum class StopReason { kConverged, kMaxIterations, kTimeLimit, kCancelled };
const char* stop_reason_name(StopReason reason);

/// The rules of the result JSON of one solve of dimension `dim` (docs/result-format.md; a 3D
/// result's contact object is contact_faces_rules.cpp's).
ObjectRulePtr result_rule(int dim = 2);

}  // namespace fosls
