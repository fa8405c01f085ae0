// A converged answer that is physically empty or questionable says so (docs/result-format.md,
// "Warnings"): no contact (an obstacle normal pointing the wrong way, a body pulled away), a
// body that starts inside the obstacle, a tangential displacement a frictionless contact cannot
// hold, a contact zone of a few edges, implausible units; and the shipped examples raise none
// of the review warnings.

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "../shipped_example.hpp"
#include "case/format/case_reader.hpp"
#include "case/result/result_warnings.hpp"
#include "case/run/case_runner.hpp"

namespace fosls {
namespace {

using nlohmann::json;

json solve(const json& j) {
  const CaseReadResult read = read_case(j);
  EXPECT_TRUE(read.spec) << (read.errors.empty() ? "" : read.errors[0].detail);
  RunControl control;
  control.want_vtu = false;
  return run_case(*read.spec, control).result;
}

std::vector<std::string> codes(const json& r) {
  std::vector<std::string> out;
  for (const auto& w : r["warning_details"]) out.push_back(w["code"]);
  return out;
}

bool has(const json& r, const std::string& code) {
  const auto c = codes(r);
  return std::find(c.begin(), c.end(), code) != c.end();
}

std::string message(const json& r, const std::string& code) {
  for (const auto& w : r["warning_details"])
    if (w["code"] == code) return w["message"];
  return "";
}

json hertz(int refinements = 1) {
  json j = testing::load_shipped_example("hertz");
  j["mesh"]["refinements"] = refinements;
  return j;
}

/// The unit square pressed onto a plane y = 0 by its top.
json square_on_plane(int refinements = 1) {
  json j = testing::load_shipped_example("signorini_square");
  j["mesh"]["refinements"] = refinements;
  j["boundary"]["bottom"] = {
      {"type", "contact"},
      {"obstacle", {{"type", "plane"}, {"point", {0, 0}}, {"normal", {0, 1}}}}};
  return j;
}

TEST(ResultWarnings, AnObstacleNormalPointingTheWrongWayIsNoContactAndNeedsReview) {
  json j = hertz();
  j["boundary"]["contact"]["obstacle"]["normal"] = {0, -1};
  const json r = solve(j);
  ASSERT_TRUE(r["converged"].get<bool>());
  EXPECT_EQ(r["contact"]["zone"]["edges"], 0);
  EXPECT_TRUE(has(r, "no_contact")) << r["warnings"];
  EXPECT_NE(message(r, "no_contact").find("(0, 1)"), std::string::npos)
      << "names the normal it should be: " << message(r, "no_contact");
  EXPECT_TRUE(r["review_required"].get<bool>());
}

TEST(ResultWarnings, ABodyPulledAwayIsNoContactWithTheSmallestGap) {
  json j = hertz();
  j["boundary"]["top"]["displacement"] = {0, 0.01};
  const json r = solve(j);
  ASSERT_TRUE(r["converged"].get<bool>());
  EXPECT_EQ(r["contact"]["force"], json({0.0, 0.0}));
  EXPECT_TRUE(has(r, "no_contact")) << r["warnings"];
  EXPECT_NE(message(r, "no_contact").find("smallest remaining gap is 0.01"), std::string::npos)
      << message(r, "no_contact");
  EXPECT_TRUE(r["review_required"].get<bool>());
}

TEST(ResultWarnings, ABodyThatStartsInsideTheObstacleSaysByHowMuchAndWhere) {
  json j = square_on_plane();
  j["boundary"]["bottom"]["obstacle"]["point"] = {0, 0.6};
  const json r = solve(j);
  ASSERT_TRUE(r["converged"].get<bool>());
  EXPECT_TRUE(has(r, "initial_penetration")) << r["warnings"];
  const std::string m = message(r, "initial_penetration");
  EXPECT_NE(m.find("by up to 0.6 at ("), std::string::npos) << m;
  EXPECT_TRUE(r["review_required"].get<bool>());
}

TEST(ResultWarnings, AnObstacleDisplacementIsAnIndentationNotAnOverlap) {
  json j = square_on_plane();
  j["boundary"]["top"]["displacement"] = {0, 0};
  j["boundary"]["bottom"]["obstacle"]["displacement"] = {0, 0.02};
  const json r = solve(j);
  EXPECT_GT(r["contact"]["zone"]["edges"].get<int>(), 0);
  EXPECT_FALSE(has(r, "initial_penetration")) << r["warnings"];
  EXPECT_FALSE(r["review_required"].get<bool>()) << r["warnings"];
}

TEST(ResultWarnings, ATangentialDisplacementOnAFrictionlessContactOnlySlidesTheBody) {
  json j = square_on_plane();
  j["boundary"]["top"]["displacement"] = {0.005, -0.02};
  json r = solve(j);
  EXPECT_TRUE(has(r, "tangential_load_frictionless")) << r["warnings"];
  EXPECT_NE(message(r, "tangential_load_frictionless").find("0.005"), std::string::npos);
  // The answer is right for frictionless contact: a warning, not a review.
  EXPECT_FALSE(r["review_required"].get<bool>());

  j["boundary"]["top"]["displacement"] = {0, -0.02};  // straight down: nothing to say
  EXPECT_FALSE(has(solve(j), "tangential_load_frictionless"));
  // Held elsewhere at another tangential displacement: the body is sheared, not slid.
  j["boundary"]["top"]["displacement"] = {0.005, -0.02};
  j["boundary"]["left"] = {{"type", "dirichlet"}, {"displacement", {0, nullptr}}};
  EXPECT_FALSE(has(solve(j), "tangential_load_frictionless"));
}

TEST(ResultWarnings, AContactZoneOfFewEdgesAsksForRefinement) {
  const json coarse = solve(hertz(0));
  const int edges = coarse["contact"]["zone"]["edges"];
  ASSERT_GT(edges, 0);
  ASSERT_LT(edges, kResolvedZoneEdges);
  EXPECT_TRUE(has(coarse, "contact_zone_underresolved")) << coarse["warnings"];
  EXPECT_NE(message(coarse, "contact_zone_underresolved").find(std::to_string(edges) + " edges"),
            std::string::npos);
  EXPECT_FALSE(coarse["review_required"].get<bool>());
  const json fine = solve(hertz(2));
  ASSERT_GE(fine["contact"]["zone"]["edges"].get<int>(), kResolvedZoneEdges);
  EXPECT_FALSE(has(fine, "contact_zone_underresolved")) << fine["warnings"];
  // The width's resolution: the edges at the zone's ends.
  EXPECT_GT(fine["contact"]["zone"]["end_edge_length"].get<double>(), 0.0);
  EXPECT_LT(fine["contact"]["zone"]["end_edge_length"].get<double>(),
            fine["contact"]["zone"]["length"].get<double>() / 5);
}

TEST(ResultWarnings, PascalsOnAMillimetreGeometryAreImplausible) {
  json j = hertz(0);  // radius 1: scale it to a roller of radius 10
  j["mesh"]["builtin"]["radius"] = 10;
  j["mesh"]["size"] = 0.5;
  j["material"] = {{"E", 2.1e11}, {"nu", 0.3}};
  j["boundary"]["top"]["displacement"] = {0, -0.1};
  json r = solve(j);
  EXPECT_TRUE(has(r, "units_implausible")) << r["warnings"];
  EXPECT_TRUE(r["review_required"].get<bool>());
  EXPECT_FALSE(r["units"]["declared"].get<bool>());
  // Declared: MPa with E in Pa is beyond any solid; E in MPa is fine.
  j["units"] = {{"length", "mm"}, {"stress", "MPa"}};
  r = solve(j);
  EXPECT_TRUE(has(r, "units_implausible")) << r["warnings"];
  j["material"]["E"] = 2.1e5;
  r = solve(j);
  EXPECT_FALSE(has(r, "units_implausible")) << r["warnings"];
  EXPECT_EQ(r["units"], json({{"declared", true},
                              {"length", "mm"},
                              {"stress", "MPa"},
                              {"force_per_thickness", "N/mm"}}));
}

TEST(ResultWarnings, WarningsAndTheirDetailsAgree) {
  json j = square_on_plane();
  j["boundary"]["bottom"]["obstacle"]["point"] = {0, 0.6};
  j["boundary"]["top"]["displacement"] = {0.005, -0.02};
  j["solver"]["max_iterations"] = 2;
  const json r = solve(j);
  ASSERT_EQ(r["warnings"].size(), r["warning_details"].size());
  for (std::size_t i = 0; i < r["warnings"].size(); ++i)
    EXPECT_EQ(r["warnings"][i], r["warning_details"][i]["message"]);
  EXPECT_TRUE(has(r, "not_converged"));
  const auto all = warning_codes();
  for (const auto& c : codes(r))
    EXPECT_NE(std::find(all.begin(), all.end(), c), all.end()) << c << " is not in warning_codes()";
}

TEST(ResultWarnings, TheShippedExamplesNeedNoReview) {
  for (const char* name :
       {"hertz", "hertz_incompressible", "signorini_square", "signorini_square_incompressible",
        "signorini_square_order2", "linear_square"}) {
    json j = testing::load_shipped_example(name);
    j["mesh"]["refinements"] = std::min(2, j["mesh"]["refinements"].get<int>());
    const json r = solve(j);
    EXPECT_FALSE(r["review_required"].get<bool>()) << name << ": " << r["warnings"];
    for (const char* code :
         {"no_contact", "initial_penetration", "units_implausible", "tangential_load_frictionless"})
      EXPECT_FALSE(has(r, code)) << name << ": " << r["warnings"];
  }
}

TEST(ResultWarnings, TheWalkthroughsCasesAreValidAndNeedNoReview) {
  for (const char* name : {"steel_roller", "rubber_seal"}) {
    std::ifstream in(std::string(FOSLS_SOURCE_DIR) + "/docs/walkthrough/" + name + ".json");
    json j = json::parse(in);
    j["mesh"]["refinements"] = 1;
    const json r = solve(j);
    EXPECT_TRUE(r["converged"].get<bool>()) << name;
    EXPECT_FALSE(r["review_required"].get<bool>()) << name << ": " << r["warnings"];
    EXPECT_EQ(r["units"]["force_per_thickness"], "N/mm") << name;
  }
}

TEST(ResultWarnings, HertzIsRecognisedByGeometry) {
  json j = hertz();
  j["name"] = "a roller";  // no "hertz" in the name
  json r = solve(j);
  EXPECT_EQ(r["contact"]["shape"]["type"], "arc");
  EXPECT_NEAR(r["contact"]["shape"]["radius"].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(r["contact"]["shape"]["center"][1].get<double>(), 1.0, 1e-9);
  EXPECT_EQ(r["contact"]["plane_normal"], json({0.0, 1.0}));
  r = solve(square_on_plane());
  EXPECT_EQ(r["contact"]["shape"]["type"], "line");
}

// The same rule in 3D (the tangential part by the projector onto the contact plane): hertz_3d's
// top moved sideways by (0.003, 0.004) slides the ball by 0.005 along (0.6, 0.8, 0).
TEST(ResultWarnings, ATangentialDisplacementIn3dIsFoundByTheSameRule) {
  json j = testing::load_shipped_example("3d/hertz_3d");
  j["boundary"]["top"]["displacement"] = {0.003, 0.004, -0.01};
  const auto warning = tangential_load_warning(*read_case(j).spec);
  ASSERT_TRUE(warning);
  EXPECT_NE(warning->message.find("of 0.005 "), std::string::npos) << warning->message;
  EXPECT_NE(warning->message.find("(0.6, 0.8, 0)"), std::string::npos) << warning->message;
  j["boundary"]["top"]["displacement"] = {0, 0, -0.01};
  EXPECT_FALSE(tangential_load_warning(*read_case(j).spec));
  // Held elsewhere at another tangential displacement: sheared, not slid.
  j["boundary"]["top"]["displacement"] = {0.003, 0.004, -0.01};
  j["mesh"]["builtin"]["quarter"] = true;
  j["boundary"]["symmetry_x"] = {{"type", "dirichlet"}, {"displacement", {0, nullptr, nullptr}}};
  EXPECT_FALSE(tangential_load_warning(*read_case(j).spec));
}

}  // namespace
}  // namespace fosls
