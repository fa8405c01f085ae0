// A 3D case through run_case is the same problem in any unit of length (mesh/length_scale.hpp,
// as 2D's length_scale_test): the half ball of hertz_3d in millimetres, metres and micrometres
// gives the same force over L² (to 10⁻⁶) and the same iterations to within two. Before the c1 term
// was weighted by ℓ² in 3D, the ball gave 667 N in mm, 819 N (not converged) in m and no result in
// µm (issue 47). And solver.time_limit_s stops a 3D run, as in 2D.
#include <gtest/gtest.h>

#include <cmath>

#include "../case3d_runs.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"
#include "core/deadline.hpp"

namespace fosls {
namespace {

/// hertz_3d at refinements 1 with every length multiplied by `scale`.
nlohmann::json ball_scaled(double scale) {
  nlohmann::json j = testing::hertz_3d(1);
  j["mesh"]["builtin"]["radius"] = scale;
  j["boundary"]["top"]["displacement"] = {0.0, 0.0, -0.01 * scale};
  j["boundary"]["contact"]["point"] = {0.0, 0.0, -scale};
  return testing::run_3d(j);
}

TEST(Case3dUnits, TheBallIsTheSameProblemInMillimetresMetresAndMicrometres) {
  const nlohmann::json mm = ball_scaled(1.0);
  ASSERT_TRUE(mm["converged"].get<bool>());
  const double f_mm = mm["contact"]["force"][2].get<double>();
  ASSERT_GT(f_mm, 0.0);
  for (const double scale : {1e-3, 1e3}) {
    const nlohmann::json r = ball_scaled(scale);
    ASSERT_TRUE(r["converged"].get<bool>()) << scale;
    EXPECT_NEAR(r["contact"]["force"][2].get<double>() / (scale * scale), f_mm, 1e-6 * f_mm)
        << scale;
    // Measured: 25 iterations in mm and m, 23 in µm (the relative KKT residual crosses the
    // tolerance one sweep apart); 2D's length_scale_test allows the same +-2.
    EXPECT_LE(std::abs(r["iterations"].get<int>() - mm["iterations"].get<int>()), 2) << scale;
  }
}

TEST(Case3dUnits, AModulusImplausibleForTheDeclaredUnitsIsWarnedAbout) {
  nlohmann::json j = testing::hertz_3d(0);
  j["units"] = {{"length", "m"}, {"stress", "Pa"}};  // a ball of 1 m with E of about 2.5 Pa
  const nlohmann::json r = testing::run_3d(j);
  bool warned = false;
  for (const auto& w : r["warning_details"]) warned |= w["code"] == "units_implausible";
  EXPECT_TRUE(warned) << r["warning_details"].dump();
  EXPECT_TRUE(r["review_required"].get<bool>());
  EXPECT_TRUE(testing::warnings_but_resolution(testing::run_3d(testing::hertz_3d(0))).empty());
}

TEST(Case3dUnits, ATimeLimitStopsA3dRunNamingTheLimit) {
  nlohmann::json j = testing::hertz_3d(2);
  j["solver"]["time_limit_s"] = 1e-3;
  const CaseReadResult read = read_case(j);
  ASSERT_TRUE(read.spec) << read.errors[0].detail;
  RunControl control;
  control.want_vtu = false;
  try {
    run_case(*read.spec, control);
    FAIL() << "a 1 ms limit did not stop hertz_3d at refinements 2";
  } catch (const TimeLimitReached& e) {
    EXPECT_NE(std::string(e.what()).find("time_limit_s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fosls
