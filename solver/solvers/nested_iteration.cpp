#include "solvers/nested_iteration.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace fosls {

BoxQp coarser_problem(const BoxQp& fine, const Level& level, CoarseProjection projection) {
  const SparseMatrix& p = level.prolongation;
  BoxQp c;  // c.A is the chain's matrix, lent to the problem while it is solved
  c.b = p.transpose() * fine.b;
  const int n = static_cast<int>(p.cols());
  c.lower = Vector::Constant(n, -kNoBound);
  c.upper = Vector::Constant(n, kNoBound);
  Vector defect(fine.size());
  for (int i = 0; i < fine.size(); ++i)
    defect[i] = is_bounded_above(fine.upper[i]) ? fine.upper[i] : kNoBound;
  project_defect(level, projection, defect, c.upper);
  // A frictional DOF held at 0 (every S_t at Coulomb's start, s̄ = 0) holds at 0 the coarse DOF
  // that carries most of it (a fine S_t is half its coarse edge's S_t), not the whole row as in
  // the cycle (row_obstacle.hpp): on a curved boundary the row of a fine S_t also reaches the
  // coarse S_n a little, and would hold that at 0 too. Other bounds (Tresca's) are not passed
  // down, as before; the start is clipped to the fine bounds afterwards.
  if (!fine.row_obstacles.empty()) {
    std::vector<int> main_column(fine.size(), -1);
    std::vector<double> main_weight(fine.size(), 0.0);
    for (int col = 0; col < n; ++col)
      for (SparseMatrix::InnerIterator it(p, col); it; ++it)
        if (std::abs(it.value()) > std::abs(main_weight[it.row()]))
          main_weight[it.row()] = it.value(), main_column[it.row()] = col;
    for (int i : fine.row_obstacles)
      if (main_column[i] >= 0 && fine.lower[i] == 0.0 && fine.upper[i] == 0.0)
        c.lower[main_column[i]] = c.upper[main_column[i]] = 0.0;
  }
  return c;
}

namespace {

/// Lends matrices to the nested solves by swapping them in, and takes them back however the
/// solve ends: each coarse problem and sub-chain would otherwise hold a copy of the chain's
/// matrices (at level 7 of the square the largest allocation of the nested iteration).
class LentMatrices {
 public:
  void lend(SparseMatrix& owner, SparseMatrix& borrower) {
    owner.swap(borrower);
    loans_.emplace_back(&owner, &borrower);
  }
  ~LentMatrices() {
    for (auto& [owner, borrower] : loans_) owner->swap(*borrower);
  }

 private:
  std::vector<std::pair<SparseMatrix*, SparseMatrix*>> loans_;
};

/// The coarse problems of levels 0 … top−1, finest first formed.
std::vector<BoxQp> coarser_problems(const BoxQp& qp, const LevelHierarchy& h,
                                    CoarseProjection projection) {
  const int top = h.num_levels() - 1;
  std::vector<BoxQp> problems(top);
  for (int j = top; j >= 1; --j)
    problems[j - 1] = coarser_problem(j == top ? qp : problems[j], h.levels[j], projection);
  return problems;
}

/// The options of the coarse solves: to the nested tolerance by the KKT test alone.
SolverOptions coarse_solve_options(const SolverOptions& options) {
  SolverOptions inner = options;
  inner.nested = false;
  inner.stopping = StoppingRule::kKktResidual;
  inner.tolerance = options.nested_tolerance;
  inner.max_iterations = options.nested_max_iterations;
  return inner;
}

}  // namespace

bool nested_initial_guess(const BoxQp& qp, const LevelHierarchy& h, const SolverOptions& options,
                          GalerkinChain& chain, Vector& x, SolverReport& report,
                          const std::function<bool()>& out_of_time) {
  const int top = h.num_levels() - 1;
  if (top < 1) return false;
  for (int i = 0; i < qp.size(); ++i)
    if (qp.lower[i] > 0 || qp.upper[i] < 0) return false;
  std::vector<BoxQp> problems = coarser_problems(qp, h, options.multilevel.projection);
  SolverOptions inner = coarse_solve_options(options);
  SolverObserver coarse;
  coarse.out_of_time = out_of_time;
  Vector xc;
  for (int j = 0; j < top; ++j) {
    LevelHierarchy sub;
    sub.levels.assign(h.levels.begin(), h.levels.begin() + j + 1);
    auto sub_chain = std::make_shared<GalerkinChain>();
    sub_chain->matrices.resize(j);
    LentMatrices lent;
    lent.lend(chain.matrices[j], problems[j].A);
    for (int k = 0; k < j; ++k) lent.lend(chain.matrices[k], sub_chain->matrices[k]);
    if (j > 0) {
      xc = h.levels[j].prolongation * xc;
      problems[j].clip(xc);
    }
    // The coarsest level is solved by pdas on CHOLMOD: a handful of factorisations, where the
    // cycle's exact coarse solver met the bounds one at a time from x = 0 (docs/performance.md,
    // "Nested iteration"). The initial guess needs no monotone path: it is clipped to the bounds.
    inner.method = j == 0 ? SolverMethod::kPdas : options.method;
    const SolverReport r = solve_with_chain(problems[j], sub, inner, coarse, xc, sub_chain);
    report.nested_iterations.push_back(r.iterations);
  }
  x = h.levels[top].prolongation * xc;
  qp.clip(x);
  return true;
}

}  // namespace fosls
