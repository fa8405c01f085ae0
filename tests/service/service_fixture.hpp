#pragma once
// What the integration tests share: the shipped examples, cases of known run time, and a
// Service (the real fosls-serve on a free loopback port with its own temporary database,
// stopped by each test even when it fails).

#include <gtest/gtest.h>
#include <httplib.h>

#include <chrono>
#include <fstream>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "server_process.hpp"
#include "temp_dir.hpp"

namespace fosls::service::testing {

using nlohmann::json;

inline json example(const std::string& name) {
  std::ifstream in(std::string(FOSLS_EXAMPLES_DIR) + "/" + name + ".json");
  std::stringstream ss;
  ss << in.rdbuf();
  return json::parse(ss.str());
}

/// Solves in a fraction of a second.
inline json small_case(int tag = 0) {
  json j = example("signorini_square");
  j["name"] = "small-" + std::to_string(tag);
  j["mesh"]["refinements"] = 1;
  return j;
}

/// Projected Gauss–Seidel on a fine mesh with an unreachable tolerance: runs for hours
/// unless cancelled.
inline json endless_case() {
  json j = example("signorini_square");
  j["name"] = "endless";
  j["mesh"]["refinements"] = 5;
  j["solver"] = {{"method", "pgs"}, {"tolerance", 1e-15}, {"max_iterations", 100000}};
  return j;
}

/// Runs long enough (150 PGS sweeps, about two seconds) to be caught running, then finishes.
inline json medium_case() {
  json j = example("signorini_square");
  j["name"] = "medium";
  j["mesh"]["refinements"] = 4;
  j["solver"] = {{"method", "pgs"}, {"tolerance", 1e-15}, {"max_iterations", 150}};
  return j;
}

/// A service instance with its temporary folder, database and log.
class Service {
 public:
  explicit Service(int workers = 2, std::vector<std::string> extra = {}) {
    start(workers, std::move(extra));
  }

  void start(int workers, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = {
        "--db", db(), "--workers", std::to_string(workers), "--web-root", dir_.path().string()};
    args.insert(args.end(), extra.begin(), extra.end());
    server_ = std::make_unique<ServerProcess>(FOSLS_SERVE_PATH, args, dir_.file("server.log"));
  }
  ServerProcess& server() { return *server_; }
  std::string db() const { return dir_.file("jobs.db"); }
  std::string log() const { return server_->log(); }

  httplib::Client client() const {
    httplib::Client cli("127.0.0.1", server_->port());
    cli.set_read_timeout(std::chrono::seconds(60));
    return cli;
  }

  httplib::Result post(const json& body, const httplib::Headers& headers = {}) {
    return client().Post("/v1/jobs", headers, body.dump(), "application/json");
  }

  std::int64_t submit(const json& body) {
    auto res = post(body);
    if (!res || res->status != 202) {
      ADD_FAILURE() << "submit failed: " << (res ? res->body : "no response");
      return 0;
    }
    return json::parse(res->body)["id"].get<std::int64_t>();
  }

  json job(std::int64_t id) {
    auto res = client().Get("/v1/jobs/" + std::to_string(id));
    return res && res->status == 200 ? json::parse(res->body) : json();
  }

  /// Polls the job until `done` holds; the bound only keeps a broken server from hanging
  /// the suite (no timing is asserted).
  json wait_for(std::int64_t id, const std::function<bool(const json&)>& done, int seconds = 120) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    for (;;) {
      json j = job(id);
      if (!j.is_null() && done(j)) return j;
      if (std::chrono::steady_clock::now() > give_up) {
        ADD_FAILURE() << "job " << id << " did not get there; last seen: " << j.dump();
        return j;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  json wait_state(std::int64_t id, const std::string& state, int seconds = 120) {
    return wait_for(
        id, [&](const json& j) { return j["state"] == state; }, seconds);
  }

 private:
  TempDir dir_;
  std::unique_ptr<ServerProcess> server_;
};

inline bool is_finished(const json& job) {
  return job["state"] == "succeeded" || job["state"] == "failed" || job["state"] == "cancelled";
}

inline void expect_problem(const httplib::Result& res, int status) {
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, status) << res->body;
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/problem+json");
  json p = json::parse(res->body, nullptr, false);
  ASSERT_FALSE(p.is_discarded()) << res->body;
  EXPECT_EQ(p["status"], status);
  EXPECT_TRUE(p.contains("type") && p.contains("title") && p.contains("detail"));
}

}  // namespace fosls::service::testing
