#pragma once
// `fosls-contact example [NAME]`: prints a shipped case, or lists them without NAME.

#include <CLI/CLI.hpp>

namespace fosls {

/// Adds the `example` subcommand to `app`; when it runs, its exit code is stored in
/// `exit_code`.
void add_example_command(CLI::App& app, int& exit_code);

}  // namespace fosls
