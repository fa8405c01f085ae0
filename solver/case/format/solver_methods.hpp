#pragma once
// The solver methods, smoothers and coarse obstacles a case can name: one table each (the
// smoothers' is solvers/smoother_table.hpp, with their constructors), used by
// the case reader (allowed values, defaults), the runner (what to build), the CLI (help,
// bench), the result (names) and the docs (generated rows of docs/case-format.md).

#include <span>
#include <string>
#include <vector>

#include "solvers/solve_loop.hpp"

namespace fosls {

/// The solver options of the case that a method may use.
enum class SolverOption { kSmoother, kPreSmoothing, kPostSmoothing, kCoarseObstacle, kCycle };

struct MethodInfo {
  SolverMethod method;
  const char* name;     ///< the case's `solver.method`
  const char* summary;  ///< one line for docs and help
  /// A smoothing step per level is needed: pre_smoothing + post_smoothing ≥ 1.
  bool needs_smoothing;
  std::vector<SolverOption> options;  ///< the options it uses, in the order of the case
};

struct CoarseObstacleInfo {
  CoarseProjection projection;
  const char* name;
  const char* summary;
};

struct CycleInfo {
  CycleShape shape;
  const char* name;
  const char* summary;
};

std::span<const MethodInfo> solver_methods();
std::span<const SmootherInfo> smoothers();
std::span<const CoarseObstacleInfo> coarse_obstacles();
std::span<const CycleInfo> cycles();

const MethodInfo& method_info(SolverMethod method);
const CoarseObstacleInfo& coarse_obstacle_info(CoarseProjection projection);
const CycleInfo& cycle_info(CycleShape shape);

/// nullptr when no entry has that name.
const MethodInfo* find_method(const std::string& name);
const SmootherInfo* find_smoother(const std::string& name);
const CoarseObstacleInfo* find_coarse_obstacle(const std::string& name);
const CycleInfo* find_cycle(const std::string& name);

std::vector<std::string> method_names();
std::vector<std::string> smoother_names();
std::vector<std::string> coarse_obstacle_names();
std::vector<std::string> cycle_names();

/// The case field of an option ("smoother", "pre_smoothing", ...).
const char* option_field(SolverOption option);
/// Whether `method` uses `option`.
bool uses_option(const MethodInfo& method, SolverOption option);

}  // namespace fosls
