// The monotone multilevel method on the order-2 space (docs/method.md §10): the lowest-order
// hierarchy with the P2 × RT1 level on top. J never increases after any smoother sweep or coarse
// correction, every iterate is feasible, the cycle converges in as few iterations as at the
// lowest order, and the solve agrees with pdas on the same discrete problem.
#include <gtest/gtest.h>

#include <limits>

#include "../sweep_checks.hpp"
#include "assembly/p2_rt1_assembler.hpp"
#include "assembly/p2_rt1_level.hpp"
#include "contact_problems.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Case {
  const char* name;
  bool hertz;
  double lambda;
};

class Order2Multilevel : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    const Case& c = GetParam();
    const ProblemData<2> data =
        c.hertz ? testing::hertz(c.lambda) : testing::signorini_square(c.lambda);
    lowest_ = std::make_unique<Discretization>(
        build_mesh_hierarchy(c.hertz ? make_hertz({.size = 0.1}) : make_square({.size = 0.25}), 2),
        data);
    space_ = std::make_unique<P2Rt1Space>(lowest_->meshes().finest(), data.boundary_roles());
    assembler_ = std::make_unique<P2Rt1Assembler>(*space_, lowest_->data());
    problem_ = assembler_->assemble_system();
    hierarchy_ = lowest_->build_level_hierarchy();
    hierarchy_.levels.push_back(order2_level(lowest_->finest_space(), *space_));
  }
  std::unique_ptr<Discretization> lowest_;
  std::unique_ptr<P2Rt1Space> space_;
  std::unique_ptr<P2Rt1Assembler> assembler_;
  AssembledProblem problem_;
  LevelHierarchy hierarchy_;
};

TEST_P(Order2Multilevel, HierarchyIsConsistentAndTheEmbeddingExact) {
  EXPECT_EQ(hierarchy_inconsistency(hierarchy_, problem_.qp.size()), "");
  // A lowest-order field and its embedding have the same c1 and c2 terms (the spaces are nested
  // and both assemblies integrate exactly): the embedding is the identity on functions.
  const FoslsSpace<2>& lowest = lowest_->finest_space();
  Vector x1 = Vector::Zero(lowest.num_dofs());
  for (int d = 0; d < lowest.num_dofs(); ++d) x1[d] = std::sin(0.37 * d + 0.1);
  const Eigen::SparseMatrix<double> embed =
      space_->rotation().transpose() * order2_embedding(lowest, *space_) * lowest.rotation();
  const FunctionalParts p1 = lowest_->assembler().functional(x1);
  const FunctionalParts p2 = assembler_->functional(embed * x1);
  EXPECT_NEAR(p2.momentum, p1.momentum, 1e-10 * p1.momentum);
  EXPECT_NEAR(p2.constitutive, p1.constitutive, 1e-10 * p1.constitutive);
  if (GetParam().hertz) return;
  // The contact term's bilinear part ⟨u·d, σ_nn⟩ too on straight edges (the gap is interpolated
  // quadratically at order 2, so compare the change when u doubles). On an arc the order-2
  // midpoint constrains along its own normal, not the mean of the vertex normals.
  Vector x1u = x1;
  for (int v = 0; v < lowest.mesh().num_vertices(); ++v)
    for (int c = 0; c < 2; ++c) x1u[lowest.u_dof(v, c)] *= 2.0;
  const double bilinear1 = lowest_->assembler().functional(x1u).contact - p1.contact;
  const double bilinear2 = assembler_->functional(embed * x1u).contact - p2.contact;
  EXPECT_NEAR(bilinear2, bilinear1, 1e-10 * std::abs(bilinear1));
}

TEST_P(Order2Multilevel, EnergyNeverIncreasesAndIteratesStayFeasible) {
  const BoxQp& qp = problem_.qp;
  MultilevelCycle cycle(qp, hierarchy_, MultilevelOptions{});
  Vector x = Vector::Zero(qp.size());
  qp.clip(x);
  Vector r = qp.b - qp.A * x;
  int checks = 0;
  testing::check_every_sweep(cycle, qp, x, checks);
  const double initial_kkt = qp.kkt_residual(x, r);
  int iterations = 0;
  for (; iterations < 200 && qp.kkt_residual(x, r) > 1e-8 * initial_kkt; ++iterations) {
    cycle.nonlinear_cycle(x, r);
    r = qp.b - qp.A * x;
  }
  EXPECT_LE(qp.kkt_residual(x, r), 1e-8 * initial_kkt);
  EXPECT_GE(checks, 3 * iterations);
}

TEST_P(Order2Multilevel, MmgAgreesWithPdasInFewIterations) {
  BoxQp& qp = problem_.qp;
  SolverOptions options;
  options.tolerance = 1e-8;  // the shipped examples' tolerance
  Vector x = Vector::Zero(qp.size());
  const SolverReport mmg = solve_box_qp(qp, hierarchy_, options, {}, x);
  EXPECT_TRUE(mmg.converged);
  EXPECT_LE(mmg.iterations, 15);  // the default method (nested, accelerated) on the lowest order
  options.method = SolverMethod::kPdas;
  Vector y = Vector::Zero(qp.size());
  const SolverReport pdas = solve_box_qp(qp, hierarchy_, options, {}, y);
  EXPECT_TRUE(pdas.converged);
  const Point f_mmg = assembler_->contact_force(assembler_->full_vector(problem_, x));
  const Point f_pdas = assembler_->contact_force(assembler_->full_vector(problem_, y));
  EXPECT_GT(f_pdas.norm(), 0.0);
  EXPECT_NEAR(f_mmg.y(), f_pdas.y(), 1e-6 * std::abs(f_pdas.y()));
  std::printf("%s: mmg %d iterations, nested %zu levels; force %.10g (pdas %.10g)\n",
              GetParam().name, mmg.iterations, mmg.nested_iterations.size(), f_mmg.y(), f_pdas.y());
}

INSTANTIATE_TEST_SUITE_P(Benchmarks, Order2Multilevel,
                         ::testing::Values(Case{"square_lambda1", false, 1.0},
                                           Case{"square_lambdainf", false, kInf},
                                           Case{"hertz_lambda1", true, 1.0},
                                           Case{"hertz_lambdainf", true, kInf}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace fosls
