#pragma once
// The case's optional `units` declaration. fosls-contact is unit-agnostic: it computes in
// whatever consistent units the case's numbers are in (lengths in one unit, stresses and moduli
// in one unit; forces per unit thickness then come out in stress × length). Declaring them
// changes no number: it names the units in every output and lets the plausibility check of
// the modulus use them (docs/case-format.md, "Units").

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "case/format/case_rules.hpp"

namespace fosls {

struct UnitsSpec {
  std::string length;  ///< "mm", "m", ...; empty when the case declares no units
  std::string stress;  ///< "MPa", "Pa", ...
  bool declared() const { return !length.empty(); }
};

/// The rules of the `units` section and its reading (case_sections.hpp's pattern).
ObjectRulePtr units_rule();
UnitsSpec read_units_section(const nlohmann::json& j);

/// The names a declaration may use, with their value in SI (metres, pascals).
struct UnitName {
  const char* name;
  double si;
};
const std::vector<UnitName>& length_units();
const std::vector<UnitName>& stress_units();

/// The unit of a force per unit thickness (stress × length): "N/mm" for MPa and mm, "N/m" for
/// Pa and m, "kN/m" for kPa and m, "lbf/in" for psi and in; "MPa·m" when the force unit has
/// no name.
std::string force_per_thickness_unit(const UnitsSpec& units);

/// The result's `units` object: {declared, length, stress, force_per_thickness}.
nlohmann::json units_json(const UnitsSpec& units);

/// For a string where a number was expected ("210 GPa", "0.6 mm"): the sentence that explains
/// consistent units, or "" when the string does not look like a number with a unit.
std::string unit_hint(const nlohmann::json& value);

/// Young's modulus of the material (μ and λ as read; λ may be infinite).
double youngs_modulus(double mu, double lambda);

/// A sentence when the modulus and the body's size do not go together in any plausible unit
/// system: with declared units, a modulus outside what solids have (100 Pa to 2e12 Pa); without,
/// a modulus that can only be in Pa or kPa (≥ 1e8, whose lengths are metres) on a body larger
/// than 5 of its length units. `extent` is the body's bounding-box diagonal. "" when plausible.
std::string implausible_units(const UnitsSpec& units, double E, double extent);

}  // namespace fosls
