// mesh.order: 1 or 2, and what the order-2 space is not built for yet, refused at /mesh/order
// with the other field named (docs/case-format.md, "Order 2").
#include <gtest/gtest.h>

#include "../case_errors.hpp"
#include "../shipped_example.hpp"
#include "case/admission/resource_estimate.hpp"

namespace fosls {
namespace {

using nlohmann::json;
using testing::has_error;

json square_of_order(int order) {
  json j = testing::load_shipped_example("signorini_square");
  j["mesh"]["order"] = order;
  return j;
}

TEST(MeshOrder, OneAndTwoAreReadAndOtherValuesRefused) {
  EXPECT_EQ(read_case(testing::load_shipped_example("signorini_square")).spec->mesh.order, 1);
  EXPECT_EQ(read_case(square_of_order(2)).spec->mesh.order, 2);
  EXPECT_TRUE(has_error(read_case(square_of_order(3)), "/mesh/order", ""));
  EXPECT_TRUE(has_error(read_case(square_of_order(0)), "/mesh/order", ""));
  json text = square_of_order(2);
  text["mesh"]["order"] = "2";
  EXPECT_TRUE(has_error(read_case(text), "/mesh/order", ""));
}

TEST(MeshOrder, OrderTwoRefusesWhatItDoesNotSupportNamingIt) {
  json friction = square_of_order(2);
  friction["boundary"]["bottom"]["friction"] = {{"coefficient", 0.3}};
  EXPECT_TRUE(has_error(read_case(friction), "/mesh/order", "boundary.bottom has friction"));

  json oblique = testing::load_shipped_example("hertz");
  oblique["mesh"]["order"] = 2;
  oblique["boundary"]["contact"]["direction"] = "obstacle_normal";
  EXPECT_TRUE(has_error(read_case(oblique), "/mesh/order", "obstacle_normal"));

  json adaptive = square_of_order(2);
  adaptive["adaptivity"] = {{"steps", 2}};
  EXPECT_TRUE(has_error(read_case(adaptive), "/mesh/order", "adaptivity"));

  json tnnmg = square_of_order(2);
  tnnmg["solver"]["method"] = "tnnmg";
  EXPECT_TRUE(has_error(read_case(tnnmg), "/mesh/order", "mmg or pdas"));

  json pdas = square_of_order(2);
  pdas["solver"]["method"] = "pdas";
  EXPECT_TRUE(read_case(pdas).errors.empty());
  json accuracy = square_of_order(2);
  accuracy["accuracy"] = {{"force", 1e-3}};
  EXPECT_TRUE(read_case(accuracy).errors.empty());
}

TEST(MeshOrder, OrderTwoCountsItsDofs) {
  // One triangle (3 vertices, 3 edges): order 1 has 2·3 + 2·3 DOFs, order 2 2·3 + 6·3 + 4.
  EXPECT_EQ(unknowns_after_refinement(1LL, 3LL, 3LL, 0, 1), 12);
  EXPECT_EQ(unknowns_after_refinement(1LL, 3LL, 3LL, 0, 2), 28);
  // Refined once: 6 vertices, 9 edges, 4 triangles.
  EXPECT_EQ(unknowns_after_refinement(1LL, 3LL, 3LL, 1, 2), 2 * 6 + 6 * 9 + 4 * 4);
  const ResourceEstimate one = estimate_resources({100000, 100, true, 1, 2}, SolverMethod::kMmg);
  const ResourceEstimate two = estimate_resources({100000, 100, true, 2, 2}, SolverMethod::kMmg);
  EXPECT_GT(two.memory_bytes, one.memory_bytes);
  EXPECT_EQ(two.order, 2);
}

}  // namespace
}  // namespace fosls
