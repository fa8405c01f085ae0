#pragma once
// Scalars of the case (numbers or muParser expressions of x, y, and z in 3D cases) as callable
// functions.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "case/format/case_spec.hpp"

namespace fosls {

using ScalarFunction = std::function<double(double x, double y)>;

/// Compiles a scalar. The returned function is not safe to call from several threads at once.
/// Throws std::invalid_argument with muParser's message when the expression does not parse.
ScalarFunction compile_scalar(const Scalar& s);

/// A 3D case's scalar: an expression of x, y and z. The same rules as compile_scalar.
using ScalarFunction3d = std::function<double(double x, double y, double z)>;
ScalarFunction3d compile_scalar_3d(const Scalar& s);

/// The reason an expression is not acceptable (empty, longer than `max_length` characters,
/// unparsable, an unknown variable, an assignment, several comma-separated values, or not
/// finite at one of the sample points (0, 0), (0.5, 0.25), (1, 1)), or nothing when it is fine.
/// `variables` 3: an expression of x, y and z (z = 0, 0.5, 1 at the sample points).
std::optional<std::string> check_expression(const std::string& text, std::size_t max_length = 1024,
                                            int variables = 2);

}  // namespace fosls
