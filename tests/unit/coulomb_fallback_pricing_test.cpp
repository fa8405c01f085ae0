// Admission prices Coulomb's fallback (issue 49): mmg on a Coulomb problem of at most
// kFallbackMaxUnknowns unknowns may hand a stalled solve to pdas, which factorises the whole
// problem, so its estimate includes pdas's factorisation there, and a job whose budget does not
// hold it is refused up front (docs/case-format.md, "Resources").
#include <gtest/gtest.h>

#include "../shipped_example.hpp"
#include "case/admission/case_admission.hpp"
#include "case/admission/resource_estimate.hpp"
#include "solvers/coulomb_fallback.hpp"

namespace fosls {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;

ProblemCount count_of(long long unknowns, bool coulomb) {
  return {.unknowns = unknowns, .coarse_unknowns = 300, .exact = true, .coulomb = coulomb};
}

double mmg_bytes(long long unknowns, bool coulomb) {
  return estimate_resources(count_of(unknowns, coulomb), SolverMethod::kMmg).memory_bytes;
}

TEST(CoulombFallbackPricing, CoulombCostsMoreWhereTheFallbackCanRunAndTheSameAbove) {
  for (long long n : {20'000LL, 100'000LL, static_cast<long long>(kFallbackMaxUnknowns)})
    EXPECT_GT(mmg_bytes(n, true), mmg_bytes(n, false) + 0.5 * n * 766) << n;
  for (long long n : {static_cast<long long>(kFallbackMaxUnknowns) + 1, 434'816LL, 1'737'344LL})
    EXPECT_EQ(mmg_bytes(n, true), mmg_bytes(n, false)) << n;
}

TEST(CoulombFallbackPricing, OnlyMmgIn2dFallsBack) {
  const ProblemCount coulomb = count_of(100'000, true), none = count_of(100'000, false);
  EXPECT_EQ(estimate_resources(coulomb, SolverMethod::kPdas).memory_bytes,
            estimate_resources(none, SolverMethod::kPdas).memory_bytes);
  ProblemCount in_3d = coulomb, in_3d_none = none;
  in_3d.dimension = in_3d_none.dimension = 3;
  EXPECT_EQ(estimate_resources(in_3d, SolverMethod::kMmg).memory_bytes,
            estimate_resources(in_3d_none, SolverMethod::kMmg).memory_bytes);
  EXPECT_EQ(fallback_bytes(coulomb, SolverMethod::kPdas), 0.0);
}

// Peaks measured by tests/benchmarks/memory_calibration.py --coulomb on the robustness cases
// where mmg stalls and pdas takes over (docs/case-format.md, "Resources"): the estimate covers
// each, without a large excess.
TEST(CoulombFallbackPricing, TheMeasuredFallbackPeaksAreCovered) {
  struct Row {
    long long unknowns;
    double fallback_mib;
  };
  for (const Row& r : {Row{78'994, 152}, Row{63'010, 143}}) {
    const double estimate = mmg_bytes(r.unknowns, true) / kMiB;
    EXPECT_GE(estimate, r.fallback_mib) << r.unknowns;
    EXPECT_LE(estimate, 2.0 * r.fallback_mib) << r.unknowns;
  }
}

// The shipped cattaneo_mindlin at refinements 4 (about 115 000 unknowns, estimated before
// meshing) under a budget that holds its mmg solve but not the fallback's factorisation: refused
// at /mesh/refinements, saying why; the same case without friction is admitted.
TEST(CoulombFallbackPricing, ABudgetWithoutRoomForTheFallbackRefusesTheCase) {
  nlohmann::json j = testing::load_shipped_example("cattaneo_mindlin");
  j["mesh"]["refinements"] = 4;
  CaseReadOptions options;
  options.limits.max_memory_bytes = 200 * kMiB;
  const CaseAdmission coulomb = admit_case(j, options);
  ASSERT_EQ(coulomb.errors.size(), 1u);
  EXPECT_EQ(coulomb.errors[0].pointer, "/mesh/refinements");
  EXPECT_NE(coulomb.errors[0].detail.find("Coulomb's fallback to pdas"), std::string::npos)
      << coulomb.errors[0].detail;
  // tnnmg would fit the budget but has no friction: the advice does not offer it.
  EXPECT_EQ(coulomb.errors[0].detail.find("tnnmg"), std::string::npos) << coulomb.errors[0].detail;
  for (auto& [name, condition] : j["boundary"].items()) condition.erase("friction");
  const CaseAdmission frictionless = admit_case(j, options);
  EXPECT_TRUE(frictionless.errors.empty());
  ASSERT_TRUE(frictionless.estimate && coulomb.estimate);
  EXPECT_LT(frictionless.estimate->memory_bytes, options.limits.max_memory_bytes);
  EXPECT_GT(coulomb.estimate->memory_bytes, options.limits.max_memory_bytes);
  // Tresca never falls back: priced as frictionless, bit for bit.
  j["boundary"]["contact"]["friction"] = {{"bound", 0.01}};
  const CaseAdmission tresca = admit_case(j, options);
  EXPECT_TRUE(tresca.errors.empty());
  ASSERT_TRUE(tresca.estimate);
  EXPECT_EQ(tresca.estimate->memory_bytes, frictionless.estimate->memory_bytes);
}

}  // namespace
}  // namespace fosls
