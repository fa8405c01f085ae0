#include "strategy/order2_solve.hpp"

#include <chrono>

#include "assembly/p2_rt1_assembler.hpp"
#include "assembly/p2_rt1_level.hpp"
#include "core/peak_memory.hpp"

namespace fosls {

Order2Solution solve_order2(const Discretization<2>& lowest, const P2Rt1Space& space,
                            const SolverOptions& options, const SolverObserver& observer) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  Order2Solution out;
  const P2Rt1Assembler assembler(space, lowest.data());
  const AssembledProblem problem = assembler.assemble_system();
  out.assembly_mib = peak_rss_mib();
  LevelHierarchy hierarchy;
  if (needs_level_hierarchy(options.method)) {
    hierarchy = lowest.build_level_hierarchy();
    hierarchy.levels.push_back(order2_level(lowest.finest_space(), space));
  }
  out.hierarchy_mib = peak_rss_mib();
  out.assembly_s = std::chrono::duration<double>(Clock::now() - t0).count();
  out.x = Vector::Zero(problem.qp.size());
  out.report = solve_box_qp(problem.qp, hierarchy, options, observer, out.x);
  const Vector full = assembler.full_vector(problem, out.x);
  out.parts = assembler.functional(full);
  out.interpolant = lowest_order_interpolant(lowest.finest_space(), space, full);
  return out;
}

}  // namespace fosls
