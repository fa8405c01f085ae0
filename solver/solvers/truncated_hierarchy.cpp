#include "solvers/truncated_hierarchy.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <map>

#include "core/indefinite_system.hpp"
#include "solvers/galerkin_product.hpp"
#include "solvers/sparse_sum.hpp"
#include "solvers/truncation_correction.hpp"

namespace fosls {

namespace {

/// The change δ on the DOFs `local` that minimises the energy (v + δ)ᵀ A (v + δ) of v = column
/// `column` of p with the `extras` (DOF, value) added: δ = −A_LL⁻¹ (A v)_L.
Vector energy_minimising_correction(const SparseMatrix& a, const SparseMatrix& p, int column,
                                    const std::vector<int>& local,
                                    const std::vector<std::pair<int, double>>& extras,
                                    const std::vector<char>* dropped_rows) {
  const int m = static_cast<int>(local.size());
  std::vector<int> position(a.rows(), -1);
  for (int i = 0; i < m; ++i) position[local[i]] = i;
  Vector ap = Vector::Zero(m);
  for (SparseMatrix::InnerIterator pc(p, column); pc; ++pc) {
    if (dropped_rows && (*dropped_rows)[pc.row()]) continue;
    for (SparseMatrix::InnerIterator it(a, static_cast<int>(pc.row())); it; ++it)
      if (const int i = position[it.row()]; i >= 0) ap[i] += it.value() * pc.value();
  }
  for (const auto& [extra_dof, extra_value] : extras)
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

/// The flux moved into one coarse S_n's column: where it lands and the path that carries it.
struct ColumnMoves {
  std::vector<int> path;                         ///< the interior fine σ DOFs on the way
  std::vector<std::pair<int, double>> arrivals;  ///< (free fine S_n, flux added there)
};

/// The path DOFs of a flux move (its entries after the arrival's).
std::vector<int> path_of(const std::vector<std::pair<int, double>>& move) {
  std::vector<int> path;
  for (std::size_t m = 1; m < move.size(); ++m) path.push_back(move[m].first);
  return path;
}

/// When every child of link l is truncated, its share of the coarse S_n moves onto the first free
/// child of a partner link (another pair of the same coarse facet): false when there is none.
bool move_to_partner(const Level& level, int l, const std::vector<char>& truncated,
                     std::vector<std::array<double, 2>>& weights, ColumnMoves& column) {
  const ContactLink& link = level.links[l];
  if (link.partners.empty() || link.flux_moves[0].empty()) return false;
  for (const LinkPartner& partner : link.partners)
    for (int i = 0; i < 2; ++i) {
      const int free_sn = level.links[partner.link].fine_sn[i];
      if (free_sn < 0 || truncated[free_sn]) continue;
      for (int k = 0; k < 2; ++k) {
        if (link.fine_sn[k] < 0) continue;
        const double moved = link.sn_weight[k] * partner.factor[k][i];
        column.arrivals.emplace_back(free_sn, moved);
        weights[partner.link][i] += moved;
      }
      column.path = path_of(link.flux_moves[0]);
      return true;
    }
  return false;  // every child of the facet is truncated: the coarse S_n has no flux left
}

/// P̃'s entries for the moves: the arrivals, and one least-energy correction on each column's path.
void add_moves(const SparseMatrix& a, const SparseMatrix& prolongation,
               const std::vector<char>& truncated, const std::map<int, ColumnMoves>& columns,
               std::vector<Eigen::Triplet<double>>& corrections) {
  for (const auto& [coarse_sn, column] : columns) {
    if (column.arrivals.empty()) continue;
    for (const auto& [free_sn, moved] : column.arrivals)
      corrections.emplace_back(free_sn, coarse_sn, moved);
    // The truncated rows of the coarse S_n's column are zero, and the path and the free
    // quarters are not truncated, so column coarse_sn of P stands for that of P̃ here.
    const Vector delta = energy_minimising_correction(a, prolongation, coarse_sn, column.path,
                                                      column.arrivals, &truncated);
    for (std::size_t m = 0; m < column.path.size(); ++m)
      corrections.emplace_back(column.path[m], coarse_sn, delta[m]);
  }
}

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

TruncatedHierarchy::TruncatedHierarchy(const BoxQp& qp, const LevelHierarchy& hierarchy,
                                       std::shared_ptr<GalerkinChain> chain)
    : qp_(qp), hierarchy_(hierarchy), chain_(std::move(chain)), levels_(hierarchy.num_levels()) {
  const int nl = hierarchy.num_levels();
  if (nl >= 2) top_edits_ = std::make_unique<ReversibleEdits>(chain_->matrices[nl - 2]);
}

TruncatedHierarchy::~TruncatedHierarchy() {
  if (top_edits_) top_edits_->restore();
}

const SparseMatrix& TruncatedHierarchy::matrix(int j) const {
  return j == hierarchy_.num_levels() - 1 ? qp_.A : *levels_[j].A;
}

SparseMatrix& TruncatedHierarchy::chain_matrix(int j) {
  SparseMatrix& m = chain_->matrices[j];
  if (m.rows() == 0) {
    const int top = hierarchy_.num_levels() - 1;
    SparseMatrix coarse = galerkin_product(j + 1 == top ? qp_.A : chain_matrix(j + 1),
                                           hierarchy_.levels[j + 1].prolongation);
    m.swap(coarse);
  }
  return m;
}

bool TruncatedHierarchy::set_truncation(const std::vector<char>& truncated,
                                        const std::function<void(int j)>& level_built) {
  if (built_ && truncated == truncated_) return false;
  truncated_ = truncated;
  const int top = hierarchy_.num_levels() - 1;
  level_truncated_.assign(top + 1, {});
  prolongations_.assign(top + 1, TruncatedProlongation());
  sn_weights_.assign(top + 1, {});
  if (top > 0) {
    level_truncated_[top] = truncated;
    truncate_level(top);
  }
  const bool truncating = std::find(truncated_.begin(), truncated_.end(), 1) != truncated_.end();
  if (top_edits_) top_edits_->restore();
  // The untruncated levels are formed before any level's diagonal is shifted in place below,
  // so that each is the product of unshifted ones, as when the chain was formed at once.
  if (!truncating && top > 0) chain_matrix(0);
  for (int j = top - 1; j >= 0; --j) {
    form_level(j, truncating);
    if (j == 0) break;
    // The truncated prolongation into level j needs level j's (truncated) matrix.
    truncate_level(j);
    try {
      level_built(j);
    } catch (const IndefiniteSystemError&) {
      if (!truncating) throw;
      // On deep bisection hierarchies the rounding of the truncated chain can outgrow
      // kCoarseShift and a level's strip block lose definiteness; a larger shift on that level,
      // only when needed, keeps its correction minimising a majorant of J, so the cycle stays
      // monotone (docs/performance.md, "Coarse shifts").
      shift_diagonal(j);
      level_built(j);
    }
  }
  built_ = true;
  return true;
}

void TruncatedHierarchy::form_level(int j, bool truncating) {
  const int top = hierarchy_.num_levels() - 1;
  LevelMatrix& level = levels_[j];
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
}

void TruncatedHierarchy::shift_diagonal(int j) {
  LevelMatrix& level = levels_[j];
  SparseMatrix& a = *level.A;  // the level's own, or the chain's edited in place
  const bool in_chain = level.A == &chain_->matrices[j];
  for (int col = 0; col < a.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(a, col); it; ++it)
      if (it.row() == col) {
        if (in_chain) top_edits_->save(&it.valueRef());
        it.valueRef() += kRetryCoarseShift * it.value();
      }
}

void TruncatedHierarchy::truncate_second_finest() {
  const int top = hierarchy_.num_levels() - 1;
  LevelMatrix& level = levels_[top - 1];
  SparseMatrix& full = chain_->matrices[top - 1];
  SparseMatrix correction;
  truncation_correction(qp_.A, hierarchy_.levels[top].prolongation, level_truncated_[top],
                        prolongation(top).moves(), correction);
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

void TruncatedHierarchy::truncate_level(int j) {
  // Truncated basis: coarse functions lose their component at truncated DOFs of level j, i.e.
  // the rows of P_j of those DOFs are zero. On the finest level these are the active DOFs; on
  // a coarser level, the S_n of coarse contact edges whose children are all truncated (their
  // functions have no normal flux left on the finest level).
  const Level& level = hierarchy_.levels[j];
  const std::vector<char>& truncated = level_truncated_[j];
  const bool any = std::find(truncated.begin(), truncated.end(), 1) != truncated.end();
  std::vector<char> coarse(hierarchy_.levels[j - 1].num_dofs, 0);
  SparseMatrix moves = flux_moves(j, coarse);
  // P̃ = P without the truncated rows, plus the flux moves: applied from P on the finest level,
  // elsewhere formed in storage of its exact size.
  if (j == hierarchy_.num_levels() - 1) {
    prolongations_[j] = TruncatedProlongation::applied(
        level.prolongation, any ? truncated : std::vector<char>{}, std::move(moves));
  } else {
    prolongations_[j] = TruncatedProlongation::formed(
        sparse_sum(level.prolongation, moves, any ? &truncated : nullptr), &level.prolongation);
  }
  if (j > 1) level_truncated_[j - 1] = std::move(coarse);
}

SparseMatrix TruncatedHierarchy::flux_moves(int j, std::vector<char>& coarse) {
  const Level& level = hierarchy_.levels[j];
  const std::vector<char>& truncated = level_truncated_[j];
  std::vector<std::array<double, 2>>& weights = sn_weights_[j];
  weights.assign(level.links.size(), {0.0, 0.0});
  for (std::size_t l = 0; l < level.links.size(); ++l) weights[l] = level.links[l].sn_weight;
  const bool any = std::find(truncated.begin(), truncated.end(), 1) != truncated.end();
  std::vector<Eigen::Triplet<double>> corrections;
  if (any) {
    // Zeroing the flux of one half of a coarse contact edge leaves the edge's coarse S_n
    // function with a divergence of order 1/h² in that half's fine triangle: so stiff that the
    // coarse levels cannot represent a normal traction on coarse edges that straddle the end
    // of the contact zone, and the linear phase slows down (docs/performance.md, "Measurements
    // behind choices in the code"). The function keeps
    // its flux instead: the truncated half's share goes to the free half, and the fine edges
    // between the halves carry it with the least energy, so the divergence stays bounded and
    // the truncated DOF is untouched. (In 3D a truncated pair of quarters moves to its partner.)
    std::map<int, ColumnMoves> columns;
    for (std::size_t l = 0; l < level.links.size(); ++l) {
      const ContactLink& link = level.links[l];
      if (link.coarse_sn < 0 || link.fine_sn[0] < 0) continue;
      if (link.fine_sn[1] < 0) {
        // A contact edge that bisection kept has one child: the coarse S_n is truncated
        // with it, unless the child's partners of the same facet take its share.
        if (truncated[link.fine_sn[0]] && !move_to_partner(level, static_cast<int>(l), truncated,
                                                           weights, columns[link.coarse_sn]))
          coarse[link.coarse_sn] = 1;
        continue;
      }
      const bool t0 = truncated[link.fine_sn[0]], t1 = truncated[link.fine_sn[1]];
      if (t0 && t1) {
        if (!move_to_partner(level, static_cast<int>(l), truncated, weights,
                             columns[link.coarse_sn]))
          coarse[link.coarse_sn] = 1;
        continue;
      }
      const int k = t0 ? 0 : 1;
      if (t0 == t1 || link.flux_moves[k].empty()) continue;
      const auto& [free_sn, factor] = link.flux_moves[k].front();
      const double moved = link.sn_weight[k] * factor;
      ColumnMoves& column = columns[link.coarse_sn];
      column.path = path_of(link.flux_moves[k]);
      column.arrivals.emplace_back(free_sn, moved);
      weights[l][1 - k] += moved;
    }
    add_moves(matrix(j), level.prolongation, truncated, columns, corrections);
  }
  SparseMatrix moves(level.prolongation.rows(), level.prolongation.cols());
  moves.setFromTriplets(corrections.begin(), corrections.end());
  moves.makeCompressed();
  return moves;
}

}  // namespace fosls
