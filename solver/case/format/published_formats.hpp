#pragma once
// The published forms of the case and result formats: their JSON Schemas and the generated
// tables of docs/case-format.md and docs/result-format.md. They come from case_rule(), the
// rules the reader checks, and result_rule(), the rules every result is tested against.

#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace fosls {

/// JSON Schema (draft 2020-12) of a case of either dimension, with the default limits: the 2D
/// and 3D rules joined by `if dimension is 3` (rules_schema.hpp). Rules that a schema cannot
/// express (an expression parses, a geometry is one closed loop, ...) are `$comment`s; the
/// reader checks them.
nlohmann::json case_json_schema();
/// The JSON Schema of a 3D case's result (docs/result-format.md, "3D results"):
/// `fosls-contact schema result3d`.
nlohmann::json result3d_json_schema();

/// The generated blocks of docs/case-format.md by name: "fields:<section>" for the field
/// table of each section (case, mesh, builtin, geometry, curve, material, condition, obstacle,
/// weights, solver), "methods" (the solver methods and the options they use) and "limits".
std::map<std::string, std::string> case_format_blocks();

/// JSON Schema (draft 2020-12) of the result JSON of a solve.
nlohmann::json result_json_schema();

/// The generated blocks of docs/result-format.md by name: "fields:<object>" for each object of
/// the result (result, iteration, solver_statistics, contact, zone, functional, ...) and "vtu"
/// (the arrays of the VTU file).
std::map<std::string, std::string> result_format_blocks();

}  // namespace fosls
