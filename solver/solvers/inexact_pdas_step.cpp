#include "solvers/inexact_pdas_step.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/fosls_assert.hpp"

namespace fosls {

InexactPdasStep::InexactPdasStep(const BoxQp& qp, const LevelHierarchy& hierarchy,
                                 const MultilevelOptions& options,
                                 std::shared_ptr<GalerkinChain> chain, int cycles)
    : qp_(qp), test_(qp), cycle_(qp, hierarchy, options, std::move(chain)), cycles_(cycles) {
  FOSLS_ASSERT(cycles >= 1, "an inexact Newton step needs at least one cycle");
}

InexactPdasStep::~InexactPdasStep() {
  if (std::getenv("FOSLS_INEXACT_FORCING")) std::fprintf(stderr, "inexact pdas: %d cycles\n", cycles_run_);
}

void InexactPdasStep::iterate(Vector& x, Vector& r) {
  const int n = qp_.size();
  const std::vector<char> active = test_.next(x, r);
  const Vector psi = test_.held_values(active);
  // The Newton step's linear problem: the active DOFs at ψ (r recomputed if that moved them),
  // the others free. The linear cycle is mmg's with those DOFs pinned (correction 0 there,
  // truncated from the coarse levels) and no bounds elsewhere, so the cycle needs no obstacle
  // projections and the QP's bounds are left as they are.
  std::vector<char> held(n, 0);
  bool moved = false;
  for (int i = 0; i < n; ++i)
    if (active[i]) {
      held[i] = 1;
      moved = moved || x[i] != psi[i];
      x[i] = psi[i];
    }
  if (moved) {
    symmetric_multiply(qp_.A, x, r);
    r = qp_.b - r;
  }
  Vector c = Vector::Zero(n);
  // TEMPORARY (experiment): FOSLS_INEXACT_FORCING=eta: cycles (up to cycles_) until the free
  // DOFs' residual has fallen by eta, the inexact Newton method's forcing term.
  static const double forcing =
      std::getenv("FOSLS_INEXACT_FORCING") ? std::atof(std::getenv("FOSLS_INEXACT_FORCING")) : 0.0;
  auto free_norm = [&] {
    double s = 0.0;
    for (int i = 0; i < n; ++i)
      if (!held[i]) s += r[i] * r[i];
    return std::sqrt(s);
  };
  const double start = free_norm();
  for (int k = 0; k < cycles_; ++k) {
    cycle_.linear_cycle(held, c, r);
    ++cycles_run_;
    if (forcing > 0.0 && free_norm() <= forcing * start) break;
  }
  x += c;
}

}  // namespace fosls
