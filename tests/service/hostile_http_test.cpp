// The real fosls-serve against hostile HTTP (issue 31 of the hostile probe): header floods cut
// off while they are read, with the server's resident memory measured from /proc; strict
// header-field syntax (RFC 9112 §5.1); keep-alive and pipelining still working. Memory bounds
// are asserted with a wide margin; the numbers are printed for docs/service.md.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <poll.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "hostile_cases.hpp"
#include "http_client.hpp"
#include "server_watch.hpp"
#include "service_fixture.hpp"

namespace fosls::service {
namespace {

using nlohmann::json;
using testing::connect_loopback;
using testing::grid_msh;
using testing::kMiB;
using testing::percentile;
using testing::proc_status_bytes;
using testing::raw_body;
using testing::raw_http;
using testing::RawResponse;
using testing::Service;

struct Flood {
  std::size_t sent = 0;  ///< bytes the server's socket took before it answered or closed
  RawResponse response;
};

/// Sends `start`, then `line` over and over on one connection until the server answers or
/// closes it, or `cap` bytes went out; then reads the answer.
Flood flood(int port, const std::string& start, const std::string& line, std::size_t cap) {
  Flood out;
  const int fd = connect_loopback(port);
  if (fd < 0) return out;
  fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
  std::string batch = start;
  while (batch.size() < 64 * 1024) batch += line;
  std::size_t offset = 0;
  while (out.sent < cap) {
    pollfd p{fd, POLLIN | POLLOUT, 0};
    if (poll(&p, 1, 10000) <= 0) break;  // neither answered nor read: the test fails below
    if (p.revents & (POLLIN | POLLHUP | POLLERR)) break;
    const ssize_t n = send(fd, batch.data() + offset, batch.size() - offset, MSG_NOSIGNAL);
    if (n < 0 && errno != EAGAIN) break;
    if (n <= 0) continue;
    out.sent += static_cast<std::size_t>(n);
    offset += static_cast<std::size_t>(n);
    if (offset == batch.size()) {  // later batches: only lines
      batch.clear();
      while (batch.size() < 64 * 1024) batch += line;
      offset = 0;
    }
  }
  fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  timeval tv{10, 0};
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  char buf[4096];
  for (ssize_t n; (n = recv(fd, buf, sizeof buf, 0)) > 0;)
    out.response.text.append(buf, static_cast<std::size_t>(n));
  close(fd);
  if (out.response.text.rfind("HTTP/1.1 ", 0) == 0)
    out.response.status = std::stoi(out.response.text.substr(9, 3));
  return out;
}

void expect_head_problem(const RawResponse& r, int status, const std::string& type) {
  EXPECT_EQ(r.status, status) << r.text.substr(0, 400);
  EXPECT_NE(r.text.find("Content-Type: application/problem+json"), std::string::npos) << r.text;
  EXPECT_NE(r.text.find("Connection: close"), std::string::npos) << r.text;
  const json p = json::parse(raw_body(r), nullptr, false);
  ASSERT_FALSE(p.is_discarded()) << r.text;
  EXPECT_EQ(p["status"], status);
  EXPECT_EQ(p["type"], "urn:fosls:problem:" + type);
}

TEST(HostileHttp, HeaderFloodsAreCutOffWhileReadAndMemoryStaysBounded) {
  Service svc(1);
  const pid_t pid = svc.server().pid();
  const std::size_t rss_before = proc_status_bytes(pid, "VmRSS");
  const std::string start = "GET /healthz HTTP/1.1\r\nHost: x\r\n";

  // One connection streaming 8 KB field lines (each within the per-line limit).
  const Flood big =
      flood(svc.server().port(), start, "X-Flood: " + std::string(8000, 'a') + "\r\n", 256 * kMiB);
  expect_head_problem(big.response, 431, "header-fields-too-large");
  EXPECT_LT(big.sent, 64 * kMiB) << "the server kept reading the flood";

  // Four connections at once, each streaming small fields.
  std::vector<Flood> small(4);
  std::vector<std::thread> clients;
  for (Flood& f : small)
    clients.emplace_back(
        [&] { f = flood(svc.server().port(), start, "X-Small: 1\r\n", 64 * kMiB); });
  for (auto& c : clients) c.join();
  for (const Flood& f : small) {
    expect_head_problem(f.response, 431, "header-fields-too-large");
    EXPECT_NE(raw_body(f.response).find("more than 100 header fields"), std::string::npos);
    EXPECT_LT(f.sent, 32 * kMiB);
  }

  const std::size_t rss_after = proc_status_bytes(pid, "VmRSS");
  const std::size_t peak = proc_status_bytes(pid, "VmHWM");
  std::printf(
      "header floods: RSS before %.1f MiB, after %.1f MiB, peak %.1f MiB; the 8 KB-line "
      "flood was cut off after %.2f MiB sent, the small-field floods after %.2f, %.2f, "
      "%.2f, %.2f MiB\n",
      rss_before / double(kMiB), rss_after / double(kMiB), peak / double(kMiB),
      big.sent / double(kMiB), small[0].sent / double(kMiB), small[1].sent / double(kMiB),
      small[2].sent / double(kMiB), small[3].sent / double(kMiB));
  EXPECT_LT(peak, rss_before + 100 * kMiB);
  EXPECT_LT(rss_after, rss_before + 100 * kMiB);
  auto health = svc.client().Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
}

TEST(HostileHttp, OneHundredKilobyteHeaderIs431) {
  Service svc(1);
  const auto r =
      raw_http(svc.server().port(), "GET /healthz HTTP/1.1\r\nHost: x\r\nCookie: " +
                                        std::string(100000, 'c') + "\r\nConnection: close\r\n\r\n");
  expect_head_problem(r, 431, "header-fields-too-large");
  EXPECT_NE(raw_body(r).find("'Cookie' is longer than 8192 bytes"), std::string::npos) << r.text;
}

TEST(HostileHttp, WhitespaceBeforeTheColonIs400AndTheRequestIsNotServed) {
  Service svc(1);
  // A proxy reading "Transfer-Encoding : chunked" as chunked frames this request differently.
  const auto r = raw_http(svc.server().port(),
                          "POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                          "Transfer-Encoding : chunked\r\nContent-Length: 29\r\n\r\n"
                          "0\r\n\r\nGET /healthz HTTP/1.1\r\n\r\n");
  expect_head_problem(r, 400, "malformed-request-head");
  EXPECT_NE(raw_body(r).find("'Transfer-Encoding'"), std::string::npos) << r.text;
  EXPECT_EQ(r.text.find("HTTP/1.1 200"), std::string::npos) << "the body was served: " << r.text;
  auto list = svc.client().Get("/v1/jobs");
  ASSERT_TRUE(list);
  EXPECT_TRUE(json::parse(list->body)["jobs"].empty());
}

TEST(HostileHttp, KeepAliveAndPipelinedRequestsStillWork) {
  Service svc(1);
  // Two requests in one write: both are answered, in order, on one connection.
  const auto both = raw_http(svc.server().port(),
                             "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n"
                             "GET /v1/jobs HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  const auto second = both.text.find("HTTP/1.1 200", 1);
  EXPECT_EQ(both.status, 200) << both.text;
  ASSERT_NE(second, std::string::npos) << "the pipelined request was lost: " << both.text;
  EXPECT_NE(both.text.find("\"jobs\"", second), std::string::npos);

  // A keep-alive client: one connection for many requests, a POST with a body among them.
  auto cli = svc.client();
  cli.set_keep_alive(true);
  for (int i = 0; i < 20; ++i) {
    auto res = cli.Get("/healthz");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200);
  }
  auto post = cli.Post("/v1/jobs", testing::small_case().dump(), "application/json");
  ASSERT_TRUE(post);
  EXPECT_EQ(post->status, 202) << post->body;
  auto after = cli.Get("/v1/jobs");
  ASSERT_TRUE(after);
  EXPECT_EQ(json::parse(after->body)["jobs"].size(), 1u);
}

TEST(HostileHttp, TraceConnectAndOtherUnservedMethodsAre405) {
  Service svc(1);
  struct Probe {
    const char* request;
    const char* allow;
  };
  for (const Probe& p : {
           Probe{"TRACE / HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", "GET, HEAD"},
           Probe{"TRACE /v1/jobs HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", "GET, POST"},
           Probe{"CONNECT example.com:443 HTTP/1.1\r\nHost: example.com:443\r\n\r\n", "GET, HEAD"},
           Probe{"PUT /v1/jobs/1 HTTP/1.1\r\nHost: x\r\nContent-Length: 2\r\n\r\n{}",
                 "GET, DELETE"},
       }) {
    const auto r = raw_http(svc.server().port(), p.request);
    EXPECT_EQ(r.status, 405) << p.request << "\n" << r.text;
    EXPECT_NE(r.text.find(std::string("Allow: ") + p.allow), std::string::npos) << r.text;
    EXPECT_NE(r.text.find("application/problem+json"), std::string::npos) << r.text;
  }
}

TEST(HostileHttp, ARepeatedQueryParameterIs400NamingIt) {
  Service svc(1);
  auto res = svc.client().Get("/v1/jobs?state=queued&page_size=5&state=failed");
  testing::expect_problem(res, 400);
  const json p = json::parse(res->body);
  EXPECT_EQ(p["type"], "urn:fosls:problem:invalid-parameter");
  EXPECT_EQ(p["errors"][0]["parameter"], "state") << res->body;
  EXPECT_NE(p["detail"].get<std::string>().find("given 2 times"), std::string::npos);
}

TEST(HostileHttp, AnEmptiedDatabaseFileIsRefusedNotStartedOver) {
  testing::TempDir dir;
  const std::string db = (dir.path() / "jobs.db").string();
  std::ofstream(db).close();  // 0 bytes: a truncated store
  try {
    testing::ServerProcess server(FOSLS_SERVE_PATH, {"--db", db, "--workers", "0"},
                                  (dir.path() / "server.log").string());
    ADD_FAILURE() << "the server started on an empty database file";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("exists but is empty (0 bytes)"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(std::filesystem::file_size(db), 0u) << "the file was written to";
}

TEST(HostileHttp, LargeBodiesDoNotStallHealthAndTheirMemoryGoesBack) {
  // The probe: 32 clients post a 4 MiB msh case each at once (all refused with 422: a group the
  // mesh lacks, found only once the mesh is read), three rounds, while a monitor asks /healthz
  // every 20 ms on one kept-alive connection. /healthz must keep answering within 100 ms, and
  // the memory the bodies took must go back. The bound is asserted on the 90th percentile (a
  // shared machine's scheduler can hold any one request for a while: single answers of a few
  // hundred ms were seen at load 9-12, as for any request there); the maximum is printed.
  Service svc(1);
  const json big = {{"mesh", {{"msh", grid_msh(235)}, {"refinements", 0}}},
                    {"material", {{"mu", 1}, {"lambda", 1}}},
                    {"boundary", {{"nope", {{"type", "dirichlet"}, {"displacement", {0, 0}}}}}}};
  const std::string body = big.dump();
  ASSERT_GT(body.size(), 3500000u);
  const pid_t pid = svc.server().pid();
  const std::size_t rss_before = proc_status_bytes(pid, "VmRSS");
  std::vector<double> health_ms;
  httplib::Client cli("127.0.0.1", svc.server().port());  // the monitor's, kept alive
  cli.set_keep_alive(true);
  for (int round = 0; round < 3; ++round) {
    std::atomic<bool> posting{true};
    std::thread monitor([&] {
      while (posting) {
        const auto t0 = std::chrono::steady_clock::now();
        auto res = cli.Get("/healthz");
        health_ms.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
        EXPECT_TRUE(res && res->status == 200);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    });
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::thread> clients;
    std::atomic<int> refused{0};
    for (int c = 0; c < 32; ++c)
      clients.emplace_back([&] {
        httplib::Client poster("127.0.0.1", svc.server().port());
        poster.set_read_timeout(std::chrono::seconds(120));
        auto res = poster.Post("/v1/jobs", body, "application/json");
        if (res && res->status == 422) ++refused;
      });
    for (auto& c : clients) c.join();
    posting = false;
    monitor.join();
    std::printf("round %d: 32 posts of %.1f MiB in %.1f s, %d refused with 422\n", round + 1,
                body.size() / double(kMiB),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                refused.load());
    EXPECT_EQ(refused.load(), 32);
  }
  std::this_thread::sleep_for(std::chrono::seconds(1));
  const std::size_t rss_after = proc_status_bytes(pid, "VmRSS");
  const std::size_t peak = proc_status_bytes(pid, "VmHWM");
  std::printf(
      "/healthz during the posts: %zu answers, median %.1f ms, p90 %.1f ms, max %.1f ms; "
      "RSS before %.0f MiB, peak %.0f MiB, after %.0f MiB\n",
      health_ms.size(), percentile(health_ms, 0.5), percentile(health_ms, 0.9),
      percentile(health_ms, 1.0), rss_before / double(kMiB), peak / double(kMiB),
      rss_after / double(kMiB));
  EXPECT_LT(percentile(health_ms, 0.9), 100.0);
  EXPECT_LT(rss_after, rss_before + 100 * kMiB);
}

/// fosls-serve with its database on a tmpfs of 4 MiB in a mount namespace of its own (unshare
/// -rm: as root, or wherever user namespaces are allowed); the tmpfs goes with the server.
class ServerOnSmallDisk {
 public:
  ServerOnSmallDisk() {
    std::filesystem::create_directories(disk_);
    ::setenv("FOSLS_TEST_SMALL_DISK", disk_.c_str(), 1);
    const std::string mount = "mount -t tmpfs -o size=4m tmpfs \"$FOSLS_TEST_SMALL_DISK\"";
    available_ = std::system(("unshare -rm sh -c '" + mount + "' 2>/dev/null").c_str()) == 0;
    if (!available_) return;
    std::ofstream(script_) << "#!/bin/sh\nexec unshare -rm sh -c '" << mount
                           << " || exit 97; exec \"$0\" \"$@\"' " << FOSLS_SERVE_PATH
                           << " \"$@\"\n";
    std::filesystem::permissions(script_, std::filesystem::perms::owner_all);
    server_ = std::make_unique<testing::ServerProcess>(
        script_.string(),
        std::vector<std::string>{"--db", (disk_ / "jobs.db").string(), "--workers", "0"},
        (dir_.path() / "server.log").string());
  }
  bool available() const { return available_; }
  testing::ServerProcess& server() { return *server_; }
  /// The tmpfs as the server sees it (through its root, in its mount namespace).
  std::filesystem::path disk() const {
    return "/proc/" + std::to_string(server_->pid()) + "/root" + disk_.string();
  }

 private:
  testing::TempDir dir_;
  std::filesystem::path disk_ = dir_.path() / "disk", script_ = dir_.path() / "serve.sh";
  bool available_ = false;
  std::unique_ptr<testing::ServerProcess> server_;
};

TEST(HostileHttp, AFullDiskIsSaidToBeFullByPostAndHealth) {
  ServerOnSmallDisk small;
  if (!small.available()) GTEST_SKIP() << "no tmpfs can be mounted here (unshare -rm refused)";
  httplib::Client cli("127.0.0.1", small.server().port());
  const std::string body = testing::small_case().dump();
  auto first = cli.Post("/v1/jobs", body, "application/json");
  ASSERT_TRUE(first);
  EXPECT_EQ(first->status, 202) << first->body;
  // Fill the disk from outside, then submit until the store meets it (its WAL may have room
  // for a few).
  const auto filler = small.disk() / "filler";
  {
    std::ofstream out(filler, std::ios::binary);
    const std::string block(64 * 1024, '\0');
    while (out.write(block.data(), block.size())) {
    }
  }
  int status = 0;
  std::string answer;
  for (int i = 0; i < 200 && status != 507; ++i) {
    auto res = cli.Post("/v1/jobs", body, "application/json");
    ASSERT_TRUE(res) << "no answer";
    status = res->status;
    answer = res->body;
    if (status != 202) break;
  }
  EXPECT_EQ(status, 507) << answer;
  const json problem = json::parse(answer, nullptr, false);
  EXPECT_EQ(problem["type"], "urn:fosls:problem:store-full") << answer;
  EXPECT_NE(answer.find("disk is full"), std::string::npos) << answer;
  auto health = cli.Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 503) << health->body;
  EXPECT_NE(health->body.find("store-full"), std::string::npos) << health->body;
  std::printf("full disk: POST %d, /healthz %d: %s\n", status, health->status,
              json::parse(health->body)["detail"].get<std::string>().c_str());
  // Space freed: the next submit goes through, and health is ok again.
  std::filesystem::remove(filler);
  auto again = cli.Post("/v1/jobs", body, "application/json");
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 202) << again->body;
  auto healthy = cli.Get("/healthz");
  ASSERT_TRUE(healthy);
  EXPECT_EQ(healthy->status, 200) << healthy->body;
}

}  // namespace
}  // namespace fosls::service
