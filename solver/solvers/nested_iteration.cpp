#include "solvers/nested_iteration.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "solvers/coarse_friction.hpp"

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
    const std::vector<int> main_column = main_columns(p);
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

/// The coarse problems with Coulomb friction of their own (coarse_friction.hpp) in `friction`,
/// whose row obstacles hold each coarser level's S_t at 0 from the start like the fine one's;
/// `friction` is left empty, and the problems are coarser_problems', where a level's edges do
/// not pair up.
std::vector<BoxQp> coarser_coulomb_problems(const BoxQp& qp, const NestedCoulomb& coulomb,
                                            const LevelHierarchy& h, CoarseProjection projection,
                                            std::vector<CoarseFriction>& friction) {
  const int top = h.num_levels() - 1;
  std::vector<BoxQp> problems(top);
  friction.assign(top, {});
  for (int j = top; j >= 1; --j) {
    const bool finest = j == top;
    std::optional<CoarseFriction> coarse =
        coarser_friction(finest ? *coulomb.layout : friction[j].layout,
                         finest ? *coulomb.kinks : friction[j].kinks, h.levels[j].prolongation);
    if (!coarse) {
      friction.clear();
      return coarser_problems(qp, h, projection);
    }
    problems[j - 1] = coarser_problem(finest ? qp : problems[j], h.levels[j], projection);
    friction[j - 1] = std::move(*coarse);
    problems[j - 1].row_obstacles = friction[j - 1].row_obstacles;
  }
  return problems;
}

/// x within the bounds of qp, except that the S_t of `layout` (if any) keep their values within
/// ±𝔣 max(0, −S_n) of x's own S_n instead of Coulomb's start bounds of 0: the start the coarser
/// level's Coulomb solve gives.
void clip_start(const BoxQp& qp, const FrictionLayout* layout, Vector& x) {
  if (!layout) return qp.clip(x);
  std::vector<double> st(layout->edges.size());
  for (std::size_t e = 0; e < st.size(); ++e) st[e] = x[layout->edges[e].st];
  qp.clip(x);
  for (std::size_t e = 0; e < st.size(); ++e) {
    const FrictionEdge& f = layout->edges[e];
    const double s = slip_bound(f, x);
    x[f.st] = std::clamp(st[e], -s, s);
  }
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
                          const std::function<bool()>& out_of_time, const NestedCoulomb& coulomb) {
  const int top = h.num_levels() - 1;
  if (top < 1) return false;
  for (int i = 0; i < qp.size(); ++i)
    if (qp.lower[i] > 0 || qp.upper[i] < 0) return false;
  std::vector<CoarseFriction> friction;
  std::vector<BoxQp> problems =
      coulomb.layout
          ? coarser_coulomb_problems(qp, coulomb, h, options.multilevel.projection, friction)
          : coarser_problems(qp, h, options.multilevel.projection);
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
    const FrictionLayout* layout = friction.empty() ? nullptr : &friction[j].layout;
    if (j > 0) {
      xc = h.levels[j].prolongation * xc;
      clip_start(problems[j], layout, xc);
    }
    // The coarsest level is solved by pdas on CHOLMOD: a handful of factorisations, where the
    // cycle's exact coarse solver met the bounds one at a time from x = 0 (docs/performance.md,
    // "Nested iteration"). The initial guess needs no monotone path: it is clipped to the bounds.
    inner.method = j == 0 ? SolverMethod::kPdas : options.method;
    const SolverReport r =
        layout ? solve_kinked_qp(problems[j], KinkedProblem{&friction[j].kinks, layout, {}}, sub,
                                 inner, coarse, xc, sub_chain)
               : solve_with_chain(problems[j], sub, inner, coarse, xc, sub_chain);
    report.nested_iterations.push_back(r.iterations);
  }
  x = h.levels[top].prolongation * xc;
  clip_start(qp, friction.empty() ? nullptr : coulomb.layout, x);
  return true;
}

}  // namespace fosls
