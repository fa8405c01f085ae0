#pragma once
// A case's sections as the options of the loop of solves over levels (strategy/level_loop.hpp):
// the case layer reads and checks them; the loop only runs them.

#include "case/format/case_spec.hpp"
#include "strategy/level_loop_options.hpp"

namespace fosls {

/// `solver`, `mesh.order`, `adaptivity` and `accuracy` of `spec`.
LevelLoopOptions level_loop_options(const CaseSpec& spec);

}  // namespace fosls
