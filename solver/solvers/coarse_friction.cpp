#include "solvers/coarse_friction.hpp"

#include <cmath>
#include <map>
#include <utility>

namespace fosls {

namespace {

/// main_columns and each row's entry there.
std::vector<int> main_columns(const SparseMatrix& P, std::vector<double>& weight) {
  std::vector<int> column(P.rows(), -1);
  weight.assign(P.rows(), 0.0);
  for (int col = 0; col < P.cols(); ++col)
    for (SparseMatrix::InnerIterator it(P, col); it; ++it)
      if (std::abs(it.value()) > std::abs(weight[it.row()]))
        weight[it.row()] = it.value(), column[it.row()] = col;
  return column;
}

/// The kink the two halves share (E's midpoint), or -1.
int shared_kink(const FrictionEdge& a, const FrictionEdge& b) {
  for (int k : a.kink)
    if (k >= 0 && (k == b.kink[0] || k == b.kink[1])) return k;
  return -1;
}

/// Builds the coarse edges from the halves grouped by their coarse S_t.
class CoarseFrictionBuilder {
 public:
  CoarseFrictionBuilder(const Kinks& fine_kinks, const SparseMatrix& P)
      : fine_kinks_(fine_kinks), main_(main_columns(P, main_weight_)) {}

  /// The coarse edge of the halves a and b; false where they are not two halves of one edge.
  bool add_edge(const FrictionEdge& a, const FrictionEdge& b) {
    const int mid = shared_kink(a, b);
    if (mid < 0 || main_[a.sn] != main_[b.sn] || main_[a.sn] < 0 || a.coefficient != b.coefficient)
      return false;
    FrictionEdge e;
    e.st = main_[a.st];
    e.sn = main_[a.sn];
    e.coefficient = a.coefficient;
    e.tresca = a.tresca + b.tresca;  // ∫_E s/μ over both halves
    int k = 0;
    for (const FrictionEdge* half : {&a, &b})
      for (int end = 0; end < 2; ++end) {
        if (half->kink[end] == mid) continue;
        if (k == 2) return false;
        if (half->kink[end] < 0) {
          e.fixed_slip[k++] = half->fixed_slip[end];
          continue;
        }
        e.kink[k] = coarse_kink(half->kink[end]);
        if (e.kink[k++] < 0) return false;
      }
    if (k != 2) return false;
    out_.layout.edges.push_back(e);
    out_.row_obstacles.push_back(e.st);
    return true;
  }

  CoarseFriction take(double c3) {
    out_.layout.c3 = c3;
    out_.kinks.weight.assign(out_.kinks.dof.size(), 0.0);
    out_.row_obstacles.insert(out_.row_obstacles.end(), out_.kinks.dof.begin(),
                              out_.kinks.dof.end());
    return std::move(out_);
  }

  int main_column(int row) const { return main_[row]; }

 private:
  /// The coarse kink of the U_t that carries fine kink k at a coarse vertex (-1 where none
  /// carries most of it).
  int coarse_kink(int k) {
    const int d = fine_kinks_.dof[k];
    if (main_[d] < 0 || std::abs(main_weight_[d]) < 0.75) return -1;
    auto [it, added] = kink_of_.try_emplace(main_[d], out_.kinks.size());
    if (added) {
      out_.kinks.dof.push_back(main_[d]);
      out_.kinks.at.push_back(fine_kinks_.at[k]);
    }
    return it->second;
  }

  const Kinks& fine_kinks_;
  std::vector<double> main_weight_;  // before main_: main_columns fills it
  std::vector<int> main_;
  std::map<int, int> kink_of_;  // coarse U_t → coarse kink
  CoarseFriction out_;
};

}  // namespace

std::vector<int> main_columns(const SparseMatrix& P) {
  std::vector<double> weight;
  return main_columns(P, weight);
}

std::optional<CoarseFriction> coarser_friction(const FrictionLayout& fine, const Kinks& fine_kinks,
                                               const SparseMatrix& P) {
  CoarseFrictionBuilder builder(fine_kinks, P);
  std::map<int, std::vector<int>> halves;  // coarse S_t → its fine edges, in layout order
  for (std::size_t e = 0; e < fine.edges.size(); ++e) {
    const int st = builder.main_column(fine.edges[e].st);
    if (st < 0) return std::nullopt;
    halves[st].push_back(static_cast<int>(e));
  }
  for (const auto& [st, edges] : halves)
    if (edges.size() != 2 || !builder.add_edge(fine.edges[edges[0]], fine.edges[edges[1]]))
      return std::nullopt;
  return builder.take(fine.c3);
}

}  // namespace fosls
