#pragma once
// `fosls-contact bench CASE --levels A..B --methods mmg,tnnmg,pdas,pgs`: the same case over
// several levels and methods, one table row per run (level, DOFs, method, smoother, coarse
// obstacle, iterations, asymptotic rate, setup and solve time, peak memory) with the physical
// answer of each (|F|, peak pressure, contact width, estimator J^1/2): a mesh-convergence
// study in one command.

#include <CLI/CLI.hpp>

namespace fosls {

/// Adds the `bench` subcommand to `app`; its exit code is stored in `exit_code`.
void add_bench_command(CLI::App& app, int& exit_code);

}  // namespace fosls
