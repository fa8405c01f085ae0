// The rigid obstacles of 3D contact cases (case/format/obstacle_section.cpp): a plane given in
// either form, a sphere and a gap function of x, y and z, each checked against an exact or an
// independent answer; and every problem of an obstacle named by its field.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "../case3d_runs.hpp"
#include "case/format/case_error.hpp"
#include "case/format/case_reader.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;

using testing::case3d_problems;
using testing::hertz_3d;
using testing::run_3d;
using testing::run_3d_problem;

/// The unit box (ν = 0) pushed up by 0.01 from its bottom onto an obstacle above its top, which
/// touches it: the top face in contact.
json box_under(const json& obstacle, double nu = 0.0) {
  return {{"dimension", 3},
          {"mesh", {{"builtin", "box"}, {"refinements", 1}}},
          {"material", {{"E", 1}, {"nu", nu}}},
          {"boundary",
           {{"bottom", {{"type", "dirichlet"}, {"displacement", {0, 0, 0.01}}}},
            {"top", {{"type", "contact"}, {"obstacle", obstacle}}}}},
          {"solver", {{"tolerance", 1e-12}}}};
}

TEST(Case3dObstacles, APlaneGivenAsObstacleIsThePointAndNormalBitForBit) {
  const json short_form = run_3d(hertz_3d(1));
  json given = hertz_3d(1);
  json& contact = given["boundary"]["contact"];
  contact["obstacle"] = {{"type", "plane"}, {"point", contact["point"]}, {"normal", {0, 0, 2}}};
  contact.erase("point");
  contact.erase("normal");
  const json object_form = run_3d(given);
  EXPECT_EQ(object_form["contact"]["force"], short_form["contact"]["force"]);
  EXPECT_EQ(object_form["iterations"], short_form["iterations"]);
}

TEST(Case3dObstacles, AGapFunctionOfZIsThePlaneItDescribes) {
  // Above the unit box's top (z = 1, outward normal +z) the plane z = 1 is the gap g = 1 − z;
  // pushed up by 0.01 the box is uniaxially compressed: F = (0, 0, −0.01 E).
  const json plane =
      run_3d(box_under({{"type", "plane"}, {"point", {0, 0, 1}}, {"normal", {0, 0, -1}}}));
  const json gap = run_3d(box_under({{"type", "gap"}, {"g", "1 - z"}}));
  for (const json* r : {&plane, &gap}) {
    ASSERT_TRUE((*r)["converged"].get<bool>());
    EXPECT_NEAR((*r)["contact"]["force"][2].get<double>(), -0.01, 1e-8);
    EXPECT_EQ((*r)["contact"]["faces_in_contact"], (*r)["contact"]["faces"]);
  }
  EXPECT_NEAR(gap["contact"]["force"][2].get<double>(), plane["contact"]["force"][2].get<double>(),
              1e-12);
}

TEST(Case3dObstacles, ALargeSphereIsAlmostItsTangentPlane) {
  // A ball of radius 10⁶ touching the top at its centre: the gap along +z departs from the
  // plane's by at most r²/(2R) = 2.5·10⁻⁷ over the face, so the force is the plane's 0.01 E to
  // about 2.5·10⁻⁵ of it.
  const double R = 1e6;
  const json r =
      run_3d(box_under({{"type", "sphere"}, {"center", {0.5, 0.5, 1 + R}}, {"radius", R}}));
  ASSERT_TRUE(r["converged"].get<bool>());
  EXPECT_NEAR(r["contact"]["force"][2].get<double>() / -0.01, 1.0, 1e-4);
  EXPECT_TRUE(r["warning_details"].empty()) << r["warning_details"].dump();
}

TEST(Case3dObstacles, ASphereAndItsParaboloidPressTheBoxAlike) {
  // A ball of radius 10 touching the top of the 2 × 2 × 1 box at its centre, the box pushed up
  // by 0.01: Hertz's paraboloid 1 + r²/20 − z as a gap function departs from the sphere by
  // r⁴/(8R³) ≤ 8·10⁻⁶ within r = 0.5 of the axis, against the indentation 0.01, so the forces
  // agree to about 10⁻³; and mmg equals pdas. (The box is finite and coarse: its force is not
  // Hertz's.)
  auto box = [](const json& obstacle, const char* method) {
    json j = box_under(obstacle, 0.25);
    j["mesh"]["builtin"] = {{"name", "box"}, {"lengths", {2, 2, 1}}, {"cells", {4, 4, 2}}};
    j["solver"] = {{"method", method}, {"tolerance", 1e-10}};
    return run_3d(j);
  };
  const json ball = {{"type", "sphere"}, {"center", {1, 1, 11}}, {"radius", 10}};
  const json sphere = box(ball, "mmg");
  const json pdas = box(ball, "pdas");
  const json paraboloid =
      box({{"type", "gap"}, {"g", "1 + ((x - 1)^2 + (y - 1)^2) / 20 - z"}}, "mmg");
  const double f = sphere["contact"]["force"][2].get<double>();
  EXPECT_LT(f, 0.0);  // the ball pushes the body down
  EXPECT_NEAR(pdas["contact"]["force"][2].get<double>() / f, 1.0, 1e-6);
  EXPECT_NEAR(paraboloid["contact"]["force"][2].get<double>() / f, 1.0, 2e-3);
  EXPECT_NEAR(sphere["contact"]["force"][0].get<double>(), 0.0, 1e-8 * std::abs(f));
  EXPECT_LE(sphere["iterations"].get<int>(), 40);
  EXPECT_TRUE(testing::warnings_but_resolution(sphere).empty()) << sphere["warning_details"].dump();
}

TEST(Case3dObstacles, MovingTheObstacleDownIsPushingTheBodyUp) {
  // The top's faces are flat and their gap is taken along +z, so moving the plane or the ball
  // down by 0.01 onto a body at rest differs from pushing the body up by 0.01 by a rigid
  // translation: the same force, and no overlap warning (the displacement is the indentation).
  const json plane = {{"type", "plane"}, {"point", {0, 0, 1}}, {"normal", {0, 0, -1}}};
  const json ball = {{"type", "sphere"}, {"center", {1, 1, 11}}, {"radius", 10}};
  for (const json& obstacle : {plane, ball}) {
    json pushed = box_under(obstacle, 0.25);
    pushed["mesh"]["builtin"] = {{"name", "box"}, {"lengths", {2, 2, 1}}, {"cells", {4, 4, 2}}};
    json moved = pushed;
    moved["boundary"]["bottom"]["displacement"] = {0, 0, 0};
    moved["boundary"]["top"]["obstacle"]["displacement"] = {0, 0, -0.01};
    const json a = run_3d(pushed), b = run_3d(moved);
    const double f = a["contact"]["force"][2].get<double>();
    EXPECT_LT(f, 0.0);
    EXPECT_NEAR(b["contact"]["force"][2].get<double>() / f, 1.0, 1e-8) << obstacle.dump();
    EXPECT_TRUE(testing::warnings_but_resolution(b).empty()) << b["warning_details"].dump();
  }
}

TEST(Case3dObstacles, AMissedOrOverlappingSphereIsNamedInTheWarnings) {
  const json away =
      run_3d(box_under({{"type", "sphere"}, {"center", {0.5, 0.5, 2}}, {"radius", 0.5}}));
  ASSERT_EQ(away["warning_details"].size(), 1u);
  EXPECT_EQ(away["warning_details"][0]["code"], "no_contact");
  EXPECT_NE(away["warning_details"][0]["message"].get<std::string>().find("the sphere"),
            std::string::npos);
  const json into =
      run_3d(box_under({{"type", "sphere"}, {"center", {0.5, 0.5, 1.4}}, {"radius", 0.5}}));
  ASSERT_GE(into["warning_details"].size(), 1u);
  EXPECT_EQ(into["warning_details"][0]["code"], "initial_penetration");
  EXPECT_NE(into["warning_details"][0]["message"].get<std::string>().find("sphere's center"),
            std::string::npos);
}

TEST(Case3dObstacles, EveryProblemOfAnObstacleIsNamedByItsField) {
  json both = hertz_3d(0);
  both["boundary"]["contact"]["obstacle"] = {{"type", "gap"}, {"g", 0}};
  EXPECT_EQ(case3d_problems(both), std::vector<std::string>{"/boundary/contact"});
  json neither = hertz_3d(0);
  neither["boundary"]["contact"].erase("point");
  neither["boundary"]["contact"].erase("normal");
  EXPECT_EQ(case3d_problems(neither), std::vector<std::string>{"/boundary/contact/obstacle"});
  json half = hertz_3d(0);
  half["boundary"]["contact"].erase("normal");
  EXPECT_EQ(case3d_problems(half), std::vector<std::string>{"/boundary/contact/normal"});
  json bad_gap = box_under({{"type", "gap"}, {"g", "w - z"}});
  const auto read = read_case(bad_gap);
  ASSERT_EQ(read.errors.size(), 1u);
  EXPECT_EQ(read.errors[0].pointer, "/boundary/top/obstacle/g");
  EXPECT_NE(read.errors[0].detail.find("x, y and z"), std::string::npos) << read.errors[0].detail;
  EXPECT_EQ(case3d_problems(box_under({{"type", "sphere"}, {"center", {0, 0, 2}}, {"radius", 0}})),
            std::vector<std::string>{"/boundary/top/obstacle/radius"});
  EXPECT_EQ(
      case3d_problems(box_under({{"type", "plane"}, {"point", {0, 0, 1}}, {"normal", {0, 0, 0}}})),
      std::vector<std::string>{"/boundary/top/obstacle/normal"});
  EXPECT_EQ(case3d_problems(box_under({{"type", "cylinder"}})),
            std::vector<std::string>{"/boundary/top/obstacle/type"});
  // A gap that is not a number at the vertices x = 0.25 of the group (0·log 0), though it is at
  // the expression's sample points (x = 0, 0.5, 1): found once the mesh is built.
  const CaseError nan =
      run_3d_problem(box_under({{"type", "gap"}, {"g", "1 - z + 0 * ln(abs(x - 0.25))"}}));
  EXPECT_EQ(nan.pointer, "/boundary/top/obstacle/g")
      << "a gap that is NaN on the group was accepted";
  EXPECT_NE(nan.detail.find("not finite"), std::string::npos);
  // Facing away: the plane's normal from the body into the plane. Found once the mesh is built.
  json away = box_under({{"type", "plane"}, {"point", {0, 0, 1}}, {"normal", {0, 0, 1}}});
  EXPECT_EQ(run_3d_problem(away).pointer, "/boundary/top/obstacle/normal")
      << "a plane the contact faces do not face was accepted";
}

// "direction": "obstacle_normal" in 3D, as in 2D: each contact vertex is constrained along the
// obstacle's normal where the body's normal meets it. On a plane whose normal the flat contact
// faces share the two directions are the same; under a sphere they differ by a little at the
// zone's edge, and mmg and pdas agree on the discrete problem.
TEST(Case3dObstacles, TheObstaclesNormalAsTheConstraintDirection) {
  const json plane = {{"type", "plane"}, {"point", {0, 0, 1}}, {"normal", {0, 0, -1}}};
  json along_obstacle = box_under(plane);
  along_obstacle["boundary"]["top"]["direction"] = "obstacle_normal";
  EXPECT_EQ(run_3d(along_obstacle)["contact"]["force"],
            run_3d(box_under(plane))["contact"]["force"]);

  json sphere = box_under({{"type", "sphere"}, {"center", {0.5, 0.5, 3}}, {"radius", 2}});
  sphere["solver"]["tolerance"] = 1e-10;
  const double body = run_3d(sphere)["contact"]["force"][2].get<double>();
  sphere["boundary"]["top"]["direction"] = "obstacle_normal";
  const json mmg = run_3d(sphere);
  sphere["solver"]["method"] = "pdas";
  const json pdas = run_3d(sphere);
  const double obstacle = mmg["contact"]["force"][2].get<double>();
  ASSERT_TRUE(mmg["converged"].get<bool>());
  EXPECT_NEAR(obstacle, pdas["contact"]["force"][2].get<double>(), 1e-6 * std::abs(obstacle));
  EXPECT_NE(obstacle, body);
  EXPECT_NEAR(obstacle, body, 0.05 * std::abs(body));  // 2 % apart on this mesh
}

}  // namespace
}  // namespace fosls
