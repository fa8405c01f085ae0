#include "solvers/galerkin_product.hpp"

#include <omp.h>

#include <algorithm>
#include <vector>

namespace fosls {

SparseMatrix galerkin_product(const SparseMatrix& A, const SparseMatrix& P) {
  const int n = static_cast<int>(P.rows()), nc = static_cast<int>(P.cols());
  const SparseMatrix pt = P.transpose();  // column i: row i of P
  const int threads = std::max(1, omp_get_max_threads());
  // Thread t computes the columns [first[t], first[t + 1]) into its own lists.
  std::vector<int> first(threads + 1);
  for (int t = 0; t <= threads; ++t)
    first[t] = static_cast<int>(static_cast<long long>(nc) * t / threads);
  std::vector<std::vector<int>> rows(threads), counts(threads);
  std::vector<std::vector<double>> values(threads);
#pragma omp parallel num_threads(threads)
  for (int t = omp_get_thread_num(); t < threads; t += omp_get_num_threads()) {
    std::vector<double> w(n, 0.0), c(nc, 0.0);
    std::vector<int> fine, coarse;
    std::vector<char> in_fine(n, 0), in_coarse(nc, 0);
    for (int J = first[t]; J < first[t + 1]; ++J) {
      fine.clear();
      coarse.clear();
      for (SparseMatrix::InnerIterator p(P, J); p; ++p)
        for (SparseMatrix::InnerIterator a(A, static_cast<int>(p.row())); a; ++a) {
          const int i = static_cast<int>(a.row());
          if (!in_fine[i]) in_fine[i] = 1, fine.push_back(i);
          w[i] += a.value() * p.value();
        }
      for (int i : fine) {
        for (SparseMatrix::InnerIterator q(pt, i); q; ++q) {
          const int k = static_cast<int>(q.row());
          if (!in_coarse[k]) in_coarse[k] = 1, coarse.push_back(k);
          c[k] += q.value() * w[i];
        }
        w[i] = 0.0, in_fine[i] = 0;
      }
      std::sort(coarse.begin(), coarse.end());
      for (int k : coarse) {
        rows[t].push_back(k);
        values[t].push_back(c[k]);
        c[k] = 0.0, in_coarse[k] = 0;
      }
      counts[t].push_back(static_cast<int>(coarse.size()));
    }
  }
  SparseMatrix out(nc, nc);
  std::size_t nnz = 0;
  for (int t = 0; t < threads; ++t) nnz += rows[t].size();
  out.resizeNonZeros(static_cast<Eigen::Index>(nnz));
  int* outer = out.outerIndexPtr();
  outer[0] = 0;
  std::size_t at = 0;
  for (int t = 0; t < threads; ++t) {
    for (std::size_t k = 0; k < counts[t].size(); ++k)
      outer[first[t] + k + 1] = outer[first[t] + k] + counts[t][k];
    std::copy(rows[t].begin(), rows[t].end(), out.innerIndexPtr() + at);
    std::copy(values[t].begin(), values[t].end(), out.valuePtr() + at);
    at += rows[t].size();
    std::vector<int>().swap(rows[t]);
    std::vector<double>().swap(values[t]);
  }
  return out;
}

}  // namespace fosls
