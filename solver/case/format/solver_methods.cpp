#include "case/format/solver_methods.hpp"

#include <algorithm>
#include <stdexcept>

namespace fosls {

namespace {

using enum SolverOption;

const std::vector<MethodInfo>& method_table() {
  static const std::vector<MethodInfo> table = {
      {SolverMethod::kMmg,
       "mmg",
       "monotone multilevel method: smoothing, truncated coarse corrections within coarse "
       "obstacles, W-cycle, nested iteration",
       true,
       {kSmoother, kPreSmoothing, kPostSmoothing, kCoarseObstacle, kCycle}},
      {SolverMethod::kTnnmg,
       "tnnmg",
       "truncated non-smooth Newton multigrid: smoothing, a linear cycle on the inactive set, "
       "projection and line search",
       false,
       {kSmoother, kPreSmoothing, kPostSmoothing, kCoarseObstacle, kCycle}},
      {SolverMethod::kPdas,
       "pdas",
       "primal-dual active set method with a direct solver (CHOLMOD) on the finest level",
       false,
       {}},
      {SolverMethod::kPgs,
       "pgs",
       "projected Gauss-Seidel on the finest level only",
       false,
       {kSmoother}},
  };
  return table;
}

std::span<const SmootherInfo> smoother_table() { return kSmootherTable; }

const std::vector<CoarseObstacleInfo>& coarse_obstacle_table() {
  static const std::vector<CoarseObstacleInfo> table = {
      {CoarseProjection::kA, "a", "least restrictive"},
      {CoarseProjection::kB, "b", "minimum of the end points and the midpoint"},
      {CoarseProjection::kC, "c", "minimum over the edge"},
  };
  return table;
}

const std::vector<CycleInfo>& cycle_table() {
  static const std::vector<CycleInfo> table = {
      {CycleShape::kW, "W", "each level visits the next coarser twice (the default)"},
      {CycleShape::kV, "V", "each level visits the next coarser once"},
      {CycleShape::kF, "F", "an F-cycle then a V-cycle on the next coarser level"},
  };
  return table;
}

template <class Table, class Key, class Member>
const auto& entry_of(const Table& table, Key key, Member member) {
  for (const auto& e : table)
    if (e.*member == key) return e;
  throw std::logic_error(
      "an enumerator is missing from its table in case/format/solver_methods.cpp");
}

template <class Table>
const typename Table::value_type* entry_named(const Table& table, const std::string& name) {
  for (const auto& e : table)
    if (name == e.name) return &e;
  return nullptr;
}

template <class Table>
std::vector<std::string> names_of(const Table& table) {
  std::vector<std::string> names;
  for (const auto& e : table) names.emplace_back(e.name);
  return names;
}

}  // namespace

std::span<const MethodInfo> solver_methods() { return method_table(); }
std::span<const SmootherInfo> smoothers() { return smoother_table(); }
std::span<const CoarseObstacleInfo> coarse_obstacles() { return coarse_obstacle_table(); }
std::span<const CycleInfo> cycles() { return cycle_table(); }

const MethodInfo& method_info(SolverMethod method) {
  return entry_of(method_table(), method, &MethodInfo::method);
}
const CoarseObstacleInfo& coarse_obstacle_info(CoarseProjection projection) {
  return entry_of(coarse_obstacle_table(), projection, &CoarseObstacleInfo::projection);
}
const CycleInfo& cycle_info(CycleShape shape) {
  return entry_of(cycle_table(), shape, &CycleInfo::shape);
}

const MethodInfo* find_method(const std::string& name) { return entry_named(method_table(), name); }
const SmootherInfo* find_smoother(const std::string& name) {
  return entry_named(smoother_table(), name);
}
const CoarseObstacleInfo* find_coarse_obstacle(const std::string& name) {
  return entry_named(coarse_obstacle_table(), name);
}
const CycleInfo* find_cycle(const std::string& name) { return entry_named(cycle_table(), name); }

std::vector<std::string> method_names() { return names_of(method_table()); }
std::vector<std::string> smoother_names() { return names_of(smoother_table()); }
std::vector<std::string> coarse_obstacle_names() { return names_of(coarse_obstacle_table()); }
std::vector<std::string> cycle_names() { return names_of(cycle_table()); }

const char* option_field(SolverOption option) {
  switch (option) {
    case kSmoother:
      return "smoother";
    case kPreSmoothing:
      return "pre_smoothing";
    case kPostSmoothing:
      return "post_smoothing";
    case kCoarseObstacle:
      return "coarse_obstacle";
    case kCycle:
      return "cycle";
  }
  return "?";
}

bool uses_option(const MethodInfo& method, SolverOption option) {
  return std::find(method.options.begin(), method.options.end(), option) != method.options.end();
}

}  // namespace fosls
