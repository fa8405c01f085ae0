// BoundedHttpServer on its own: a head that arrives too slowly is refused with 408, refusals
// reach the handler with the request line's method and path, and requests that pass are
// served by cpp-httplib's routing as before.

#include "bounded_http_server.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <thread>

#include "http_client.hpp"

namespace fosls::service {
namespace {

using testing::raw_body;
using testing::raw_http;

class SmallServer {
 public:
  explicit SmallServer(HttpServerLimits limits) : server_(limits) {
    server_.Get("/hello", [](const httplib::Request&, httplib::Response& res) {
      res.set_content("hello", "text/plain");
    });
    server_.set_head_refusal_handler([this](const httplib::Request& req,
                                            const HeadRejection& rejection,
                                            httplib::Response& res) {
      refused_method_ = req.method;
      refused_path_ = req.path;
      res.set_content(std::to_string(rejection.status) + ": " + rejection.detail, "text/plain");
    });
    port_ = server_.bind_to_any_port("127.0.0.1");
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ~SmallServer() {
    server_.stop();
    thread_.join();
  }
  int port() const { return port_; }
  std::string refused_method_, refused_path_;

 private:
  BoundedHttpServer server_;
  int port_ = 0;
  std::thread thread_;
};

TEST(BoundedHttpServer, ASlowHeadIsRefusedWith408AtItsDeadline) {
  HttpServerLimits limits;
  limits.head_deadline = std::chrono::milliseconds(300);
  SmallServer server(limits);
  // The head trickles in: each piece within the read timeout, the whole beyond the deadline.
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(server.port()));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  std::string answer;
  for (const char* piece : {"GET /hello HTTP/1.1\r\n", "X-A: 1\r\n", "X-B: 2\r\n", "X-C: 3\r\n"}) {
    if (send(fd, piece, strlen(piece), MSG_NOSIGNAL) <= 0) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
  }
  timeval tv{5, 0};
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  char buf[1024];
  for (ssize_t n; (n = recv(fd, buf, sizeof buf, 0)) > 0;) answer.append(buf, n);
  close(fd);
  EXPECT_EQ(answer.rfind("HTTP/1.1 408 Request Timeout\r\n", 0), 0u) << answer;
  EXPECT_NE(answer.find("within 300 ms"), std::string::npos) << answer;
  EXPECT_EQ(server.refused_method_, "GET");
  EXPECT_EQ(server.refused_path_, "/hello");
}

TEST(BoundedHttpServer, HeadsThatPassAreServedAndRefusalsCloseTheConnection) {
  SmallServer server({});
  const auto ok =
      raw_http(server.port(), "GET /hello HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(ok.status, 200);
  EXPECT_EQ(raw_body(ok), "hello");
  // A refused head and a request behind it: the refusal is the only answer.
  const auto refused = raw_http(server.port(),
                                "GET /hello?x=1 HTTP/1.1\r\nHost : x\r\n\r\n"
                                "GET /hello HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_EQ(refused.status, 400) << refused.text;
  EXPECT_NE(refused.text.find("Connection: close"), std::string::npos);
  EXPECT_EQ(refused.text.find("hello", refused.text.find("\r\n\r\n")), std::string::npos)
      << refused.text;
  EXPECT_EQ(server.refused_path_, "/hello");
}

}  // namespace
}  // namespace fosls::service
