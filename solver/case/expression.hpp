#pragma once
// Scalars of the case (numbers or muParser expressions of x, y) as callable functions.

#include <functional>
#include <optional>
#include <string>

#include "case/case_spec.hpp"

namespace fosls {

using ScalarFunction = std::function<double(double x, double y)>;

/// Compiles a scalar. The returned function is not safe to call from several threads at once.
/// Throws std::invalid_argument with muParser's message when the expression does not parse.
ScalarFunction compile_scalar(const Scalar& s);

/// The reason an expression is not acceptable (unparsable, unknown variable, not finite at
/// the origin), or nothing when it is fine.
std::optional<std::string> check_expression(const std::string& text);

}  // namespace fosls
