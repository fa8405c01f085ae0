#pragma once
// Markdown tables of rules (case_rules.hpp), for the generated parts of docs/case-format.md
// and docs/result-format.md.

#include <string>

#include "case/format/case_rules.hpp"

namespace fosls {

/// One table of an object's fields (with a row per variant when it has a discriminator),
/// followed by its exclusive field sets and semantic rules in words. An input's table has
/// the columns field, type, default, allowed, meaning; an output's field, type, unit, meaning.
enum class TableKind { kInput, kOutput };
std::string rules_markdown_table(const ObjectRule& rule, TableKind kind = TableKind::kInput);

/// The "type" cell of a value ("number", "[scalar, scalar]", "object: name → object (…)").
std::string value_type_text(const ValueRule& rule);
/// The "allowed" cell of a value ("> 0", "0 to 8", "`a`, `b`").
std::string value_allowed_text(const ValueRule& rule);

}  // namespace fosls
