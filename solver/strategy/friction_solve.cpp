#include "strategy/friction_solve.hpp"

namespace fosls {

SolverReport solve_frictional(Discretization<2>& disc, const LevelHierarchy& hierarchy,
                              const SolverOptions& options, const SolverObserver& observer,
                              Vector& x) {
  AssembledProblem& problem = disc.mutable_problem();
  KinkedProblem kinked;
  kinked.kinks = &problem.kinks;
  if (problem.friction.coulomb()) kinked.coulomb = &problem.friction;
  return solve_kinked_qp(problem.qp, kinked, hierarchy, options, observer, x);
}

}  // namespace fosls
