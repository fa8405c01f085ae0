// c3 "auto" with friction where the contact boundary is most of the body's boundary: the wedge
// pressed tip first (tests/robustness/cases/wedge_tip.json) leaves σ_nn and σ_nt free on both
// of its long sides, A0 is then too near singular for the Lanczos iteration, which broke down
// and reported no limit (c3 = 0.1, an indefinite matrix, the case refused). The limit now comes
// from the definiteness of A0 + c3 B itself, and the case is solved, mmg equal to pdas.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "../solved_case.hpp"

namespace fosls {
namespace {

using nlohmann::json;

json frictional_wedge(const std::string& method) {
  std::ifstream in(std::string(FOSLS_SOURCE_DIR) + "/tests/robustness/cases/wedge_tip.json");
  std::stringstream text;
  text << in.rdbuf();
  json j = json::parse(text.str());
  j["boundary"]["contact"]["friction"] = {{"coefficient", 0.3}};
  j["solver"] = {{"method", method}};
  return j;
}

TEST(FrictionWeight, AutoC3IsFiniteWhereLanczosBreaksDownAndTheCaseSolves) {
  const json mmg = testing::solved_case(frictional_wedge("mmg"));
  ASSERT_TRUE(mmg.contains("weights")) << mmg.dump().substr(0, 400);
  const double limit = mmg["weights"]["c3_limit"].get<double>();
  EXPECT_TRUE(std::isfinite(limit));
  EXPECT_LT(limit, 0.05);  // far below the frictionless 0.108: the tangential couplings
  EXPECT_NEAR(mmg["weights"]["c3"].get<double>(), 0.5 * limit, 1e-12);
  EXPECT_TRUE(mmg["converged"].get<bool>());
  const json pdas = testing::solved_case(frictional_wedge("pdas"));
  ASSERT_TRUE(pdas["converged"].get<bool>());
  for (int c = 0; c < 2; ++c)
    EXPECT_NEAR(mmg["contact"]["force"][c].get<double>(), pdas["contact"]["force"][c].get<double>(),
                1e-6 * pdas["contact"]["force"][1].get<double>());
}

}  // namespace
}  // namespace fosls
