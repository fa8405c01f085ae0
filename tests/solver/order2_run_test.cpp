// mesh.order 2 as a user runs it (docs/case-format.md, "Order 2"): the result counts the
// order-2 DOFs, mmg and pdas agree, the force is far closer to the reference than the lowest
// order's on the next finer mesh, and the accuracy loop refines order-2 levels.
#include <gtest/gtest.h>

#include <cmath>

#include "../shipped_example.hpp"
#include "../solved_case.hpp"
#include "case/admission/resource_estimate.hpp"

namespace fosls {
namespace {

using nlohmann::json;

constexpr double kSquareReference = 0.083366;  // λ = 1 (docs/validation.md §12)

json square(int order, int refinements, const char* method = "mmg") {
  json j = testing::load_shipped_example("signorini_square");
  j["mesh"]["order"] = order;
  j["mesh"]["refinements"] = refinements;
  j["solver"]["method"] = method;
  return j;
}

double relative_error(const json& r) {
  return std::abs(r["contact"]["force"][1].get<double>() - kSquareReference) / kSquareReference;
}

TEST(Order2Run, ResultCountsTheOrderTwoSpaceAndMmgAgreesWithPdas) {
  const json mmg = testing::solved_case(square(2, 2));
  const json pdas = testing::solved_case(square(2, 2, "pdas"));
  ASSERT_TRUE(mmg["converged"].get<bool>());
  ASSERT_TRUE(pdas["converged"].get<bool>());
  EXPECT_EQ(mmg["mesh"]["order"], 2);
  // The square of size 0.25 is 4 × 4 × 2 triangles (25 vertices, 56 edges), refined twice.
  EXPECT_EQ(mmg["dofs_total"].get<long long>(), unknowns_after_refinement(32LL, 56LL, 25LL, 2, 2));
  EXPECT_LT(mmg["dofs"].get<long long>(), mmg["dofs_total"].get<long long>());
  EXPECT_LE(mmg["iterations"].get<int>(), 15);
  const double f_mmg = mmg["contact"]["force"][1].get<double>();
  const double f_pdas = pdas["contact"]["force"][1].get<double>();
  EXPECT_NEAR(f_mmg, f_pdas, 1e-6 * f_pdas);
  EXPECT_GT(mmg["contact"]["zone"]["edges"].get<int>(), 0);
}

TEST(Order2Run, ForceBeatsTheLowestOrderOnTheNextFinerMesh) {
  const double order2 = relative_error(testing::solved_case(square(2, 3)));
  const double order1 = relative_error(testing::solved_case(square(1, 4)));
  std::printf("square λ = 1: order 2 at refinements 3 %.4f %%, order 1 at refinements 4 %.4f %%\n",
              100 * order2, 100 * order1);
  EXPECT_LT(order2, order1 / 3);  // measured 0.030 % against 0.250 % (docs/validation.md §15)
}

TEST(Order2Run, AccuracyLoopRefinesOrderTwoLevels) {
  json j = square(2, 1);
  j["accuracy"] = {{"force", 2e-3}};
  const json r = testing::solved_case(j);
  const json& a = r["accuracy"];
  EXPECT_TRUE(a["reached"].get<bool>()) << a["stop_message"];
  const json& steps = a["steps"];
  ASSERT_GE(steps.size(), 2u);
  for (const json& s : steps) {
    const int refinements = s["refinements"].get<int>();
    EXPECT_EQ(s["dofs_total"].get<long long>(),
              unknowns_after_refinement(32LL, 56LL, 25LL, refinements, 2));
  }
  EXPECT_LE(relative_error(r), 2 * 2e-3);
}

}  // namespace
}  // namespace fosls
