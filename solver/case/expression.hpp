#pragma once
// Scalars of the case (numbers or muParser expressions of x, y) as callable functions.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "case/case_spec.hpp"

namespace fosls {

using ScalarFunction = std::function<double(double x, double y)>;

/// Compiles a scalar. The returned function is not safe to call from several threads at once.
/// Throws std::invalid_argument with muParser's message when the expression does not parse.
ScalarFunction compile_scalar(const Scalar& s);

/// The reason an expression is not acceptable (empty, longer than `max_length` characters,
/// unparsable, an unknown variable, an assignment, several comma-separated values, or not
/// finite at one of the sample points (0, 0), (0.5, 0.25), (1, 1)), or nothing when it is fine.
std::optional<std::string> check_expression(const std::string& text, std::size_t max_length = 1024);

}  // namespace fosls
