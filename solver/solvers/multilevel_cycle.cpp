#include "solvers/multilevel_cycle.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>

#include "core/fosls_assert.hpp"
#include "core/indefinite_system.hpp"
#include "solvers/galerkin_product.hpp"
#include "solvers/sparse_sum.hpp"

namespace fosls {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
/// The change δ on the DOFs `local` that minimises the energy (v + δ)ᵀ A (v + δ) of v = column
/// `column` of p with `extra_value` added at `extra_dof`: δ = −A_LL⁻¹ (A v)_L.
Vector energy_minimising_correction(const SparseMatrix& a, const SparseMatrix& p, int column,
                                    const std::vector<int>& local, int extra_dof,
                                    double extra_value, const std::vector<char>* dropped_rows) {
  const int m = static_cast<int>(local.size());
  std::vector<int> position(a.rows(), -1);
  for (int i = 0; i < m; ++i) position[local[i]] = i;
  Vector ap = Vector::Zero(m);
  for (SparseMatrix::InnerIterator pc(p, column); pc; ++pc) {
    if (dropped_rows && (*dropped_rows)[pc.row()]) continue;
    for (SparseMatrix::InnerIterator it(a, static_cast<int>(pc.row())); it; ++it)
      if (const int i = position[it.row()]; i >= 0) ap[i] += it.value() * pc.value();
  }
  for (SparseMatrix::InnerIterator it(a, extra_dof); it; ++it)
    if (const int i = position[it.row()]; i >= 0) ap[i] += it.value() * extra_value;
  Eigen::MatrixXd all(m, m);
  all.setZero();
  for (int b = 0; b < m; ++b)
    for (SparseMatrix::InnerIterator it(a, local[b]); it; ++it)
      if (const int i = position[it.row()]; i >= 0) all(i, b) = it.value();
  Eigen::LDLT<Eigen::MatrixXd> ldlt(all);
  if (ldlt.info() != Eigen::Success) return Vector::Zero(m);
  return -ldlt.solve(ap);
}

}  // namespace

struct MultilevelCycle::LevelState {
  /// The level's matrix (coarse levels only): the chain's untruncated Galerkin matrix, not
  /// copied, while nothing is truncated, else `truncated`.
  SparseMatrix* A = nullptr;
  SparseMatrix truncated;  ///< the truncated Galerkin matrix, when truncating
  std::unique_ptr<PatchSmoother> patch;
  std::unique_ptr<PointSmoother> point;
  std::unique_ptr<StripSmoother> strip;
};

GalerkinChain galerkin_chain(const SparseMatrix& A, const LevelHierarchy& hierarchy, int levels) {
  const int top = hierarchy.num_levels() - 1;
  GalerkinChain c;
  c.matrices.resize(std::max(top, 0));
  for (int j = top; j >= 1 && top - j < levels; --j) {
    SparseMatrix coarse =
        galerkin_product(j == top ? A : c.matrices[j], hierarchy.levels[j].prolongation);
    c.matrices[j - 1].swap(coarse);  // no move in Eigen 3.4: swapped, not copied
  }
  return c;
}

namespace {
constexpr double kRevisitFactor = 2;
}  // namespace

MultilevelCycle::MultilevelCycle(const BoxQp& qp, const LevelHierarchy& hierarchy,
                                 MultilevelOptions options, std::shared_ptr<GalerkinChain> chain)
    : qp_(qp), hierarchy_(hierarchy), options_(options), chain_(std::move(chain)) {
  FOSLS_ASSERT(hierarchy_inconsistency(hierarchy, qp.size()).empty(),
               hierarchy_inconsistency(hierarchy, qp.size()));
  const int nl = hierarchy.num_levels();
  if (!chain_) chain_ = std::make_shared<GalerkinChain>(galerkin_chain(qp.A, hierarchy));
  if (nl >= 2) top_edits_ = std::make_unique<ReversibleEdits>(chain_->matrices[nl - 2]);
  for (int j = 0; j < nl; ++j) levels_.push_back(std::make_unique<LevelState>());
  // A W-cycle's second visit of the coarser levels is affordable only where the unknowns have
  // fallen by a large enough factor since the last level that made one. A factor 2 keeps every
  // uniform level (factor ≈ 4) revisiting, as before, and on bisection levels (factor ≈ 1.1
  // to 1.5 each) revisits where the size has halved: a level of N_k unknowns is then visited
  // at most N/N_k times, so a cycle costs O(N log N) instead of the W-cycle's (γ/1.5)^levels
  // N. Measured on the adaptive Hertz case, 9 steps to 27 242 unknowns on 10 levels:
  // 15.2 s CPU with the W-cycle, 5.5 s with this rule, 4.7 s with a V-cycle on the
  // bisection levels; iterations per step 10–26, 15–26 and 15–26; on the adaptive Signorini
  // square the V-cycle's grow with the steps (13 → 42 over 6 steps), this rule's stay 15–28.
  revisit_.assign(nl, 0);
  long long reference = qp.size();
  for (int j = nl - 1; j >= 2; --j) {
    const long long coarse = hierarchy.levels[j - 1].num_dofs;
    if (kRevisitFactor * coarse < reference) revisit_[j] = 1, reference = coarse;
  }
  // The finest matrix never changes: its smoother is built once, here. The coarse levels are
  // built by the first set_truncation, for the first cycle's truncated set: building them
  // untruncated here as well was one full rebuild per solve that a constrained problem threw
  // away at once (docs/performance.md, adaptivity). A single level has no coarse levels to wait
  // for, only its exact solver.
  make_smoother(nl - 1);
  if (nl == 1) set_truncation(std::vector<char>(qp.size(), 0));
}

MultilevelCycle::~MultilevelCycle() {
  if (top_edits_) top_edits_->restore();
}

const SparseMatrix& MultilevelCycle::matrix(int j) const {
  return j == hierarchy_.num_levels() - 1 ? qp_.A : *levels_[j]->A;
}

SparseMatrix& MultilevelCycle::chain_matrix(int j) {
  SparseMatrix& m = chain_->matrices[j];
  if (m.rows() == 0) {
    const int top = hierarchy_.num_levels() - 1;
    SparseMatrix coarse = galerkin_product(j + 1 == top ? qp_.A : chain_matrix(j + 1),
                                           hierarchy_.levels[j + 1].prolongation);
    m.swap(coarse);
  }
  return m;
}

const TruncatedProlongation& MultilevelCycle::prolongation(int j) const {
  return truncated_prolongations_[j];
}

void MultilevelCycle::set_truncation(const std::vector<char>& truncated) {
  if (built_ && truncated == truncated_) return;
  truncated_ = truncated;
  const int top = hierarchy_.num_levels() - 1;
  level_truncated_.assign(top + 1, {});
  truncated_prolongations_.assign(top + 1, TruncatedProlongation());
  sn_weights_.assign(top + 1, {});
  if (top > 0) {
    level_truncated_[top] = truncated;
    truncate_level(top);
  }
  rebuild_coarse_levels();
  built_ = true;
}

void MultilevelCycle::truncate_level(int j) {
  // Truncated basis: coarse functions lose their component at truncated DOFs of level j, i.e.
  // the rows of P_j of those DOFs are zero. On the finest level these are the active DOFs; on
  // a coarser level, the S_n of coarse contact edges whose children are all truncated (their
  // functions have no normal flux left on the finest level).
  const Level& level = hierarchy_.levels[j];
  const std::vector<char>& truncated = level_truncated_[j];
  const SparseMatrix& a = matrix(j);
  std::vector<char> coarse(hierarchy_.levels[j - 1].num_dofs, 0);
  std::vector<std::array<double, 2>>& weights = sn_weights_[j];
  weights.assign(level.links.size(), {0.0, 0.0});
  for (std::size_t l = 0; l < level.links.size(); ++l) weights[l] = level.links[l].sn_weight;
  const bool any = std::find(truncated.begin(), truncated.end(), 1) != truncated.end();
  std::vector<Eigen::Triplet<double>> corrections;
  if (any) {
    // Zeroing the flux of one half of a coarse contact edge leaves the edge's coarse S_n
    // function with a divergence of order 1/h² in that half's fine triangle: so stiff that the
    // coarse levels cannot represent a normal traction on coarse edges that straddle the end
    // of the contact zone, and the linear phase slows to rates of 0.92–0.96. The function keeps
    // its flux instead: the truncated half's share goes to the free half, and the fine edges
    // between the halves carry it with the least energy, so the divergence stays bounded and
    // the truncated DOF is untouched.
    for (std::size_t l = 0; l < level.links.size(); ++l) {
      const ContactLink& link = level.links[l];
      if (link.coarse_sn < 0 || link.fine_sn[0] < 0) continue;
      if (link.fine_sn[1] < 0) {
        // A contact edge that bisection kept has one child: the coarse S_n is truncated
        // with it.
        if (truncated[link.fine_sn[0]]) coarse[link.coarse_sn] = 1;
        continue;
      }
      const bool t0 = truncated[link.fine_sn[0]], t1 = truncated[link.fine_sn[1]];
      if (t0 && t1) coarse[link.coarse_sn] = 1;
      const int k = t0 ? 0 : 1;
      if (t0 == t1 || link.flux_moves[k].empty()) continue;
      const auto& [free_sn, factor] = link.flux_moves[k].front();
      std::vector<int> path;  // the interior fine σ DOFs between the halves
      for (std::size_t m = 1; m < link.flux_moves[k].size(); ++m)
        path.push_back(link.flux_moves[k][m].first);
      const double moved = link.sn_weight[k] * factor;
      corrections.emplace_back(free_sn, link.coarse_sn, moved);
      weights[l][1 - k] += moved;
      // The truncated rows of the coarse S_n's column are zero, and the path and the free
      // half are not truncated, so column coarse_sn of P stands for that of P̃ here.
      const Vector delta = energy_minimising_correction(a, level.prolongation, link.coarse_sn, path,
                                                        free_sn, moved, &truncated);
      for (std::size_t m = 0; m < path.size(); ++m)
        corrections.emplace_back(path[m], link.coarse_sn, delta[m]);
    }
  }
  // P̃ = P without the truncated rows, plus the flux moves: applied from P on the finest level,
  // elsewhere formed in storage of its exact size.
  SparseMatrix moves(level.prolongation.rows(), level.prolongation.cols());
  moves.setFromTriplets(corrections.begin(), corrections.end());
  moves.makeCompressed();
  if (j == hierarchy_.num_levels() - 1) {
    truncated_prolongations_[j] = TruncatedProlongation::applied(
        level.prolongation, any ? truncated : std::vector<char>{}, std::move(moves));
  } else {
    truncated_prolongations_[j] = TruncatedProlongation::formed(
        sparse_sum(level.prolongation, moves, any ? &truncated : nullptr));
  }
  if (j > 1) level_truncated_[j - 1] = std::move(coarse);
}

namespace {

/// A small set of indices out of [0, n): a bit per index and the sorted members, so that the
/// position of a member costs a binary search and the set n / 8 bytes (two int maps of the fine
/// size were a fifth of the transient at a solve's peak).
class SparseIndexSet {
 public:
  explicit SparseIndexSet(int n) : in_(n, false) {}
  void insert(int i) {
    if (!in_[i]) in_[i] = true, members_.push_back(i);
  }
  /// Call after the last insert: positions follow the sorted order.
  void finish() { std::sort(members_.begin(), members_.end()); }
  /// Position of i among the members, −1 if it is not one.
  int position(int i) const {
    if (!in_[i]) return -1;
    return static_cast<int>(std::lower_bound(members_.begin(), members_.end(), i) -
                            members_.begin());
  }
  const std::vector<int>& members() const { return members_; }

 private:
  std::vector<bool> in_;
  std::vector<int> members_;
};

}  // namespace

void MultilevelCycle::truncation_correction(SparseMatrix& out) {
  // P̃ = P + F where F, the difference made by truncation, has few rows (the contact
  // boundary and the fine edges that carry moved flux), so
  //   P̃ᵀAP̃ = PᵀAP + FᵀAP + (FᵀAP)ᵀ + FᵀAF,
  // where PᵀAP and AP are computed once: the fine-level product is not redone for every new
  // active set. F is −P on the truncated rows plus the flux moves; only its rows, and the rows
  // of P that A couples to them, are formed (not F or a row-major P of the fine size).
  const int top = hierarchy_.num_levels() - 1;
  const SparseMatrix& p = hierarchy_.levels[top].prolongation;
  const std::vector<char>& truncated = level_truncated_[top];
  const SparseMatrix& top_moves = prolongation(top).moves();
  const int n = static_cast<int>(p.rows()), nc = static_cast<int>(p.cols());
  // F's entries in one pass over P, by fine row first, then renumbered to F's rows.
  SparseIndexSet f_rows(n);
  std::vector<Eigen::Triplet<double>> tf;
  for (int col = 0; col < nc; ++col) {
    for (SparseMatrix::InnerIterator it(p, col); it; ++it)
      if (truncated[it.row()]) {
        f_rows.insert(static_cast<int>(it.row()));
        tf.emplace_back(static_cast<int>(it.row()), col, -it.value());
      }
    for (SparseMatrix::InnerIterator it(top_moves, col); it; ++it) {
      f_rows.insert(static_cast<int>(it.row()));
      tf.emplace_back(static_cast<int>(it.row()), col, it.value());
    }
  }
  f_rows.finish();
  const std::vector<int>& rows = f_rows.members();
  const int m = static_cast<int>(rows.size());
  if (m == 0) {
    out = SparseMatrix(nc, nc);
    out.makeCompressed();
    return;
  }
  for (auto& t : tf) t = Eigen::Triplet<double>(f_rows.position(t.row()), t.col(), t.value());
  // The rows of P that A couples to F's rows, in a small row-major matrix.
  SparseIndexSet coupled(n);
  for (int k = 0; k < m; ++k)
    for (SparseMatrix::InnerIterator it(qp_.A, rows[k]); it; ++it)
      coupled.insert(static_cast<int>(it.row()));
  coupled.finish();
  std::vector<Eigen::Triplet<double>> tp;
  for (int col = 0; col < nc; ++col)
    for (SparseMatrix::InnerIterator it(p, col); it; ++it)
      if (const int c = coupled.position(it.row()); c >= 0) tp.emplace_back(c, col, it.value());
  RowMajorMatrix p_rows(static_cast<int>(coupled.members().size()), nc);
  p_rows.setFromTriplets(tp.begin(), tp.end());
  std::vector<Eigen::Triplet<double>>().swap(tp);
  // Rows `rows` of A P: row k of A is its column k (A is symmetric), times the rows of P, each
  // row summed in a dense accumulator first (one entry per coarse column it reaches, not one
  // per product).
  std::vector<Eigen::Triplet<double>> tap, taa;
  Vector sum = Vector::Zero(nc);
  std::vector<int> reached;
  for (int k = 0; k < m; ++k) {
    for (SparseMatrix::InnerIterator it(qp_.A, rows[k]); it; ++it) {
      for (RowMajorMatrix::InnerIterator pt(p_rows, coupled.position(it.row())); pt; ++pt) {
        const int col = static_cast<int>(pt.col());
        if (sum[col] == 0.0) reached.push_back(col);
        sum[col] += it.value() * pt.value();
      }
      if (const int l = f_rows.position(it.row()); l >= 0) taa.emplace_back(l, k, it.value());
    }
    for (int col : reached) tap.emplace_back(k, col, sum[col]), sum[col] = 0.0;
    reached.clear();
  }
  SparseMatrix rf(m, nc), rap(m, nc), aff(m, m);
  rf.setFromTriplets(tf.begin(), tf.end());
  rap.setFromTriplets(tap.begin(), tap.end());
  aff.setFromTriplets(taa.begin(), taa.end());
  const SparseMatrix rft = rf.transpose();
  const SparseMatrix cross = rft * rap;  // FᵀAP
  const SparseMatrix inner = rft * (aff * rf);
  out = cross + SparseMatrix(cross.transpose()) + inner;
  out.makeCompressed();
}

namespace {
constexpr double kCoarseShift = 1e-10;
constexpr double kRetryCoarseShift = 1e-8;

/// Makes a truncated coarse matrix definite, in place (no second copy of it is formed).
/// With `edits`, every change is saved there, and a missing diagonal entry makes it return
/// false with nothing changed; without, such an entry is inserted.
bool regularise_truncated(SparseMatrix& a, const TruncatedProlongation& truncated_prolongation,
                          ReversibleEdits* edits) {
  // A coarse DOF whose basis function was truncated away entirely (its column of the
  // truncated prolongation is empty: under bisection, a U_n or S_n whose fine neighbourhood
  // was not refined) has a zero row and column — up to the rounding of the truncation
  // correction's update formula, which is cleared here; a unit diagonal keeps the level
  // definite and its correction (with zero restricted residual) exactly zero.
  const std::vector<char> vanished = truncated_prolongation.vanished_columns();
  // Under bisection, truncated coarse functions can also become linearly dependent (a function
  // whose unrefined neighbourhood keeps only components that others share), and the level is
  // then only semi-definite. A relative diagonal shift of kCoarseShift makes it definite; the
  // correction then minimises a majorant of J along the level's functions, so it still never
  // increases J. The untruncated chain is checked for definiteness (chain_is_definite), so
  // this hides no indefinite weights.
  std::vector<char> has_diagonal(a.rows(), 0);
  for (int col = 0; col < a.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(a, col); it; ++it)
      if (it.row() == col) has_diagonal[col] = 1;
  const bool complete =
      std::find(has_diagonal.begin(), has_diagonal.end(), 0) == has_diagonal.end();
  if (edits && !complete) return false;
  for (int col = 0; col < a.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(a, col); it; ++it) {
      const int row = static_cast<int>(it.row());
      const bool clear = vanished[row] || vanished[col];
      if (!clear && row != col) continue;
      if (edits) edits->save(&it.valueRef());
      if (clear) it.valueRef() = 0.0;
      if (row == col)
        it.valueRef() = it.value() == 0.0 ? 1.0 : it.value() + kCoarseShift * it.value();
    }
  }
  if (complete) return true;
  // A vanished function's diagonal may be missing from the pattern: the rare insertion.
  std::vector<Eigen::Triplet<double>> unit;
  for (int i = 0; i < a.rows(); ++i)
    if (!has_diagonal[i]) unit.emplace_back(i, i, 1.0);
  SparseMatrix e(a.rows(), a.cols());
  e.setFromTriplets(unit.begin(), unit.end());
  SparseMatrix sum = sparse_sum(a, e);
  a.swap(sum);
  return true;
}
}  // namespace

void MultilevelCycle::truncate_second_finest() {
  const int top = hierarchy_.num_levels() - 1;
  LevelState& level = *levels_[top - 1];
  SparseMatrix& full = chain_->matrices[top - 1];
  SparseMatrix correction;
  truncation_correction(correction);
  if (top_edits_->add_within_pattern(correction) &&
      regularise_truncated(full, prolongation(top), top_edits_.get())) {
    level.A = &full;
    return;
  }
  // The correction reaches outside the pattern (not seen on the benchmarks): a matrix of its
  // own.
  top_edits_->restore();
  SparseMatrix sum = sparse_sum(full, correction);
  level.truncated.swap(sum);
  level.truncated.prune(0.0);
  level.A = &level.truncated;
  regularise_truncated(level.truncated, prolongation(top), nullptr);
}

void MultilevelCycle::make_smoother(int j) {
  LevelState& s = *levels_[j];
  s.patch.reset();
  s.point.reset();
  if (options_.smoother == SmootherType::kPatch) {
    s.patch = std::make_unique<PatchSmoother>(matrix(j), hierarchy_.levels[j].patches,
                                              hierarchy_.levels[j].patch_split);
    if (!s.patch->single_precision()) ++stats_.double_precision_smoothers;
  } else
    s.point = std::make_unique<PointSmoother>(matrix(j));
  s.strip.reset();
  if (options_.strip && !hierarchy_.levels[j].contact_strip.empty())
    s.strip = std::make_unique<StripSmoother>(matrix(j), hierarchy_.levels[j].contact_strip);
}

void MultilevelCycle::rebuild_coarse_levels() {
  const auto t0 = std::chrono::steady_clock::now();
  const int top = hierarchy_.num_levels() - 1;
  const bool truncating = std::find(truncated_.begin(), truncated_.end(), 1) != truncated_.end();
  if (top_edits_) top_edits_->restore();
  // The untruncated levels are formed before any level's diagonal is shifted in place below,
  // so that each is the product of unshifted ones, as when the chain was formed at once.
  if (!truncating && top > 0) chain_matrix(0);
  for (int j = top - 1; j >= 0; --j) {
    LevelState& level = *levels_[j];
    // The old matrix is released before the new one is formed: two of them at once were the
    // peak of a solve.
    SparseMatrix().swap(level.truncated);
    if (!truncating) {
      level.A = &chain_matrix(j);
    } else if (j == top - 1) {
      truncate_second_finest();
    } else {
      SparseMatrix coarse = galerkin_product(matrix(j + 1), *prolongation(j + 1).matrix());
      level.truncated.swap(coarse);
      level.truncated.makeCompressed();
      level.A = &level.truncated;
      regularise_truncated(level.truncated, prolongation(j + 1), nullptr);
    }
    if (j > 0) {
      // The truncated prolongation into level j needs level j's (truncated) matrix.
      truncate_level(j);
      try {
        make_smoother(j);
      } catch (const IndefiniteSystemError&) {
        if (!truncating) throw;
        // On deep bisection hierarchies (Hertz after 9 adaptive steps, 11 levels) the rounding
        // of the truncated chain outgrows kCoarseShift, and the strip block of a level lost
        // definiteness: a case with weights far inside the limit was refused. A larger shift on
        // that level, only when needed, keeps its correction minimising a majorant of J, so
        // the cycle stays monotone; raising kCoarseShift for every level slowed the robustness
        // cases (146 iterations on one).
        SparseMatrix& a = *level.A;  // the level's own, or the chain's edited in place
        const bool in_chain = level.A == &chain_->matrices[j];
        for (int col = 0; col < a.outerSize(); ++col)
          for (SparseMatrix::InnerIterator it(a, col); it; ++it)
            if (it.row() == col) {
              if (in_chain) top_edits_->save(&it.valueRef());
              it.valueRef() += kRetryCoarseShift * it.value();
            }
        make_smoother(j);
      }
    }
  }
  coarse_solver_ = std::make_unique<SparseBoxQpSolver>(matrix(0));
  ++stats_.galerkin_rebuilds;
  stats_.galerkin_s += seconds_since(t0);
}

void MultilevelCycle::smooth_level(int j, Vector& c, Vector& r, const Vector& lo, const Vector& hi,
                                   bool forward) {
  const auto t0 = std::chrono::steady_clock::now();
  const LevelState& s = *levels_[j];
  if (s.patch)
    s.patch->sweep(c, r, lo, hi, forward);
  else
    s.point->sweep(c, r, lo, hi, forward);
  stats_.smoothing_s += seconds_since(t0);
  if (s.strip) {
    const auto t1 = std::chrono::steady_clock::now();
    s.strip->solve(c, r, lo, hi);
    stats_.strip_s += seconds_since(t1);
  }
}

void MultilevelCycle::smooth(Vector& x, Vector& r, bool forward) {
  const int top = hierarchy_.num_levels() - 1;
  smooth_level(top, x, r, qp_.lower, qp_.upper, forward);
  if (sweep_hook_) sweep_hook_(x, r);
}

void project_defect(const Level& fine_level, CoarseProjection projection, const Vector& defect,
                    Vector& coarse_hi, const std::vector<std::array<double, 2>>* sn_weights) {
  auto d = [&](int i) { return i < 0 ? kNoBound : defect[i]; };
  for (std::size_t index = 0; index < fine_level.links.size(); ++index) {
    const ContactLink& l = fine_level.links[index];
    const std::array<double, 2>& weight = sn_weights ? (*sn_weights)[index] : l.sn_weight;
    const double va = d(l.fine_un_a), vm = d(l.fine_un_mid), vb = d(l.fine_un_b);
    double ta = 0.0, tb = 0.0;
    switch (projection) {
      case CoarseProjection::kA:
        ta = std::min(va, std::max(vm, 2.0 * vm - vb));
        tb = std::min(vb, std::max(vm, 2.0 * vm - va));
        break;
      case CoarseProjection::kB:
        ta = std::min(va, vm);
        tb = std::min(vb, vm);
        break;
      case CoarseProjection::kC:
        ta = tb = std::min({va, vm, vb});
        break;
    }
    if (l.coarse_un_a >= 0) coarse_hi[l.coarse_un_a] = std::min(coarse_hi[l.coarse_un_a], ta);
    if (l.coarse_un_b >= 0) coarse_hi[l.coarse_un_b] = std::min(coarse_hi[l.coarse_un_b], tb);
    if (l.coarse_sn >= 0) {
      // Pressure: the coarse S_n may not exceed any child's defect, measured per unit of the
      // prolongation weight (the minimum over the children of the σ_nn defects).
      double bound = kNoBound;
      for (int k = 0; k < 2; ++k) {
        if (l.fine_sn[k] < 0) continue;
        bound = std::min(bound, weight[k] > 0 ? d(l.fine_sn[k]) / weight[k] : 0.0);
      }
      coarse_hi[l.coarse_sn] = std::min(coarse_hi[l.coarse_sn], bound);
    }
  }
  for (int i = 0; i < coarse_hi.size(); ++i) coarse_hi[i] = std::max(0.0, coarse_hi[i]);
}

void MultilevelCycle::project_obstacle(int j, const Vector& c, const Vector& hi,
                                       Vector& coarse_hi) const {
  Vector defect(c.size());
  for (int i = 0; i < c.size(); ++i)
    defect[i] = (!is_bounded_above(hi[i]) || level_truncated_[j][i]) ? kNoBound
                                                                     : std::max(0.0, hi[i] - c[i]);
  project_defect(hierarchy_.levels[j], options_.projection, defect, coarse_hi, &sn_weights_[j]);
}

void MultilevelCycle::recurse(int j, CycleShape shape, Vector& c, Vector& r, const Vector& lo,
                              const Vector& hi, bool constrained) {
  const int top = hierarchy_.num_levels() - 1;
  const SparseMatrix& A = matrix(j);
  if (j == 0) {
    const auto t0 = std::chrono::steady_clock::now();
    const int n = static_cast<int>(c.size());
    Vector dlo(n), dhi(n), delta;
    for (int i = 0; i < n; ++i) {
      dlo[i] = std::min(0.0, lo[i] - c[i]);
      dhi[i] = std::max(0.0, hi[i] - c[i]);
    }
    coarse_solver_->solve(r, dlo, dhi, delta);
    Vector change(n);
    for (int i = 0; i < n; ++i) {
      const double updated = std::clamp(c[i] + delta[i], lo[i], hi[i]);
      change[i] = updated - c[i];
      c[i] = updated;
    }
    r -= A * change;
    stats_.coarse_s += seconds_since(t0);
    if (j == top && sweep_hook_) sweep_hook_(c, r);
    return;
  }
  for (int s = 0; s < options_.pre_smoothing; ++s) {
    smooth_level(j, c, r, lo, hi, true);
    if (j == top && sweep_hook_) sweep_hook_(c, r);
  }
  if (j == top && constrained) {
    // N•: bounded fine DOFs at their bound after smoothing.
    std::vector<char> active(c.size(), 0);
    for (int i = 0; i < c.size(); ++i) active[i] = is_at_bound(c[i], lo[i], hi[i]);
    set_truncation(active);
  }
  const TruncatedProlongation& P = prolongation(j);
  const int nc = P.cols();
  Vector rc;
  P.restrict_to(r, rc);
  Vector lo_c = Vector::Constant(nc, -kNoBound), hi_c = Vector::Constant(nc, kNoBound);
  if (constrained) project_obstacle(j, c, hi, hi_c);
  Vector cc = Vector::Zero(nc);
  // W and F visit the coarse problem twice; its bounds are on the total coarse correction, so
  // the second visit continues from the first (each visit is monotone, hence both are).
  recurse(j - 1, shape, cc, rc, lo_c, hi_c, constrained);
  if (revisit_[j] && shape != CycleShape::kV)
    recurse(j - 1, shape == CycleShape::kF ? CycleShape::kV : shape, cc, rc, lo_c, hi_c,
            constrained);
  Vector v;
  P.prolongate(cc, v);
  double alpha = 1.0;
  if (constrained) {
    // Safeguard: the projections make K_{j−1} ⊂ K_j exactly where contact normals agree
    // between levels; on curved boundaries the shortened step keeps every iterate feasible,
    // and J still decreases since J is convex and the coarse correction lowers it.
    for (int i = 0; i < v.size(); ++i) {
      if (v[i] > 0 && c[i] + v[i] > hi[i]) alpha = std::min(alpha, (hi[i] - c[i]) / v[i]);
      if (v[i] < 0 && c[i] + v[i] < lo[i]) alpha = std::min(alpha, (lo[i] - c[i]) / v[i]);
    }
    alpha = std::max(alpha, 0.0);
    if (alpha < 1.0) ++stats_.safeguard_reductions;
  }
  if (alpha > 0.0) {
    Vector& change = v;  // v becomes the change of c: one vector of the level fewer
    for (int i = 0; i < v.size(); ++i) {
      const double updated = std::clamp(c[i] + alpha * v[i], lo[i], hi[i]);
      change[i] = updated - c[i];
      c[i] = updated;
    }
    Vector ac;
    symmetric_multiply(A, change, ac);
    r -= ac;
  }
  if (j == top && sweep_hook_) sweep_hook_(c, r);
  for (int s = 0; s < options_.post_smoothing; ++s) {
    smooth_level(j, c, r, lo, hi, false);
    if (j == top && sweep_hook_) sweep_hook_(c, r);
  }
}

void MultilevelCycle::nonlinear_cycle(Vector& x, Vector& r) {
  recurse(hierarchy_.num_levels() - 1, options_.cycle, x, r, qp_.lower, qp_.upper, true);
}

void MultilevelCycle::linear_cycle(const std::vector<char>& frozen, Vector& c, Vector& r) {
  const int n = qp_.size();
  set_truncation(frozen);
  Vector lo = Vector::Constant(n, -kNoBound), hi = Vector::Constant(n, kNoBound);
  for (int i = 0; i < n; ++i)
    if (frozen[i]) lo[i] = hi[i] = 0.0;
  auto hook = std::move(sweep_hook_);
  sweep_hook_ = nullptr;
  recurse(hierarchy_.num_levels() - 1, options_.cycle, c, r, lo, hi, false);
  sweep_hook_ = std::move(hook);
}

}  // namespace fosls
