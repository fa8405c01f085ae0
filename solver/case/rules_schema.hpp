#pragma once
// JSON Schema (draft 2020-12) of a document described by rules (case_rules.hpp): the case
// and the result are published this way, generated from the same rules the reader checks.

#include <nlohmann/json.hpp>
#include <string>

#include "case/case_rules.hpp"

namespace fosls {

/// The schema of `root`; nested objects go to `$defs` under their anchors. Semantic rules
/// (hooks) are described in `$comment`s: a schema validator cannot check them.
nlohmann::json rules_json_schema(const ObjectRule& root, const std::string& id,
                                 const std::string& description);

}  // namespace fosls
