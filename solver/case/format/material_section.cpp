// The `material` section: linear elastic, by the Lamé parameters or by E and ν.

#include <limits>

#include "case/format/case_sections.hpp"

namespace fosls {

ObjectRulePtr material_rule() {
  auto r = std::make_shared<ObjectRule>();
  r->title = "the material";
  r->anchor = "material";
  ValueRule lambda_number = number_value(Range::non_negative());
  lambda_number.range_note = " (lambda is never negative; \"inf\" means incompressible)";
  ValueRule lambda_inf = choice_value({"inf"});
  lambda_inf.range_note = " (incompressible)";
  r->fields = {
      optional_field("mu", number_value(Range::positive()), nullptr, "the shear modulus μ"),
      optional_field("lambda",
                     one_of_value({lambda_number, lambda_inf},
                                  "a number >= 0 or the string \"inf\" (incompressible)"),
                     nullptr, "the Lamé parameter λ; \"inf\" for an incompressible material"),
      optional_field("E", number_value(Range::positive()), nullptr, "Young's modulus"),
      optional_field("nu", number_value({-1.0, 0.5, true, false}), nullptr,
                     "Poisson's ratio ν; 0.5 means incompressible"),
  };
  r->exclusive = {{{{"mu", "lambda"}, {"E", "nu"}},
                   "missing material parameters: give mu and lambda, or E and nu",
                   "give either mu and lambda, or E and nu, not both"}};
  return r;
}

Material read_material_section(const nlohmann::json& j) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Material m;
  if (j.contains("mu")) {
    m.mu = j["mu"].get<double>();
    m.lambda = j["lambda"].is_string() ? kInf : j["lambda"].get<double>();
    return m;
  }
  const double E = j["E"].get<double>(), nu = j["nu"].get<double>();
  m.mu = E / (2.0 * (1.0 + nu));
  m.lambda = nu == 0.5 ? kInf : E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  return m;
}

}  // namespace fosls
