// The 3D contact zone's extent (case/result/contact_faces.hpp): its area with the front located
// within the faces, and the whole zone's radius of a model cut at symmetry planes.
#include <gtest/gtest.h>

#include <cmath>

#include "../case3d_runs.hpp"

namespace fosls::testing {
namespace {

nlohmann::json quarter_ball(int refinements) {
  nlohmann::json j = load_shipped_example("3d/hertz_3d_quarter");
  j["mesh"]["refinements"] = refinements;
  return j;
}

/// The quarter ball at refinements 2, solved once for the tests that read it.
const nlohmann::json& quarter_r2() {
  static const nlohmann::json result = run_3d(quarter_ball(2));
  return result;
}

TEST(ContactZone3d, AQuarterModelGivesTheWholeBallsRadius) {
  const nlohmann::json half = run_3d(hertz_3d(2));
  const nlohmann::json& quarter = quarter_r2();
  const nlohmann::json& hz = half["contact"]["zone"];
  const nlohmann::json& qz = quarter["contact"]["zone"];
  EXPECT_EQ(hz["symmetry_planes"], 0);
  EXPECT_EQ(qz["symmetry_planes"], 2);
  // The same problem: a quarter of the force and of the area, the same radius (measured 0.1083
  // and 0.1100: the two meshes are not mirror images of each other).
  EXPECT_NEAR(4.0 * quarter["contact"]["force"][2].get<double>() /
                  half["contact"]["force"][2].get<double>(),
              1.0, 1e-3);
  EXPECT_NEAR(qz["radius"].get<double>() / hz["radius"].get<double>(), 1.0, 0.03);
  EXPECT_NEAR(4.0 * qz["area"].get<double>() / hz["area"].get<double>(), 1.0, 0.07);
}

/// The line's steps tile one interval, in order; its ends.
std::pair<double, double> tiled_range(const nlohmann::json& line) {
  const auto& from = line["from"];
  const auto& to = line["to"];
  EXPECT_EQ(from.size(), to.size());
  EXPECT_EQ(from.size(), line["pressure"].size());
  for (std::size_t k = 0; k + 1 < from.size(); ++k)
    EXPECT_NEAR(to[k].get<double>(), from[k + 1].get<double>(), 1e-9) << k;
  return {from.front().get<double>(), to.back().get<double>()};
}

TEST(ContactZone3d, ThePressureLineRunsThroughTheCentreOfTheWholeZone) {
  const nlohmann::json& quarter = quarter_r2();
  const nlohmann::json& line = quarter["contact"]["line"];
  // The quarter's centre of pressure, mirrored across its two symmetry planes, is the pole.
  EXPECT_NEAR(line["point"][0].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(line["point"][1].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(line["direction"][0].get<double>(), 1.0, 1e-12);
  const auto [lo, hi] = tiled_range(line);
  EXPECT_NEAR(lo, 0.0, 1e-9);  // from the pole outwards, to the contact group's rim
  const auto& p = line["pressure"];
  EXPECT_GT(p.front().get<double>(), 0.8 * quarter["contact"]["max_pressure"].get<double>());
  EXPECT_EQ(p.back().get<double>(), 0.0);
  EXPECT_GT(hi, quarter["contact"]["zone"]["radius"].get<double>());
}

TEST(ContactZone3d, NoContactHasNoLine) {
  nlohmann::json j = hertz_3d(0);
  j["boundary"]["top"]["displacement"] = {0, 0, 0.01};  // pulled away
  EXPECT_TRUE(run_3d(j)["contact"]["line"].is_null());
}

TEST(ContactZone3d, TheLocatedFrontLiesWithinTheLoadedFaces) {
  // Refinements 1: 24 faces in contact, their area 0.0897 and the located front's 0.0447
  // (measured), a front well inside the outermost faces of so coarse a zone.
  const nlohmann::json r = run_3d(hertz_3d(1));
  const double area = r["contact"]["zone"]["area"].get<double>();
  EXPECT_GT(area, 0.4 * r["contact"]["area"].get<double>());
  EXPECT_LT(area, r["contact"]["area"].get<double>());
  EXPECT_NEAR(r["contact"]["zone"]["radius"].get<double>(), std::sqrt(area / M_PI), 1e-12);
}

TEST(ContactZone3d, OnlyARollerAtZeroIsASymmetryPlane) {
  nlohmann::json j = quarter_ball(1);
  j["boundary"]["symmetry_x"]["displacement"] = {1e-4, nullptr, nullptr};  // pushes the body
  EXPECT_EQ(run_3d(j)["contact"]["zone"]["symmetry_planes"], 1);
  j = quarter_ball(1);
  j["boundary"]["symmetry_y"]["displacement"] = {0, 0, nullptr};  // holds two components
  EXPECT_EQ(run_3d(j)["contact"]["zone"]["symmetry_planes"], 1);
}

}  // namespace
}  // namespace fosls::testing
