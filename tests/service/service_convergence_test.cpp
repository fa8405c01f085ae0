// Honest convergence through the real fosls-serve: a solve stopped by solver.max_iterations
// is visible in the job, the listing and the metrics, and --fail-unconverged fails it while
// keeping its result; the submitted case can be read back.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "service_fixture.hpp"

namespace fosls::service {
namespace {

using nlohmann::json;
using testing::Service;
using testing::small_case;

/// Stops after two iterations, far from the tolerance.
json unconverged_case() {
  json j = small_case(7);
  j["name"] = "unconverged";
  j["solver"] = {{"method", "pgs"}, {"tolerance", 1e-12}, {"max_iterations", 2}};
  return j;
}

std::string path(std::int64_t id, const std::string& leaf = "") {
  return "/v1/jobs/" + std::to_string(id) + (leaf.empty() ? "" : "/" + leaf);
}

TEST(ServiceConvergence, AnUnconvergedSolveSucceedsAndSaysSoEverywhere) {
  Service svc(1);
  auto cli = svc.client();
  const auto good = svc.submit(small_case(1));
  const auto bad = svc.submit(unconverged_case());
  const json good_job = svc.wait_state(good, "succeeded");
  const json bad_job = svc.wait_state(bad, "succeeded");
  EXPECT_EQ(good_job["converged"], true);
  EXPECT_EQ(good_job["stop_reason"], "converged");
  EXPECT_EQ(bad_job["converged"], false);
  EXPECT_EQ(bad_job["stop_reason"], "max_iterations");
  EXPECT_TRUE(bad_job["error"].is_null());

  const json listed = json::parse(cli.Get("/v1/jobs")->body);
  ASSERT_EQ(listed["jobs"].size(), 2u);
  EXPECT_EQ(listed["jobs"][0]["id"], bad);  // newest first
  EXPECT_EQ(listed["jobs"][0]["converged"], false);
  EXPECT_EQ(listed["jobs"][1]["converged"], true);
  const json not_converged = json::parse(cli.Get("/v1/jobs?converged=false")->body);
  ASSERT_EQ(not_converged["jobs"].size(), 1u);
  EXPECT_EQ(not_converged["jobs"][0]["id"], bad);
  EXPECT_EQ(json::parse(cli.Get("/v1/jobs?converged=true&state=succeeded")->body)["jobs"][0]["id"],
            good);
  testing::expect_problem(cli.Get("/v1/jobs?converged=maybe"), 400);

  const json result = json::parse(cli.Get(path(bad, "result"))->body);
  EXPECT_EQ(result["converged"], false);
  EXPECT_EQ(result["iterations"], 2);

  const std::string metrics = cli.Get("/metrics")->body;
  EXPECT_NE(metrics.find("fosls_jobs_not_converged 1\n"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("fosls_solves_total{stop_reason=\"max_iterations\"} 1\n"),
            std::string::npos);
  EXPECT_NE(metrics.find("fosls_solves_total{stop_reason=\"converged\"} 1\n"), std::string::npos);
}

TEST(ServiceConvergence, FailUnconvergedFailsTheJobAndKeepsItsResult) {
  Service svc(1, {"--fail-unconverged"});
  auto cli = svc.client();
  const auto good = svc.submit(small_case(1));
  const auto bad = svc.submit(unconverged_case());
  EXPECT_EQ(svc.wait_state(good, "succeeded")["converged"], true);
  const json failed = svc.wait_state(bad, "failed");
  EXPECT_EQ(failed["converged"], false);
  EXPECT_EQ(failed["stop_reason"], "max_iterations");
  EXPECT_NE(failed["error"].get<std::string>().find("--fail-unconverged"), std::string::npos)
      << failed;
  // The last iterate is still there to look at.
  auto result = cli.Get(path(bad, "result"));
  ASSERT_EQ(result->status, 200) << result->body;
  EXPECT_EQ(json::parse(result->body)["stop_reason"], "max_iterations");
  EXPECT_EQ(cli.Get(path(bad, "solution.vtu"))->status, 200);
  EXPECT_NE(cli.Get("/metrics")->body.find("fosls_jobs{state=\"failed\"} 1\n"), std::string::npos);
}

TEST(ServiceConvergence, TheSubmittedCaseCanBeReadBack) {
  Service svc(1);
  auto cli = svc.client();
  const json submitted = unconverged_case();
  const auto id = svc.submit(submitted);
  auto res = cli.Get(path(id, "case"));
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/json");
  EXPECT_EQ(json::parse(res->body), submitted);
  EXPECT_EQ(svc.job(id)["links"]["case"], path(id, "case"));
  testing::expect_problem(cli.Get(path(id + 100, "case")), 404);
  testing::expect_problem(cli.Post(path(id, "case"), "{}", "application/json"), 405);
}

// A sweep runs in the job like any case: the result carries every point, and a point that
// does not converge makes the job's converged false.
TEST(ServiceConvergence, ASweepIsSolvedPointByPoint) {
  Service svc(1);
  auto cli = svc.client();
  json swept = small_case(3);
  swept["name"] = "swept";
  swept["boundary"]["top"]["displacement"] = {0, -0.02};
  swept["sweep"] = {{"pointer", "/boundary/top/displacement/1"}, {"values", {-0.02, -0.04}}};
  const auto id = svc.submit(swept);
  const json done = svc.wait_state(id, "succeeded");
  EXPECT_EQ(done["converged"], true);
  EXPECT_EQ(done["progress"]["step"], 1);  // the last progress is the last point's
  EXPECT_EQ(done["progress"]["steps"], 2);
  const json result = json::parse(cli.Get(path(id, "result"))->body);
  ASSERT_EQ(result["sweep"]["points"].size(), 2u);
  EXPECT_EQ(result["sweep"]["points"][1]["value"], -0.04);
  EXPECT_GT(result["sweep"]["points"][1]["force"][1].get<double>(),
            result["sweep"]["points"][0]["force"][1].get<double>());

  // Refused up front, at the value that makes the case invalid.
  swept["sweep"]["pointer"] = "/material/mu";
  swept["sweep"]["values"] = {1, 0};
  auto refused = svc.post(swept);
  testing::expect_problem(refused, 422);
  EXPECT_EQ(json::parse(refused->body)["errors"][0]["pointer"], "/sweep/values/1");
}

// Load steps run as one job whose progress says which step runs, out of how many; the
// iteration count starts again at each step. Steps seen while polling never go back.
TEST(ServiceConvergence, LoadStepsReportWhichStepRuns) {
  Service svc(1);
  json stepped = testing::example("cattaneo_mindlin");
  stepped["mesh"]["refinements"] = 1;
  const auto id = svc.submit(stepped);
  int last_seen = 0;
  bool went_back = false;
  const json done = svc.wait_for(id, [&](const json& j) {
    if (j["progress"].is_object()) {
      const int step = j["progress"]["step"];
      went_back = went_back || step < last_seen;
      last_seen = step;
      EXPECT_EQ(j["progress"]["steps"], 3) << j.dump();
    }
    return testing::is_finished(j);
  });
  EXPECT_EQ(done["state"], "succeeded");
  EXPECT_FALSE(went_back);
  ASSERT_TRUE(done["progress"].is_object()) << done.dump();
  EXPECT_EQ(done["progress"]["step"], 2);  // the last of load steps + 1 solves
  EXPECT_EQ(done["progress"]["steps"], 3);
  const json result = json::parse(svc.client().Get(path(id, "result"))->body);
  EXPECT_EQ(result["load_steps"]["count"], 3);
}

// Issue 50: a cancel keeps the load steps solved before it. The solve process is killed on
// cancel; what it leaves is the partial result it sent after each step.
TEST(ServiceConvergence, ACancelledJobKeepsTheLoadStepsSolvedBeforeIt) {
  Service svc(1);
  json stepped = testing::example("cattaneo_mindlin");
  stepped["mesh"]["refinements"] = 1;
  stepped["load_steps"] = json::array();
  for (int k = 1; k <= 60; ++k)
    stepped["load_steps"].push_back({{"/boundary/top/displacement/0", 0.0001 * k}});
  const auto id = svc.submit(stepped);
  svc.wait_for(id, [](const json& j) {
    return testing::is_finished(j) || (j["progress"].is_object() && j["progress"]["step"] >= 3);
  });
  ASSERT_EQ(svc.client().Post(path(id, "cancel"))->status, 202);
  const json done = svc.wait_for(id, [](const json& j) { return testing::is_finished(j); });
  ASSERT_EQ(done["state"], "cancelled") << done.dump();
  EXPECT_EQ(done["converged"], false);
  EXPECT_EQ(done["stop_reason"], "cancelled");
  const auto response = svc.client().Get(path(id, "result"));
  ASSERT_EQ(response->status, 200) << response->body;
  const json result = json::parse(response->body);
  const int kept = result["load_steps"]["count"];
  EXPECT_GE(kept, 3);
  EXPECT_LT(kept, 61);
  EXPECT_EQ(result["load_steps"]["steps"].size(), static_cast<std::size_t>(kept));
  EXPECT_EQ(result["load_steps"]["stopped_before"]["reason"], "cancelled");
  EXPECT_EQ(result["stop_reason"], "cancelled");
  EXPECT_TRUE(result["review_required"].get<bool>());
}

}  // namespace
}  // namespace fosls::service
