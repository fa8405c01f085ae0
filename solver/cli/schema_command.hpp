#pragma once
// `fosls-contact schema [case|result]`: prints the JSON Schema of the case format (generated
// from the rules the reader checks) or of the result JSON, for editors, scripts and validators.

#include <CLI/CLI.hpp>

namespace fosls {

/// Adds the `schema` subcommand to `app`; its exit code is stored in `exit_code`.
void add_schema_command(CLI::App& app, int& exit_code);

}  // namespace fosls
