#include "case/run/level_loop_options.hpp"

namespace fosls {

LevelLoopOptions level_loop_options(const CaseSpec& spec) {
  LevelLoopOptions loop;
  loop.solver = spec.solver;
  loop.order = spec.mesh.order;
  if (const auto& a = spec.adaptivity)
    loop.adaptivity = AdaptiveLoopOptions{a->steps, a->max_dofs, a->theta, a->target};
  if (const auto& a = spec.accuracy)
    loop.accuracy = AccuracyLoopOptions{a->force, a->max_dofs, a->adaptive, a->theta};
  return loop;
}

}  // namespace fosls
