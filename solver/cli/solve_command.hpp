#pragma once
// `fosls-contact solve CASE.json [--out RESULT.json] [--vtu SOLUTION.vtu] [--msh MESH.msh]
// [--quiet]`.

#include <CLI/CLI.hpp>

namespace fosls {

/// Adds the `solve` subcommand to `app`; when it runs, its exit code is stored in `exit_code`
/// (see cli/exit_codes.hpp).
void add_solve_command(CLI::App& app, int& exit_code);

}  // namespace fosls
