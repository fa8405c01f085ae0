#pragma once
// A contact case with an exact linear solution, for tests that need a known uniform stress.
#include <nlohmann/json.hpp>

namespace fosls::testing {

/// The unit square on a frictionless plane (contact at y = 0), a roller on the left (u_x = 0,
/// a symmetry plane), its top pressed down by δ by a roller that leaves u_x free, the right
/// side free. The exact solution is linear, so P1 × RT0 reproduces it: u_y = −δ y,
/// u_x = λδ/(λ+2μ) x, and a uniform pressure p = 4μ(λ+μ)/(λ+2μ) δ (4μδ for λ = ∞). Clamping
/// the top or the left instead would give another answer, so the rollers are tested.
inline nlohmann::json uniaxial_case(const nlohmann::json& lambda = 1.0) {
  return {{"name", "uniaxial"},
          {"mesh", {{"builtin", "square"}, {"size", 0.25}, {"refinements", 2}}},
          {"material", {{"mu", 1}, {"lambda", lambda}}},
          {"boundary",
           {{"top", {{"type", "dirichlet"}, {"displacement", {nullptr, -0.01}}}},
            {"left", {{"type", "dirichlet"}, {"displacement", {0, nullptr}}}},
            {"right", {{"type", "neumann"}, {"traction", {0, 0}}}},
            {"bottom",
             {{"type", "contact"},
              {"obstacle", {{"type", "plane"}, {"point", {0, 0}}, {"normal", {0, 1}}}}}}}},
          {"solver", {{"method", "pdas"}, {"tolerance", 1e-12}}}};
}

}  // namespace fosls::testing
