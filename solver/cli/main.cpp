// fosls-contact: the command line program of the FOSLS contact solver.
//
// Sample runs:
//   fosls-contact example                       lists the shipped cases
//   fosls-contact example hertz > hertz.json    prints one
//   fosls-contact solve hertz.json --out result.json --vtu solution.vtu
//   fosls-contact example hertz | fosls-contact solve - --quiet
//   fosls-contact bench hertz --levels 2..5 --methods mmg,tnnmg,pdas
//   fosls-contact schema case                   the JSON Schema of the case format
//   fosls-contact estimate hertz.json          memory the solve will need
//
// Exit codes: 0 converged, 1 unexpected failure, 2 bad command line or invalid case,
// 3 solved but not converged (the result is still written).

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "cli/bench_command.hpp"
#include "cli/estimate_command.hpp"
#include "cli/example_command.hpp"
#include "cli/exit_codes.hpp"
#include "cli/schema_command.hpp"
#include "cli/solve_command.hpp"
#include "process/malloc_arenas.hpp"
#include "process/solver_environment.hpp"

int main(int argc, char** argv) {
  using namespace fosls;
  // Sleeping OpenMP waiters and huge pages for malloc's large blocks (solver_environment.hpp).
  restart_with_solver_environment(argv);
  use_one_malloc_arena();
  keep_freed_memory();
  try {
    CLI::App app{
        "FOSLS solver for elastic contact with a rigid obstacle, 2D and 3D, with or without "
        "friction",
        "fosls-contact"};
    app.require_subcommand(1);
    int exit_code = kExitOk;
    add_solve_command(app, exit_code);
    add_example_command(app, exit_code);
    add_bench_command(app, exit_code);
    add_schema_command(app, exit_code);
    add_estimate_command(app, exit_code);
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      return app.exit(e) == 0 ? kExitOk : kExitBadInput;
    }
    return exit_code;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return kExitInternal;
  }
}
