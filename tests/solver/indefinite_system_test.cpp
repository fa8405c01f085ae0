// Indefinite systems are reported by type: every solver part that needs a positive definite
// matrix throws IndefiniteSystemError, and the case layer turns it into an error at /weights
// also when the cheap boundary-layer screen lets the weights through.
#include <gtest/gtest.h>

#include "assembly/definiteness.hpp"
#include "case/run/case_runner.hpp"
#include "contact_problems.hpp"
#include "core/indefinite_system.hpp"
#include "solvers/exact_box_qp.hpp"
#include "solvers/patch_smoother.hpp"
#include "solvers/solve_loop.hpp"
#include "solvers/strip_smoother.hpp"

namespace fosls {
namespace {

SparseMatrix saddle() {
  Eigen::MatrixXd a(2, 2);
  a << 1.0, 2.0, 2.0, 1.0;  // eigenvalues 3 and −1
  return a.sparseView();
}

TEST(IndefiniteSystem, SparseQpSolverAndSmoothersThrowIt) {
  const SparseMatrix a = saddle();
  EXPECT_THROW(SparseBoxQpSolver{a}, IndefiniteSystemError);
  EXPECT_THROW(StripSmoother(a, {0, 1}, BlockFactorization::reduced), IndefiniteSystemError);
  EXPECT_THROW(StripSmoother(a, {0, 1}, BlockFactorization::held_rows), IndefiniteSystemError);
  const std::vector<std::vector<int>> patches = {{0, 1}};
  EXPECT_THROW(PatchSmoother(a, patches), IndefiniteSystemError);
}

TEST(IndefiniteSystem, PdasThrowsIt) {
  BoxQp qp;
  qp.A = saddle();
  qp.b = Vector::Ones(2);
  qp.lower = Vector::Constant(2, -kNoBound);
  qp.upper = Vector::Constant(2, kNoBound);
  SolverOptions options;
  options.method = SolverMethod::kPdas;
  Vector x;
  EXPECT_THROW(solve_box_qp(qp, LevelHierarchy{}, options, {}, x), IndefiniteSystemError);
}

/// The square with c3 = 0.35 at 4 levels: beyond the limit (≈ 0.26), but close enough that
/// the boundary-layer screen does not see it; the solvers' own checks must.
nlohmann::json square_case(const char* method) {
  return {{"mesh", {{"builtin", "square"}, {"size", 0.25}, {"refinements", 3}}},
          {"material", {{"mu", 1}, {"lambda", 1}}},
          {"boundary",
           {{"top", {{"type", "dirichlet"}, {"displacement", {0, -0.05}}}},
            {"bottom",
             {{"type", "contact"},
              {"obstacle", {{"type", "plane"}, {"point", {0, 0}}, {"normal", {0, 1}}}}}}}},
          {"weights", {{"c3", 0.35}}},
          {"solver", {{"method", method}}}};
}

/// Runs the case and expects it refused with one error at /weights that names c3 = 0.35.
void expect_weights_refused(const nlohmann::json& j, const std::string& what) {
  const CaseReadResult read = read_case(j);
  ASSERT_TRUE(read.errors.empty()) << what;
  try {
    run_case(*read.spec);
    ADD_FAILURE() << what << ": indefinite weights were accepted";
  } catch (const CaseException& e) {
    ASSERT_EQ(e.errors().size(), 1u) << what;
    EXPECT_EQ(e.errors()[0].pointer, "/weights") << what;
    EXPECT_NE(e.errors()[0].detail.find("c3 = 0.35"), std::string::npos) << e.errors()[0].detail;
  }
}

TEST(IndefiniteSystem, TheCaseLayerReportsTheWeightsWhenASolverFindsIt) {
  ProblemData<2> d = testing::flat_square(1.0);
  d.weights.c3 = 0.35;
  const Discretization<2> disc(build_mesh_hierarchy(make_square({.size = 0.25}), 3), d);
  ASSERT_TRUE(contact_layer_is_definite(disc.finest_space(), disc.problem().qp))
      << "the screen catches c3 = 0.35: this test would not reach the solvers";
  for (const char* method : {"mmg", "tnnmg", "pdas"})
    expect_weights_refused(square_case(method), method);
}

// An adaptive case checks the definiteness on its first step only (SolverOptions::
// check_definiteness): indefinite weights are refused there, before any refinement.
TEST(IndefiniteSystem, AnAdaptiveCaseIsRefusedOnItsFirstStep) {
  nlohmann::json j = square_case("mmg");
  j["adaptivity"] = {{"steps", 2}};
  expect_weights_refused(j, "adaptive mmg");
}

}  // namespace
}  // namespace fosls
