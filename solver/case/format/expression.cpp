#include "case/format/expression.hpp"

#include <muParser.h>

#include <array>
#include <cctype>
#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace fosls {

namespace {

/// One muParser instance with its own x and y (and z for 3D cases). Not movable: muParser keeps
/// the addresses of the variables, so each instance lives at one place (on the heap when shared).
class ExpressionParser {
 public:
  explicit ExpressionParser(const std::string& text, int variables = 2) : variables_(variables) {
    parser_.DefineVar("x", &x_);
    parser_.DefineVar("y", &y_);
    if (variables == 3) parser_.DefineVar("z", &z_);
    // muParser's own _pi and _e carry only 12 digits; replace them by the double values.
    parser_.DefineConst("pi", std::numbers::pi);
    parser_.DefineConst("_pi", std::numbers::pi);
    parser_.DefineConst("_e", std::numbers::e);
    parser_.SetExpr(text);
  }
  ExpressionParser(const ExpressionParser&) = delete;
  ExpressionParser& operator=(const ExpressionParser&) = delete;

  /// Value at (x, y). The first call turns the text into byte code and may throw
  /// mu::ParserError; later calls do not.
  double eval(double x, double y, double z = 0.0) {
    x_ = x;
    y_ = y;
    z_ = z;
    return parser_.Eval();
  }
  int num_results() const { return parser_.GetNumResults(); }
  /// Whether the expression changed a variable (muParser accepts `x = 3`).
  bool assigned(double x, double y, double z = 0.0) const { return x_ != x || y_ != y || z_ != z; }
  bool is_function(const std::string& name) const { return parser_.GetFunDef().count(name) > 0; }
  int variables() const { return variables_; }

 private:
  int variables_;
  double x_ = 0.0;
  double y_ = 0.0;
  double z_ = 0.0;
  mu::Parser parser_;
};

bool is_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

std::string describe(const mu::ParserError& e, const ExpressionParser& p) {
  const std::string token = e.GetToken();
  if ((e.GetCode() == mu::ecUNASSIGNABLE_TOKEN || e.GetCode() == mu::ecUNEXPECTED_VAR) &&
      is_identifier(token) && !p.is_function(token)) {
    return "unknown variable or name \"" + token + "\" at position " + std::to_string(e.GetPos()) +
           "; an expression may use only the variables " +
           std::string(p.variables() == 3 ? "x, y and z" : "x and y") +
           ", the constants pi, _pi and _e, "
           "and muParser's functions (sin, cos, tan, exp, ln, log10, sqrt, abs, min, max, ...)";
  }
  return "cannot parse the expression: " + e.GetMsg();
}

std::string format_point(double x, double y, double z, int variables) {
  std::ostringstream s;
  if (variables == 3)
    s << "(x, y, z) = (" << x << ", " << y << ", " << z << ")";
  else
    s << "(x, y) = (" << x << ", " << y << ")";
  return s.str();
}

}  // namespace

ScalarFunction compile_scalar(const Scalar& s) {
  if (s.is_constant()) {
    const double v = s.value;
    return [v](double, double) { return v; };
  }
  auto parser = std::make_shared<ExpressionParser>(s.expression);
  try {
    parser->eval(0.0, 0.0);  // parse now, so that a bad expression fails here, not mid-solve
  } catch (const mu::ParserError& e) {
    throw std::invalid_argument("expression \"" + s.expression + "\": " + describe(e, *parser));
  }
  return [parser](double x, double y) { return parser->eval(x, y); };
}

ScalarFunction3d compile_scalar_3d(const Scalar& s) {
  if (s.is_constant()) {
    const double v = s.value;
    return [v](double, double, double) { return v; };
  }
  auto parser = std::make_shared<ExpressionParser>(s.expression, 3);
  try {
    parser->eval(0.0, 0.0, 0.0);
  } catch (const mu::ParserError& e) {
    throw std::invalid_argument("expression \"" + s.expression + "\": " + describe(e, *parser));
  }
  return [parser](double x, double y, double z) { return parser->eval(x, y, z); };
}

std::optional<std::string> check_expression(const std::string& text, std::size_t max_length,
                                            int variables) {
  if (text.size() > max_length)
    return "the expression is " + std::to_string(text.size()) + " characters long; at most " +
           std::to_string(max_length) + " are allowed";
  bool blank = true;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    // muParser reads a C string in places; a NUL or other control byte could hide the rest.
    if ((c < 0x20 && c != ' ' && c != '\t') || c == 0x7f)
      return "the expression contains a control character at position " + std::to_string(i);
    if (c >= 0x80)
      return "the expression contains a non-ASCII character at position " + std::to_string(i) +
             "; use plain ASCII";
    if (c != ' ' && c != '\t') blank = false;
  }
  if (blank)
    return std::string("the expression is empty; give a number or an expression of ") +
           (variables == 3 ? "x, y and z" : "x and y");

  // Points inside the shipped geometries, so that e.g. sqrt(x) and sqrt(1 - x^2) are accepted.
  constexpr std::array<std::array<double, 3>, 3> samples = {
      {{0.0, 0.0, 0.0}, {0.5, 0.25, 0.5}, {1.0, 1.0, 1.0}}};
  ExpressionParser parser(text, variables);
  try {
    for (const auto& [x, y, z] : samples) {
      const double v = parser.eval(x, y, z);
      if (parser.num_results() != 1)
        return "the expression gives " + std::to_string(parser.num_results()) +
               " comma-separated values; give exactly one";
      if (parser.assigned(x, y, z))
        return std::string("the expression assigns to ") +
               (variables == 3 ? "x, y or z" : "x or y") +
               "; it may only compute a value (use == to compare)";
      if (!std::isfinite(v)) {
        std::ostringstream value;
        value << v;
        return "the expression is not finite at " + format_point(x, y, z, variables) + " (value " +
               value.str() + "); it must give a finite number at every point";
      }
    }
  } catch (const mu::ParserError& e) {
    return describe(e, parser);
  }
  return std::nullopt;
}

}  // namespace fosls
