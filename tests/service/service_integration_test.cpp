// The real fosls-serve, started on a free loopback port with its own temporary database and
// stopped by each test: round trip on the Hertz example, every error path, cancellation,
// kill -9 recovery, graceful shutdown, 200 concurrent jobs, idempotency.

#include <gtest/gtest.h>
#include <httplib.h>
#include <sqlite3.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "http_client.hpp"
#include "server_process.hpp"
#include "service_fixture.hpp"
#include "temp_dir.hpp"

namespace fosls::service {
namespace {

using nlohmann::json;
using testing::endless_case;
using testing::example;
using testing::expect_problem;
using testing::is_finished;
using testing::medium_case;
using testing::raw_body;
using testing::raw_http;
using testing::ServerProcess;
using testing::Service;
using testing::small_case;
using testing::TempDir;

/// Rows of the jobs table: id → (state, attempts, finished_at), read directly from SQLite.
struct JobRow {
  std::string state;
  int attempts = 0;
  long long finished_at = 0;
};

std::map<std::int64_t, JobRow> read_jobs(const std::string& path) {
  std::map<std::int64_t, JobRow> rows;
  sqlite3* db = nullptr;
  if (sqlite3_open(path.c_str(), &db) != SQLITE_OK) {
    ADD_FAILURE() << "cannot open " << path;
    sqlite3_close(db);
    return rows;
  }
  sqlite3_busy_timeout(db, 5000);
  sqlite3_stmt* stmt = nullptr;
  sqlite3_prepare_v2(db, "SELECT id, state, attempts, coalesce(finished_at, 0) FROM jobs", -1,
                     &stmt, nullptr);
  while (sqlite3_step(stmt) == SQLITE_ROW) {
    rows[sqlite3_column_int64(stmt, 0)] = {
        reinterpret_cast<const char*>(sqlite3_column_text(stmt, 1)), sqlite3_column_int(stmt, 2),
        sqlite3_column_int64(stmt, 3)};
  }
  sqlite3_finalize(stmt);
  sqlite3_close(db);
  return rows;
}

long long count_rows(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  sqlite3_open(path.c_str(), &db);
  sqlite3_stmt* stmt = nullptr;
  long long n = -1;
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr) == SQLITE_OK &&
      sqlite3_step(stmt) == SQLITE_ROW) {
    n = sqlite3_column_int64(stmt, 0);
  }
  sqlite3_finalize(stmt);
  sqlite3_close(db);
  return n;
}

TEST(ServiceIntegration, HertzRoundTrip) {
  Service svc;
  auto cli = svc.client();
  auto res = svc.post(example("hertz"));
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 202) << res->body;
  const std::string location = res->get_header_value("Location");
  const json created = json::parse(res->body);
  EXPECT_EQ(location, "/v1/jobs/" + std::to_string(created["id"].get<int>()));
  EXPECT_EQ(created["state"], "queued");
  EXPECT_EQ(created["name"], "hertz");

  const json done = svc.wait_state(created["id"], "succeeded");
  EXPECT_EQ(done["attempts"], 1);
  EXPECT_GT(done["progress"]["iteration"].get<int>(), 0);
  EXPECT_TRUE(done["started_at"].is_string());
  EXPECT_TRUE(done["finished_at"].is_string());
  EXPECT_TRUE(done["error"].is_null());
  EXPECT_EQ(done["converged"], true);
  EXPECT_EQ(done["stop_reason"], "converged");

  auto result_res = cli.Get((location + "/result").c_str());
  ASSERT_EQ(result_res->status, 200);
  const json result = json::parse(result_res->body);
  ASSERT_TRUE(result.contains("contact"));
  EXPECT_TRUE(result["contact"]["pressure"].is_array());
  EXPECT_FALSE(result["contact"]["pressure"].empty());
  ASSERT_EQ(result["contact"]["force"].size(), 2u);
  EXPECT_GT(std::abs(result["contact"]["force"][1].get<double>()), 0.0);
  ASSERT_TRUE(result["history"].is_array());
  EXPECT_FALSE(result["history"].empty());
  EXPECT_TRUE(result["converged"].is_boolean());

  auto vtu = cli.Get((location + "/solution.vtu").c_str());
  ASSERT_EQ(vtu->status, 200);
  EXPECT_NE(vtu->body.find("<VTKFile"), std::string::npos);

  auto listed = json::parse(cli.Get("/v1/jobs?state=succeeded")->body);
  ASSERT_EQ(listed["jobs"].size(), 1u);
  EXPECT_EQ(listed["jobs"][0]["id"], created["id"]);
  EXPECT_EQ(cli.Get("/healthz")->status, 200);
  const std::string metrics = cli.Get("/metrics")->body;
  EXPECT_NE(metrics.find("fosls_jobs{state=\"succeeded\"} 1"), std::string::npos);
  EXPECT_NE(metrics.find("fosls_job_run_seconds_count{outcome=\"succeeded\"} 1"),
            std::string::npos);
  EXPECT_EQ(svc.server().stop(), 0);  // clean exit on SIGTERM
}

TEST(ServiceIntegration, ErrorPaths) {
  Service svc(1);
  auto cli = svc.client();
  // 400: not JSON.
  expect_problem(cli.Post("/v1/jobs", "{\"mesh\": ", "application/json"), 400);
  // 415: what `curl -d` sends without -H 'Content-Type: application/json'.
  expect_problem(cli.Post("/v1/jobs", small_case().dump(), "application/x-www-form-urlencoded"),
                 415);
  // 413: above the default 8 MiB limit.
  expect_problem(cli.Post("/v1/jobs", "\"" + std::string(9u << 20, 'x') + "\"", "application/json"),
                 413);
  // Chunked bodies would bypass the limit: refused.
  auto chunked = raw_http(svc.server().port(),
                          "POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                          "Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n"
                          "2\r\n{}\r\n0\r\n\r\n");
  EXPECT_EQ(chunked.status, 411) << chunked.text;
  EXPECT_FALSE(json::parse(raw_body(chunked), nullptr, false).is_discarded());

  // 422: invalid case, every problem with its pointer.
  json invalid = small_case();
  invalid["material"]["mu"] = -1;
  invalid["solver"]["method"] = "bogus";
  auto res = svc.post(invalid);
  expect_problem(res, 422);
  std::set<std::string> pointers;
  const json problem = json::parse(res->body);
  for (const auto& e : problem["errors"]) {
    pointers.insert(e["pointer"].get<std::string>());
    EXPECT_FALSE(e["detail"].get<std::string>().empty());
  }
  EXPECT_TRUE(pointers.count("/material/mu")) << res->body;
  EXPECT_TRUE(pointers.count("/solver/method")) << res->body;

  // 422: a gmsh .geo script can run shell commands; the service never accepts one.
  std::ofstream(svc.db() + ".geo") << "Point(1) = {0, 0, 0};\n";
  json geo = small_case();
  geo["mesh"] = {{"geo_file", svc.db() + ".geo"}, {"size", 0.5}};
  auto geo_res = svc.post(geo);
  expect_problem(geo_res, 422);
  bool names_geo_file = false;
  const json geo_problem = json::parse(geo_res->body);
  for (const auto& e : geo_problem["errors"]) {
    names_geo_file |= e["pointer"].get<std::string>().rfind("/mesh/geo_file", 0) == 0;
  }
  EXPECT_TRUE(names_geo_file) << geo_res->body;

  // Valid JSON but indefinite weights: only found while running (CaseException), so the job
  // is accepted and then fails with the pointer and the reason.
  json indefinite = small_case();
  indefinite["weights"] = {{"c1", 1}, {"c2", 1}, {"c3", 1000}};
  const auto doomed = svc.submit(indefinite);
  const json failed = svc.wait_state(doomed, "failed");
  EXPECT_NE(failed["error"].get<std::string>().find("/weights"), std::string::npos) << failed;
  auto failed_result = cli.Get(("/v1/jobs/" + std::to_string(doomed) + "/result").c_str());
  expect_problem(failed_result, 409);
  EXPECT_NE(failed_result->body.find("/weights"), std::string::npos);

  // 404: unknown job, unknown route.
  expect_problem(cli.Get("/v1/jobs/424242"), 404);
  expect_problem(cli.Get("/v1/jobs/424242/result"), 404);
  expect_problem(cli.Get("/v1/no-such-route"), 404);

  // 409: result before the job is finished; cancel of a finished job.
  const auto running = svc.submit(endless_case());
  expect_problem(cli.Get(("/v1/jobs/" + std::to_string(running) + "/result").c_str()), 409);
  expect_problem(cli.Get(("/v1/jobs/" + std::to_string(running) + "/solution.vtu").c_str()), 409);
  expect_problem(cli.Delete(("/v1/jobs/" + std::to_string(running)).c_str()), 409);
  EXPECT_LT(cli.Post(("/v1/jobs/" + std::to_string(running) + "/cancel").c_str())->status, 300);
  svc.wait_state(running, "cancelled");
  expect_problem(cli.Post(("/v1/jobs/" + std::to_string(running) + "/cancel").c_str()), 409);
  auto cancelled_result = cli.Get(("/v1/jobs/" + std::to_string(running) + "/result").c_str());
  expect_problem(cancelled_result, 409);
  EXPECT_NE(cancelled_result->body.find("cancelled"), std::string::npos);

  // Nothing above was queued except those two jobs; no request crashed the server.
  EXPECT_EQ(json::parse(cli.Get("/v1/jobs")->body)["jobs"].size(), 2u);
  EXPECT_EQ(cli.Get("/healthz")->status, 200);
}

TEST(ServiceIntegration, CancellingARunningSolveFreesTheWorker) {
  Service svc(1);
  auto cli = svc.client();
  const auto id = svc.submit(endless_case());
  // Wait until the solver reports iterations, so the cancel hits the iteration loop.
  svc.wait_for(id,
               [](const json& j) { return j["state"] == "running" && !j["progress"].is_null(); });
  auto cancel = cli.Post(("/v1/jobs/" + std::to_string(id) + "/cancel").c_str());
  ASSERT_EQ(cancel->status, 202) << cancel->body;
  EXPECT_TRUE(json::parse(cancel->body)["cancel_requested"].get<bool>());
  const json cancelled = svc.wait_state(id, "cancelled", 60);
  EXPECT_TRUE(cancelled["finished_at"].is_string());
  EXPECT_EQ(cancelled["attempts"], 1);

  // The only worker takes the next job.
  const auto next = svc.submit(small_case());
  svc.wait_state(next, "succeeded");
  EXPECT_NE(cli.Get("/metrics")->body.find("fosls_workers_busy 0"), std::string::npos);
}

TEST(ServiceIntegration, KillNineLosesNothingAndCompletesNothingTwice) {
  Service svc(1);
  std::vector<std::int64_t> ids = {svc.submit(medium_case())};
  for (int i = 0; i < 3; ++i) ids.push_back(svc.submit(small_case(i)));
  svc.wait_for(ids[0], [](const json& j) { return j["state"] == "running"; });
  svc.server().kill_hard();

  // What the crash left behind, straight from the database.
  const auto at_kill = read_jobs(svc.db());
  ASSERT_EQ(at_kill.size(), ids.size());
  int running = 0, queued = 0;
  for (const auto& [id, row] : at_kill) {
    running += row.state == "running";
    queued += row.state == "queued";
  }
  EXPECT_EQ(running, 1);
  EXPECT_GE(queued, 1);

  svc.start(1);  // same database
  for (auto id : ids) svc.wait_for(id, is_finished);
  EXPECT_EQ(svc.server().stop(), 0);

  const auto after = read_jobs(svc.db());
  for (auto id : ids) {
    const JobRow& before = at_kill.at(id);
    const JobRow& now = after.at(id);
    EXPECT_EQ(now.state, "succeeded") << "job " << id;
    if (before.state == "running") {
      EXPECT_EQ(now.attempts, before.attempts + 1) << "job " << id << " was re-run once";
    } else if (before.state == "queued") {
      EXPECT_EQ(now.attempts, 1) << "job " << id;
    } else {
      EXPECT_EQ(now.attempts, before.attempts) << "finished job " << id << " ran again";
      EXPECT_EQ(now.finished_at, before.finished_at);
    }
  }
  // One result per job: job_id is the primary key of job_results, and every job has one.
  EXPECT_EQ(count_rows(svc.db(), "SELECT count(*) FROM job_results"),
            static_cast<long long>(ids.size()));
  EXPECT_EQ(count_rows(svc.db(),
                       "SELECT count(*) FROM jobs j JOIN job_results r ON "
                       "r.job_id = j.id WHERE j.state = 'succeeded'"),
            static_cast<long long>(ids.size()));
  EXPECT_NE(svc.log().find("recovered after the previous process stopped"), std::string::npos);
}

TEST(ServiceIntegration, GracefulShutdownPutsTheRunningJobBack) {
  Service svc(1);
  const auto id = svc.submit(endless_case());
  svc.wait_for(id,
               [](const json& j) { return j["state"] == "running" && !j["progress"].is_null(); });
  EXPECT_EQ(svc.server().stop(), 0);
  const JobRow row = read_jobs(svc.db()).at(id);
  EXPECT_EQ(row.state, "queued");
  EXPECT_EQ(row.attempts, 0);  // an interrupted attempt is not counted

  svc.start(1);
  svc.wait_for(id, [](const json& j) { return j["state"] == "running"; });
  auto cli = svc.client();
  cli.Post(("/v1/jobs/" + std::to_string(id) + "/cancel").c_str());
  EXPECT_EQ(svc.wait_state(id, "cancelled", 60)["attempts"], 1);
}

TEST(ServiceIntegration, TwoHundredConcurrentJobs) {
  Service svc(2);
  constexpr int kClients = 8;
  constexpr int kPerClient = 25;
  std::atomic<int> accepted{0};
  std::vector<std::thread> clients;
  for (int c = 0; c < kClients; ++c) {
    clients.emplace_back([&, c] {
      auto cli = svc.client();
      for (int i = 0; i < kPerClient; ++i) {
        auto res = cli.Post("/v1/jobs", small_case(c * kPerClient + i).dump(), "application/json");
        if (res && res->status == 202) ++accepted;
      }
    });
  }
  for (auto& t : clients) t.join();
  ASSERT_EQ(accepted.load(), kClients * kPerClient);

  auto cli = svc.client();
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(150);
  std::string metrics;
  const std::string all_done =
      "fosls_jobs{state=\"succeeded\"} " + std::to_string(kClients * kPerClient) + "\n";
  while (std::chrono::steady_clock::now() < give_up) {
    metrics = cli.Get("/metrics")->body;
    if (metrics.find(all_done) != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_NE(metrics.find(all_done), std::string::npos) << metrics;

  // Every job listed as succeeded, walking all pages.
  std::set<int> succeeded;
  std::string token;
  do {
    std::string path = "/v1/jobs?state=succeeded&page_size=100";
    if (!token.empty()) path += "&page_token=" + token;
    json page = json::parse(cli.Get(path.c_str())->body);
    for (const auto& j : page["jobs"]) succeeded.insert(j["id"].get<int>());
    token = page["next_page_token"].is_null() ? "" : page["next_page_token"].get<std::string>();
  } while (!token.empty());
  EXPECT_EQ(succeeded.size(), static_cast<std::size_t>(kClients * kPerClient));

  const std::string log = svc.log();
  EXPECT_EQ(log.find("database is locked"), std::string::npos);
  EXPECT_EQ(log.find("store_error"), std::string::npos);
  EXPECT_EQ(log.find("\"status\":5"), std::string::npos);
}

TEST(ServiceIntegration, SecondServerOnTheSameDatabaseIsRefused) {
  Service svc(1);
  EXPECT_THROW(ServerProcess(FOSLS_SERVE_PATH, {"--db", svc.db()}, svc.db() + ".second.log"),
               std::runtime_error);
  std::ifstream in(svc.db() + ".second.log");
  std::stringstream second_log;
  second_log << in.rdbuf();
  EXPECT_NE(second_log.str().find("another fosls-serve is using"), std::string::npos);
  EXPECT_EQ(svc.client().Get("/healthz")->status, 200);  // the first one is unaffected
}

TEST(ServiceIntegration, IdempotencyKey) {
  Service svc(1);
  const httplib::Headers key = {{"Idempotency-Key", "client-7-request-1"}};
  auto first = svc.post(small_case(1), key);
  ASSERT_EQ(first->status, 202) << first->body;
  auto again = svc.post(small_case(1), key);
  ASSERT_TRUE(again->status == 200 || again->status == 202) << again->body;
  EXPECT_EQ(json::parse(again->body)["id"], json::parse(first->body)["id"]);
  EXPECT_EQ(again->get_header_value("Location"), first->get_header_value("Location"));
  auto other = svc.post(small_case(2), key);
  expect_problem(other, 422);
  auto cli = svc.client();
  EXPECT_EQ(json::parse(cli.Get("/v1/jobs")->body)["jobs"].size(), 1u);
}

}  // namespace
}  // namespace fosls::service
