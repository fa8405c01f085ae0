// The computed limit of the contact weight c3 (assembly/contact_weight.hpp) is where the FOSLS
// matrix stops being positive definite, and "auto" is the default that a case records.
#include <gtest/gtest.h>

#include <Eigen/CholmodSupport>
#include <limits>

#include "../solver/contact_problems.hpp"
#include "assembly/contact_weight.hpp"
#include "assembly/discretization.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool is_definite(const MeshHierarchy& meshes, ProblemData<2> data, double c3) {
  data.weights.c3 = c3;
  Discretization<2> disc(meshes, std::move(data));
  Eigen::CholmodSupernodalLLT<SparseMatrix> llt(disc.problem().qp.A);
  return llt.info() == Eigen::Success;
}

// The limit is computed on the finest level here (all levels are below kWeightLevelDofs), so it
// must separate definite from indefinite on that level's own matrix: 2 % either side.
TEST(ContactWeight, LimitSeparatesDefiniteFromIndefiniteMatrices) {
  for (double lambda : {1.0, kInf}) {
    const MeshHierarchy square = build_mesh_hierarchy(make_square({.size = 0.25}), 2);
    const MeshHierarchy hertz = build_mesh_hierarchy(make_hertz({}), 1);
    for (const auto& [meshes, data] : {std::pair{&square, testing::signorini_square(lambda)},
                                       std::pair{&hertz, testing::hertz(lambda)}}) {
      const ContactWeightLimit limit = contact_weight_limit(*meshes, data);
      ASSERT_EQ(limit.level, meshes->num_levels() - 1);
      ASSERT_LT(limit.limit, kInf);
      EXPECT_TRUE(is_definite(*meshes, data, 0.98 * limit.limit)) << lambda << " " << limit.limit;
      EXPECT_FALSE(is_definite(*meshes, data, 1.02 * limit.limit)) << lambda << " " << limit.limit;
      EXPECT_LT(limit.lanczos_steps, 80) << "Lanczos did not converge";
    }
  }
}

TEST(ContactWeight, RuleIsHalfTheLimitAtMostTheOldDefault) {
  EXPECT_DOUBLE_EQ(automatic_contact_weight({.limit = 0.04}), 0.02);
  EXPECT_DOUBLE_EQ(automatic_contact_weight({.limit = 0.45}), 0.1);
  EXPECT_DOUBLE_EQ(automatic_contact_weight({.limit = kInf}), 0.1);
}

nlohmann::json square_case() {
  return {{"mesh", {{"builtin", "square"}, {"size", 0.25}, {"refinements", 2}}},
          {"material", {{"mu", 1}, {"lambda", 1}}},
          {"boundary",
           {{"top", {{"type", "dirichlet"}, {"displacement", {0, -0.05}}}},
            {"bottom",
             {{"type", "contact"},
              {"obstacle", {{"type", "plane"}, {"point", {0, 0}}, {"normal", {0, 1}}}}}}}}};
}

TEST(ContactWeight, AutoIsTheDefaultAndTheResultRecordsIt) {
  const CaseReadResult read = read_case(square_case());
  ASSERT_TRUE(read.errors.empty());
  EXPECT_TRUE(read.spec->weights.c3_auto);
  const nlohmann::json w = run_case(*read.spec).result["weights"];
  EXPECT_EQ(w["c3_rule"], "auto");
  ASSERT_TRUE(w["c3_limit"].is_number());
  EXPECT_DOUBLE_EQ(w["c3"].get<double>(), std::min(0.1, 0.5 * w["c3_limit"].get<double>()));
}

TEST(ContactWeight, GivenWeightIsKeptAndARefusalNamesTheLimit) {
  nlohmann::json j = square_case();
  j["weights"] = {{"c3", 0.05}};
  nlohmann::json w = run_case(*read_case(j).spec).result["weights"];
  EXPECT_EQ(w["c3_rule"], "given");
  EXPECT_DOUBLE_EQ(w["c3"].get<double>(), 0.05);
  EXPECT_TRUE(w["c3_limit"].is_null());
  j["weights"] = {{"c3", 1.0}};
  try {
    run_case(*read_case(j).spec);
    FAIL() << "c3 = 1 was accepted";
  } catch (const CaseException& e) {
    EXPECT_NE(e.errors()[0].detail.find("must stay below about"), std::string::npos)
        << e.errors()[0].detail;
  }
}

}  // namespace
}  // namespace fosls
