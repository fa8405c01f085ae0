// Issue 50's inputs that reach the server, each against the real fosls-serve (one worker): the
// answer the issue asks for is asserted, the server's resident memory and /healthz latency
// while it handles the input are printed ("probe ...:" lines) for docs/service.md, "Hostile
// use, third round", and bounded with a wide margin.
//
// FOSLS_PROBE_SERVE=/path/to/fosls-serve runs the probes against another build (with its
// fosls-solve-job beside it), for before-and-after tables measured side by side.

#include <gtest/gtest.h>
#include <httplib.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "hostile_cases.hpp"
#include "http_client.hpp"
#include "server_process.hpp"
#include "server_watch.hpp"
#include "temp_dir.hpp"

namespace fosls::service {
namespace {

using nlohmann::json;
using testing::kMiB;
using testing::percentile;
using testing::ServerWatch;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/// fosls-serve with one worker on its own database.
class ProbedServer {
 public:
  ProbedServer() {
    const char* other = std::getenv("FOSLS_PROBE_SERVE");
    server_ = std::make_unique<testing::ServerProcess>(
        other && *other ? other : FOSLS_SERVE_PATH,
        std::vector<std::string>{"--db", dir_.file("jobs.db"), "--workers", "1"},
        dir_.file("server.log"));
  }
  int port() const { return server_->port(); }
  pid_t pid() const { return server_->pid(); }
  httplib::Client client() const {
    httplib::Client cli("127.0.0.1", port());
    cli.set_read_timeout(std::chrono::seconds(300));
    cli.set_write_timeout(std::chrono::seconds(300));
    return cli;
  }
  httplib::Result post(const std::string& body) {
    return client().Post("/v1/jobs", body, "application/json");
  }
  json job(std::int64_t id) {
    auto res = client().Get("/v1/jobs/" + std::to_string(id));
    return res && res->status == 200 ? json::parse(res->body) : json();
  }
  /// Polls until the job's state is one of `states` (the bound only keeps a broken server from
  /// hanging the suite).
  json wait_state(std::int64_t id, const std::vector<std::string>& states, int seconds = 600) {
    const auto give_up = Clock::now() + std::chrono::seconds(seconds);
    for (;;) {
      json j = job(id);
      for (const auto& s : states)
        if (!j.is_null() && j["state"] == s) return j;
      if (Clock::now() > give_up) {
        ADD_FAILURE() << "job " << id << " never reached the state asked; last: " << j.dump();
        return j;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }

 private:
  testing::TempDir dir_;
  std::unique_ptr<testing::ServerProcess> server_;
};

json square_case(const json& mesh) {
  return {{"name", "probe"},
          {"mesh", mesh},
          {"material", {{"mu", 1}, {"lambda", 1}}},
          {"boundary",
           {{"top", {{"type", "dirichlet"}, {"displacement", {0, -0.05}}}},
            {"left", {{"type", "neumann"}, {"traction", {0, 0}}}},
            {"right", {{"type", "neumann"}, {"traction", {0, 0}}}},
            {"bottom",
             {{"type", "contact"}, {"obstacle", {{"type", "gap"}, {"g", "0.4*(x-0.5)^2"}}}}}}}};
}

/// Item 1: a request naming 6 000 groups a mesh of 20 000 does not have (777 KB). Before: each
/// error listed all 20 000 names, a 660 MB answer for 3 000 names, bad_alloc for 6 000.
void probe_unknown_groups(int dimension) {
  ProbedServer server;
  json c = {{"name", "unknown groups"},
            {"mesh", {{"msh", testing::mesh_with_names(dimension, 20000)}, {"refinements", 0}}},
            {"material", {{"mu", 1}, {"lambda", 1}}},
            {"boundary", json::object()}};
  if (dimension == 3) c["dimension"] = 3;
  const json zero = dimension == 3 ? json{0, 0, 0} : json{0, 0};
  // One group the mesh has holds the body, so that the groups are checked against the mesh.
  c["boundary"][dimension == 3 ? "rest" : "top"] = {{"type", "dirichlet"}, {"displacement", zero}};
  for (int k = 0; k < 6000; ++k)
    c["boundary"]["no_such_boundary_group_" + std::to_string(k)] = {{"type", "neumann"},
                                                                    {"traction", zero}};
  const std::string body = c.dump();
  ServerWatch watch(server.pid(), server.port());
  const auto t0 = Clock::now();
  auto res = server.post(body);
  const double post_ms = ms_since(t0);
  watch.stop(std::chrono::milliseconds(500));
  ASSERT_TRUE(res) << "no answer: the server died?";
  EXPECT_EQ(res->status, 422);
  const json problem = json::parse(res->body, nullptr, false);
  ASSERT_FALSE(problem.is_discarded());
  std::size_t longest = 0, unknown = 0;
  for (const json& e : problem["errors"]) {
    longest = std::max(longest, e["detail"].get<std::string>().size());
    unknown += e["detail"].get<std::string>().find("has no boundary group") != std::string::npos;
  }
  EXPECT_EQ(unknown, 6000u) << "every unknown group is named at its own pointer: "
                            << res->body.substr(0, 1000);
  EXPECT_LT(longest, 2000u) << "an error lists the mesh's groups without bound";
  EXPECT_LT(res->body.size(), 8 * kMiB);
  EXPECT_LT(watch.peak(), watch.before() + 300 * kMiB);
  std::printf(
      "probe unknown groups %dD: a %.0f KB request, 422 of %.2f MB (longest error %zu "
      "characters) in %.0f ms; %s\n",
      dimension, body.size() / 1e3, res->body.size() / 1e6, longest, post_ms,
      watch.summary().c_str());
}

TEST(HostileProbes, UnknownGroupNamesAgainstTwentyThousandGroupsGetABounded422In2d) {
  probe_unknown_groups(2);
}

TEST(HostileProbes, UnknownGroupNamesAgainstTwentyThousandGroupsGetABounded422In3d) {
  probe_unknown_groups(3);
}

/// Item 5: 4 MB of MSH text holding 190 000 physical names (the square's four used). Before:
/// names de-duplicated in quadratic time three times per job, the POST took 54 s and a cancel
/// in the server's own phase 13.6 s. Now: admitted, solved; a cancel right after the claim
/// takes effect (the times are printed, not asserted).
TEST(HostileProbes, FourMegabytesOfPhysicalNamesAreAdmittedSolvedAndCancelled) {
  ProbedServer server;
  const json c = square_case({{"msh", testing::mesh_with_names(2, 190000)}, {"refinements", 2}});
  const std::string body = c.dump();
  ASSERT_GT(body.size(), 3900000u);
  ServerWatch watch(server.pid(), server.port());
  auto t0 = Clock::now();
  auto res = server.post(body);
  const double post_ms = ms_since(t0);
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 202) << res->body.substr(0, 2000);
  const auto first = json::parse(res->body)["id"].get<std::int64_t>();
  const json solved = server.wait_state(first, {"succeeded", "failed"});
  EXPECT_EQ(solved["state"], "succeeded") << solved.dump();
  const double solved_ms = ms_since(t0);

  // The same case again, cancelled as soon as its worker has claimed it.
  res = server.post(body);
  ASSERT_TRUE(res && res->status == 202);
  const auto second = json::parse(res->body)["id"].get<std::int64_t>();
  server.wait_state(second, {"running", "succeeded", "failed"});
  t0 = Clock::now();
  auto cancel = server.client().Post("/v1/jobs/" + std::to_string(second) + "/cancel");
  ASSERT_TRUE(cancel);
  const json after = server.wait_state(second, {"cancelled", "succeeded", "failed"});
  const double cancel_ms = ms_since(t0);
  watch.stop(std::chrono::milliseconds(500));
  EXPECT_EQ(after["state"], "cancelled") << after.dump();
  EXPECT_EQ(watch.health_failures(), 0);
  EXPECT_LT(percentile(watch.health_ms(), 0.9), 100.0);
  EXPECT_LT(watch.after(), watch.before() + 100 * kMiB);
  std::printf(
      "probe 190 000 physical names: a %.1f MB request, 202 in %.0f ms, succeeded %.0f ms "
      "after the POST; a cancel once running: cancelled in %.0f ms; %s\n",
      body.size() / 1e6, post_ms, solved_ms, cancel_ms, watch.summary().c_str());
}

/// Item 7: 100 clients ask for a large solution VTU and do not read it. Before: each held about
/// 28 MB of the server (a 9.9 MB 3D VTU), /healthz took 4.4 s. The VTU here is the square at 6
/// refinements, 16 MB; the server's part is the same whatever the VTU's dimension.
TEST(HostileProbes, StalledDownloadsOfALargeVtuHoldAPartEachNotTheVtu) {
  ProbedServer server;
  json c = square_case({{"builtin", "square"}, {"size", 0.25}, {"refinements", 6}});
  auto res = server.post(c.dump());
  ASSERT_TRUE(res && res->status == 202) << (res ? res->body : "no answer");
  const auto id = json::parse(res->body)["id"].get<std::int64_t>();
  ASSERT_EQ(server.wait_state(id, {"succeeded", "failed"})["state"], "succeeded");
  const std::string path = "/v1/jobs/" + std::to_string(id) + "/solution.vtu";
  auto whole = server.client().Get(path);  // a client that reads, for the size
  ASSERT_TRUE(whole && whole->status == 200);
  const std::size_t vtu_bytes = whole->body.size();
  EXPECT_NE(whole->body.find("</VTKFile>"), std::string::npos);

  ServerWatch watch(server.pid(), server.port());
  std::vector<int> stalled;
  for (int k = 0; k < 100; ++k) {
    const int fd = testing::connect_loopback(server.port());
    ASSERT_GE(fd, 0);
    const std::string request = "GET " + path + " HTTP/1.1\r\nHost: x\r\n" +
                                (k % 2 ? "Accept-Encoding: gzip\r\n" : "") + "\r\n";
    ASSERT_EQ(send(fd, request.data(), request.size(), MSG_NOSIGNAL),
              static_cast<ssize_t>(request.size()));
    stalled.push_back(fd);  // never read
  }
  std::this_thread::sleep_for(std::chrono::seconds(4));  // the server's write timeout is 5 s
  auto again = server.client().Get(path);                // while they still stall
  for (int fd : stalled) close(fd);
  watch.stop(std::chrono::milliseconds(1000));
  ASSERT_TRUE(again);
  EXPECT_EQ(again->body.size(), vtu_bytes);
  EXPECT_EQ(watch.health_failures(), 0);
  EXPECT_LT(percentile(watch.health_ms(), 0.9), 100.0);
  // 100 parts of 256 KiB and their buffers are 50 MiB; a whole VTU each would be 1.6 GB.
  EXPECT_LT(watch.peak(), watch.before() + 150 * kMiB);
  std::printf("probe 100 stalled downloads of a %.1f MB VTU: %s\n", vtu_bytes / 1e6,
              watch.summary().c_str());
}

/// Item 6: a 4 MB case (its mesh) with 100 load steps, posted twice. Before: the server grew by
/// 1.2 GB per post (a copy of the case per step). Pending in docs/service.md until item 6 (the
/// case layer's admission of load steps) is fixed: enable it then.
TEST(HostileProbes, DISABLED_ALoadStepCaseOfFourMegabytesIsAdmittedWithoutACopyPerStep) {
  ProbedServer server;
  json c = square_case({{"msh", testing::grid_msh(235)}, {"refinements", 0}});
  c["load_steps"] = json::array();
  for (int k = 1; k <= 100; ++k)
    c["load_steps"].push_back({{"/boundary/top/displacement/1", -0.05 - 0.0001 * k}});
  const std::string body = c.dump();
  ASSERT_GT(body.size(), 3500000u);
  ServerWatch watch(server.pid(), server.port());
  std::vector<int> statuses;
  for (int k = 0; k < 2; ++k) {
    auto res = server.post(body);
    ASSERT_TRUE(res) << "no answer";
    statuses.push_back(res->status);
  }
  watch.stop(std::chrono::milliseconds(1000));
  for (int s : statuses) EXPECT_TRUE(s == 202 || s == 422) << s;
  EXPECT_LT(watch.peak(), watch.before() + 300 * kMiB);
  std::printf("probe 4 MB case with 100 load steps, posted twice: %d, %d; %s\n", statuses[0],
              statuses[1], watch.summary().c_str());
}

/// Item 3: data that overflow to NaN in the solve. Before: "converged in 1 iterations …
/// relative KKT residual -nan", succeeded. Now the job fails, saying the numbers are not finite.
TEST(HostileProbes, CasesThatOverflowToNanFailNamingTheCause) {
  ProbedServer server;
  json two = square_case({{"builtin", "square"}, {"size", 0.25}, {"refinements", 2}});
  two["boundary"]["top"]["displacement"] = {0, "-0.01*(1+1e300*(x>0.7))"};
  json three = {
      {"name", "nan 3d"},
      {"dimension", 3},
      {"mesh", {{"builtin", {{"name", "box"}, {"cells", {2, 2, 2}}}}, {"refinements", 1}}},
      {"material", {{"mu", 1}, {"lambda", 1}}},
      {"boundary",
       {{"top", {{"type", "dirichlet"}, {"displacement", {0, 0, "-0.01*(1+1e300*(x>0.7))"}}}},
        {"bottom", {{"type", "contact"}, {"point", {0, 0, 0}}, {"normal", {0, 0, 1}}}}}}};
  json pressure = three;
  pressure["boundary"]["top"] = {{"type", "pressure"}, {"pressure", 1e300}};
  pressure["boundary"]["left"] = {{"type", "dirichlet"}, {"displacement", {0, 0, 0}}};
  ServerWatch watch(server.pid(), server.port());
  for (const json& c : {two, three, pressure}) {
    auto res = server.post(c.dump());
    ASSERT_TRUE(res);
    if (res->status == 422) {  // refused at admission: as good, if it names the cause
      EXPECT_NE(res->body.find("finite"), std::string::npos) << res->body;
      continue;
    }
    ASSERT_EQ(res->status, 202) << res->body;
    const auto id = json::parse(res->body)["id"].get<std::int64_t>();
    const json done = server.wait_state(id, {"succeeded", "failed", "cancelled"});
    EXPECT_EQ(done["state"], "failed") << c.dump() << "\n" << done.dump();
    EXPECT_NE(done["error"].get<std::string>().find("not finite"), std::string::npos)
        << done.dump();
    std::printf("probe non-finite case: %s\n",
                done["error"].get<std::string>().substr(0, 160).c_str());
  }
  watch.stop();
  std::printf("probe non-finite cases: %s\n", watch.summary().c_str());
}

}  // namespace
}  // namespace fosls::service
