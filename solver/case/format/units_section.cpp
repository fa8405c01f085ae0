// The `units` section, the words about units in error messages, and the plausibility of the
// modulus against the body's size (units.hpp).

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "case/format/units.hpp"
#include "case/result/result_warnings.hpp"

namespace fosls {

namespace {

std::vector<std::string> names(const std::vector<UnitName>& units) {
  std::vector<std::string> out;
  for (const auto& u : units) out.push_back(u.name);
  return out;
}

double si(const std::vector<UnitName>& units, const std::string& name) {
  for (const auto& u : units)
    if (name == u.name) return u.si;
  return 0.0;
}

std::string num(double v) { return sentence_number(v, 3); }

/// Words that follow a number when someone writes a quantity: units of length, stress, force.
bool is_unit_word(std::string word) {
  for (const char* w : {"m",   "cm",  "mm",    "um",     "µm",   "nm",    "in",  "ft",  "Pa",
                        "kPa", "MPa", "GPa",   "psi",    "ksi",  "N",     "kN",  "MN",  "N/mm",
                        "N/m", "bar", "N/mm2", "N/mm^2", "N/m2", "N/m^2", "lbf", "kip", "mm2"})
    if (word == w) return true;
  return false;
}

}  // namespace

const std::vector<UnitName>& length_units() {
  static const std::vector<UnitName> units = {{"m", 1.0},   {"cm", 1e-2},   {"mm", 1e-3},
                                              {"um", 1e-6}, {"in", 0.0254}, {"ft", 0.3048}};
  return units;
}

const std::vector<UnitName>& stress_units() {
  static const std::vector<UnitName> units = {{"Pa", 1.0},          {"kPa", 1e3},
                                              {"MPa", 1e6},         {"GPa", 1e9},
                                              {"psi", 6894.757293}, {"ksi", 6894757.293}};
  return units;
}

ObjectRulePtr units_rule() {
  auto r = std::make_shared<ObjectRule>();
  r->title = "the units";
  r->anchor = "units";
  r->fields = {
      required_field("length", choice_value(names(length_units())),
                     "the unit of every length of the case: coordinates, sizes, displacements, "
                     "gaps"),
      required_field("stress", choice_value(names(stress_units())),
                     "the unit of every stress of the case: mu, lambda, E, tractions, pressures "
                     "(body forces are then in stress per length)"),
  };
  return r;
}

UnitsSpec read_units_section(const nlohmann::json& j) {
  return {j["length"].get<std::string>(), j["stress"].get<std::string>()};
}

std::string force_per_thickness_unit(const UnitsSpec& units) {
  if (!units.declared()) return "";
  const double l = si(length_units(), units.length), s = si(stress_units(), units.stress);
  const double force = s * l * l;  // newtons
  static const UnitName forces[] = {{"N", 1.0},         {"kN", 1e3},       {"MN", 1e6},
                                    {"mN", 1e-3},       {"µN", 1e-6},      {"GN", 1e9},
                                    {"lbf", 4.4482216}, {"kip", 4448.2216}};
  for (const auto& f : forces)
    if (std::abs(force / f.si - 1.0) < 1e-6) return std::string(f.name) + "/" + units.length;
  return units.stress + "·" + units.length;
}

nlohmann::json units_json(const UnitsSpec& units) {
  using nlohmann::json;
  if (!units.declared())
    return {{"declared", false},
            {"length", nullptr},
            {"stress", nullptr},
            {"force_per_thickness", nullptr}};
  return {{"declared", true},
          {"length", units.length},
          {"stress", units.stress},
          {"force_per_thickness", force_per_thickness_unit(units)}};
}

std::string unit_hint(const nlohmann::json& value) {
  if (!value.is_string()) return "";
  const std::string& s = value.get_ref<const std::string&>();
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  if (end == s.c_str()) return "";
  std::string word(end);
  while (!word.empty() && std::isspace(static_cast<unsigned char>(word.front()))) word.erase(0, 1);
  while (!word.empty() && std::isspace(static_cast<unsigned char>(word.back()))) word.pop_back();
  if (!is_unit_word(word)) return "";
  return ". fosls-contact is unit-agnostic: give plain numbers, all in one consistent set of "
         "units (lengths in mm with stresses in MPa, forces per unit thickness then in N/mm; "
         "or m with Pa and N/m), and name them in \"units\": {\"length\": \"mm\", \"stress\": "
         "\"MPa\"} (docs/case-format.md, \"Units\")";
}

double youngs_modulus(double mu, double lambda) {
  if (!std::isfinite(lambda)) return 3.0 * mu;
  return mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu);
}

std::string implausible_units(const UnitsSpec& units, double E, double extent) {
  if (units.declared()) {
    const double pa = E * si(stress_units(), units.stress);
    if (pa > 2e12)
      return "Young's modulus E = " + num(E) + " " + units.stress + " is " + num(pa) +
             " Pa, stiffer than any solid (diamond: about 1.2e12 Pa): is it given in another "
             "unit than units.stress (Pa instead of " +
             units.stress +
             ")? fosls-contact does "
             "not convert units: every stress of the case must be in " +
             units.stress;
    if (pa < 100.0)
      return "Young's modulus E = " + num(E) + " " + units.stress + " is " + num(pa) +
             " Pa, softer than any solid (a soft gel: about 1e3 Pa): is it given in another "
             "unit than units.stress? fosls-contact does not convert units: every stress of "
             "the case must be in " +
             units.stress;
    return "";
  }
  if (E < 1e8 || extent <= 5.0) return "";
  return "Young's modulus E = " + num(E) +
         " can only be in Pa or kPa (in MPa it would exceed "
         "any solid's), whose consistent unit of length is the metre, but the body is " +
         num(extent) + " length units across (" + num(extent) +
         " m?). If the geometry is in "
         "mm, give the stresses in MPa (E = " +
         num(E / 1e6) +
         " if E is in Pa): fosls-contact is "
         "unit-agnostic and needs one consistent set of units (mm, MPa, N/mm or m, Pa, N/m); "
         "with mm and Pa the forces come out in µN/mm. If the numbers are right, declare "
         "them in \"units\" to say so";
}

}  // namespace fosls
