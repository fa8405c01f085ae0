// The real fosls-serve against hostile HTTP (issue 31 of the hostile probe): header floods cut
// off while they are read, with the server's resident memory measured from /proc; strict
// header-field syntax (RFC 9112 §5.1); keep-alive and pipelining still working. Memory bounds
// are asserted with a wide margin; the numbers are printed for docs/service.md.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <poll.h>

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "http_client.hpp"
#include "service_fixture.hpp"

namespace fosls::service {
namespace {

using nlohmann::json;
using testing::raw_body;
using testing::raw_http;
using testing::RawResponse;
using testing::Service;

constexpr std::size_t kMiB = 1024 * 1024;

/// A line of /proc/PID/status in bytes ("VmRSS", "VmHWM").
std::size_t proc_status_bytes(pid_t pid, const std::string& key) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + ":", 0) == 0) return std::stoull(line.substr(key.size() + 1)) * 1024;
  return 0;
}

int connect_loopback(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    close(fd);
    return -1;
  }
  return fd;
}

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

}  // namespace
}  // namespace fosls::service
