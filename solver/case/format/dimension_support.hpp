#pragma once
// What a 3D case cannot do yet, refused once it is read, at the field, with why and that it is
// coming (docs/case-format.md, "3D cases"): the format reads every section in both dimensions,
// and one point runner (point_runner.hpp) solves both; 3D has no friction or order 2 yet.

#include <nlohmann/json.hpp>
#include <vector>

#include "case/format/case_error.hpp"
#include "case/format/case_spec.hpp"

namespace fosls {

/// The problems of a read 3D case `spec` (from `j`) that the 3D backend cannot run; none for
/// a 2D case.
std::vector<CaseError> dimension_support_problems(const nlohmann::json& j, const CaseSpec& spec);

}  // namespace fosls
