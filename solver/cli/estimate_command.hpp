#pragma once
// `fosls-contact estimate CASE`: checks a case without solving it and prints the unknowns and
// the memory its solve will need (case/admission/resource_estimate.hpp), for each method.

#include <CLI/CLI.hpp>

namespace fosls {

/// Adds the `estimate` subcommand to `app`; when it runs, its exit code is stored in
/// `exit_code` (0, or 2 for an invalid case with every problem listed).
void add_estimate_command(CLI::App& app, int& exit_code);

}  // namespace fosls
