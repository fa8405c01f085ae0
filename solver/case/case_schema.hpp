#pragma once
// The published forms of the case format's rules: its JSON Schema and the generated tables of
// docs/case-format.md. Both come from case_rule(), the rules the reader checks.

#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace fosls {

/// JSON Schema (draft 2020-12) of a case, with the default limits. Rules that a schema cannot
/// express (an expression parses, a geometry is one closed loop, ...) are `$comment`s; the
/// reader checks them.
nlohmann::json case_json_schema();

/// The generated blocks of docs/case-format.md by name: "fields:<section>" for the field
/// table of each section (case, mesh, builtin, geometry, curve, material, condition, obstacle,
/// weights, solver), "methods" (the solver methods and the options they use) and "limits".
std::map<std::string, std::string> case_format_blocks();

}  // namespace fosls
