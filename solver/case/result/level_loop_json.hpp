#pragma once
// The result's `adaptivity` and `accuracy` objects (docs/result-format.md) from the records of
// the loop of solves over levels (strategy/level_loop.hpp), with the sentences that say why the
// loop stopped.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "case/format/case_spec.hpp"
#include "strategy/level_loop.hpp"

namespace fosls {

/// The `adaptivity` object: its steps count `triangles` in 2D and `tetrahedra` in 3D, and it
/// ends with the estimator's reduction, the last step's change of the force and a stop message
/// (adaptivity_json.cpp).
nlohmann::json adaptivity_json(const std::vector<AdaptiveStepRecord>& steps,
                               const std::string& stop_reason, const AdaptivitySpec& spec, int dim);

/// The `accuracy` object: the levels' forces and estimates (strategy/force_accuracy.hpp) and
/// why the loop stopped (accuracy_json.cpp).
nlohmann::json accuracy_json(const std::vector<AdaptiveStepRecord>& steps,
                             const std::string& stop_reason, const AccuracySpec& spec);

template <int dim>
nlohmann::json adaptivity_json(const LevelSolution<dim>& solution, const AdaptivitySpec& spec) {
  return adaptivity_json(solution.steps, solution.stop_reason, spec, dim);
}

template <int dim>
nlohmann::json accuracy_json(const LevelSolution<dim>& solution, const AccuracySpec& spec) {
  return accuracy_json(solution.steps, solution.stop_reason, spec);
}

}  // namespace fosls
