#pragma once
// JSON Schema (draft 2020-12) of a document described by rules (case_rules.hpp): the case
// and the result are published this way, generated from the same rules the reader checks.

#include <nlohmann/json.hpp>
#include <string>

#include "case/format/case_rules.hpp"

namespace fosls {

/// The schema of `root`; nested objects go to `$defs` under their anchors. Semantic rules
/// (hooks) are described in `$comment`s: a schema validator cannot check them.
nlohmann::json rules_json_schema(const ObjectRule& root, const std::string& id,
                                 const std::string& description);

/// One schema for a document of either dimension from its 2D and 3D rules: a document whose
/// `dimension` is 3 is checked against the 3D rules, any other against the 2D ones. Objects that
/// are the same in both are defined once; the others as `<anchor>_2d` and `<anchor>_3d`.
nlohmann::json rules_json_schema_by_dimension(const ObjectRule& root2, const ObjectRule& root3,
                                              const std::string& id,
                                              const std::string& description);

}  // namespace fosls
