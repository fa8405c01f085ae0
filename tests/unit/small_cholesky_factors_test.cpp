// SmallCholeskyFactors: patch factors in single precision only where the rounding provably
// keeps every local correction a decrease of the quadratic, in double otherwise.
#include "solvers/small_cholesky_factors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace fosls {
namespace {

/// A random symmetric positive definite matrix with eigenvalues from 1 to `condition`.
Eigen::MatrixXd spd_with_condition(int m, double condition, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::MatrixXd g(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) g(i, j) = n(rng);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(g);
  const Eigen::MatrixXd q = qr.householderQ();
  Eigen::VectorXd eigenvalues(m);
  for (int i = 0; i < m; ++i) eigenvalues[i] = std::pow(condition, double(i) / (m - 1));
  return q * eigenvalues.asDiagonal() * q.transpose();
}

SmallCholeskyFactors factorise(const std::vector<Eigen::MatrixXd>& matrices, int& failed) {
  std::vector<int> sizes;
  for (const auto& a : matrices) sizes.push_back(static_cast<int>(a.rows()));
  return SmallCholeskyFactors(
      sizes, [&](int k, Eigen::MatrixXd& block) { block = matrices[k]; }, failed);
}

/// The energy a correction d = Ã⁻¹r changes ½dᵀAd − rᵀd by, relative to the exact −½rᵀA⁻¹r.
double relative_decrease(const Eigen::MatrixXd& a, const SmallCholeskyFactors& f, int k,
                         const Vector& r) {
  Vector d = r;
  f.solve(k, d);
  const double decrease = 0.5 * d.dot(a * d) - r.dot(d);
  const double exact = -0.5 * r.dot(a.llt().solve(r));
  return decrease / exact;
}

TEST(SmallCholeskyFactors, WellConditionedPatchesAreKeptInSinglePrecisionAndStillDecrease) {
  std::vector<Eigen::MatrixXd> matrices;
  for (int k = 0; k < 50; ++k) matrices.push_back(spd_with_condition(14, 1e4, k));
  int failed = 0;
  const SmallCholeskyFactors f = factorise(matrices, failed);
  EXPECT_EQ(failed, -1);
  EXPECT_TRUE(f.single_precision());
  EXPECT_EQ(f.bytes(), 50 * 105 * sizeof(float));
  const Vector r = Vector::LinSpaced(14, -1.0, 2.0);
  for (int k = 0; k < 50; ++k) {
    // At least 1 − ε of the exact decrease (ε ≤ kMaxSinglePerturbation), and not exact: the
    // factors really are rounded.
    const double ratio = relative_decrease(matrices[k], f, k, r);
    EXPECT_GT(ratio, 1.0 - SmallCholeskyFactors::kMaxSinglePerturbation);
    EXPECT_NE(ratio, 1.0);
    EXPECT_TRUE(f.lower(k).isApprox(Eigen::MatrixXd(matrices[k].llt().matrixL()), 1e-5));
  }
}

TEST(SmallCholeskyFactors, OneIllConditionedPatchKeepsAllFactorsInDouble) {
  std::vector<Eigen::MatrixXd> matrices;
  for (int k = 0; k < 20; ++k) matrices.push_back(spd_with_condition(14, 1e4, k));
  // Condition 1e12: rounding L to float perturbs this matrix by far more than 1 % (or even
  // makes it indefinite), so no factor may be rounded.
  matrices.push_back(spd_with_condition(14, 1e12, 99));
  int failed = 0;
  const SmallCholeskyFactors f = factorise(matrices, failed);
  EXPECT_EQ(failed, -1);
  EXPECT_FALSE(f.single_precision());
  EXPECT_EQ(f.bytes(), 21 * 105 * sizeof(double));
  const Vector r = Vector::LinSpaced(14, -1.0, 2.0);
  for (int k = 0; k < 21; ++k) EXPECT_NEAR(relative_decrease(matrices[k], f, k, r), 1.0, 1e-3);
}

/// ε = ‖L⁻¹(L_f L_fᵀ − L Lᵀ)L⁻ᵀ‖₂ computed exactly (eigenvalues of the symmetric matrix).
double exact_rounding_perturbation(const Eigen::MatrixXd& a) {
  const Eigen::MatrixXd l = a.llt().matrixL();
  const Eigen::MatrixXd lf = l.cast<float>().cast<double>();
  const Eigen::MatrixXd linv =
      l.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(a.rows(), a.cols()));
  const Eigen::MatrixXd w = linv * (lf * lf.transpose() - l * l.transpose()) * linv.transpose();
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(w).eigenvalues().cwiseAbs().maxCoeff();
}

TEST(SmallCholeskyFactors, TheRoundingBoundHoldsAndIsNotFarOff) {
  for (double condition : {1e2, 1e4, 1e6, 1e8}) {
    for (unsigned seed = 0; seed < 10; ++seed) {
      const Eigen::MatrixXd a = spd_with_condition(14, condition, seed);
      const double bound = SmallCholeskyFactors::rounding_bound(Eigen::MatrixXd(a.llt().matrixL()));
      const double exact = exact_rounding_perturbation(a);
      EXPECT_GE(bound, exact) << condition << " " << seed;
      EXPECT_LE(bound, 30 * exact) << condition << " " << seed;
    }
  }
}

/// The first condition 10^(k/4) whose matrix has a rounding bound above `threshold`.
double first_condition_with_bound_above(double threshold, unsigned seed) {
  for (int k = 8; k < 60; ++k) {
    const double condition = std::pow(10.0, k / 4.0);
    const Eigen::MatrixXd l = spd_with_condition(14, condition, seed).llt().matrixL();
    if (SmallCholeskyFactors::rounding_bound(l) > threshold) return condition;
  }
  return 0.0;
}

TEST(SmallCholeskyFactors, TheSwitchToDoubleIsAtTheThresholdWhateverThreadFindsIt) {
  // 600 matrices: more than two chunks of the factorisation's dynamic schedule, so with two
  // threads the matrix that decides lies in another thread's share than the first ones.
  const double limit = SmallCholeskyFactors::kMaxSinglePerturbation;
  const double above = first_condition_with_bound_above(limit, 7);
  ASSERT_GT(above, 0.0);
  const double below = above / std::pow(10.0, 0.25);
  ASSERT_LE(SmallCholeskyFactors::rounding_bound(spd_with_condition(14, below, 7).llt().matrixL()),
            limit);
  for (const double condition : {below, above}) {
    std::vector<Eigen::MatrixXd> matrices;
    for (int k = 0; k < 600; ++k) matrices.push_back(spd_with_condition(14, 1e3, k));
    matrices[450] = spd_with_condition(14, condition, 7);
    int failed = 0;
    const SmallCholeskyFactors f = factorise(matrices, failed);
    EXPECT_EQ(failed, -1);
    EXPECT_EQ(f.single_precision(), condition == below) << condition;
  }
}

TEST(SmallCholeskyFactors, NamesTheFirstIndefiniteMatrix) {
  std::vector<Eigen::MatrixXd> matrices(6, spd_with_condition(5, 10.0, 1));
  matrices[4](2, 2) = -1.0;
  matrices[3](0, 0) = -1.0;
  int failed = -1;
  factorise(matrices, failed);
  EXPECT_EQ(failed, 3);
}

}  // namespace
}  // namespace fosls
