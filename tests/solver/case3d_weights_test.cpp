// c3 "auto" in 3D, as in 2D (assembly/contact_weight.hpp): the contact weight is chosen from the
// definiteness limit c3* of the mesh. The fixed 0.1 that 3D used before makes the matrix of an
// incompressible slab on a plane indefinite; "auto" (the default now) solves it.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "../case3d_runs.hpp"

namespace fosls {
namespace {

using nlohmann::json;

/// A 4 × 4 × 0.25 slab, incompressible, pressed by its top onto the plane its bottom touches.
json incompressible_slab() {
  return {{"dimension", 3},
          {"mesh",
           {{"builtin", {{"name", "box"}, {"lengths", {4, 4, 0.25}}, {"cells", {8, 8, 1}}}},
            {"refinements", 1}}},
          {"material", {{"mu", 1}, {"lambda", "inf"}}},
          {"boundary",
           {{"top", {{"type", "dirichlet"}, {"displacement", {0, 0, -0.001}}}},
            {"bottom", {{"type", "contact"}, {"point", {0, 0, 0}}, {"normal", {0, 0, 1}}}}}}};
}

TEST(Case3dWeights, AnIncompressibleSlabSolvesWithTheChosenC3AndNotWithTheOldFixedOne) {
  const json chosen = testing::run_3d(incompressible_slab());
  ASSERT_TRUE(chosen["converged"].get<bool>());
  const json& w = chosen["weights"];
  EXPECT_EQ(w["c3_rule"], "auto");
  const double limit = w["c3_limit"].get<double>();
  EXPECT_LT(limit, 0.2);  // below twice the old fixed weight: 0.1 is past the limit
  EXPECT_DOUBLE_EQ(w["c3"].get<double>(), 0.5 * limit);
  EXPECT_GT(chosen["contact"]["force"][2].get<double>(), 0.0);
  EXPECT_LE(chosen["iterations"].get<int>(), 40);

  json fixed = incompressible_slab();
  fixed["weights"]["c3"] = 0.1;
  const CaseError e = testing::run_3d_problem(fixed);
  EXPECT_EQ(e.pointer, "/weights");
  EXPECT_NE(e.detail.find("\"auto\""), std::string::npos) << e.detail;
}

TEST(Case3dWeights, HertzKeepsTheWeightItHadSinceItsLimitIsFarAbove) {
  const json r = testing::run_3d(testing::hertz_3d(1));
  EXPECT_EQ(r["weights"]["c3_rule"], "auto");
  EXPECT_GT(r["weights"]["c3_limit"].get<double>(), 0.2);
  EXPECT_DOUBLE_EQ(r["weights"]["c3"].get<double>(), 0.1);
}

}  // namespace
}  // namespace fosls
