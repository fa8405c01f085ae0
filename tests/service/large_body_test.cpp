// set_large_body: a browser's Accept-Encoding (gzip, deflate, br) gets gzip, never
// cpp-httplib's brotli at quality 11 (51 s for an 18.7 MB VTU); a client without gzip gets the
// body as it is. Either way the client reads back exactly the bytes given.
#include "large_body.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "gzip.hpp"

namespace fosls::service {
namespace {

class LargeBodyServer {
 public:
  explicit LargeBodyServer(std::string body) : body_(std::move(body)) {
    server_.Get("/big", [this](const httplib::Request& req, httplib::Response& res) {
      set_large_body(req, res, body_, "application/xml");
    });
    port_ = server_.bind_to_any_port("127.0.0.1");
    thread_ = std::thread([this] { server_.listen_after_bind(); });
    while (!server_.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ~LargeBodyServer() {
    server_.stop();
    thread_.join();
  }
  /// GET /big with `accept_encoding`, the body left encoded as sent.
  httplib::Result get(const std::string& accept_encoding) {
    httplib::Client cli("127.0.0.1", port_);
    cli.set_decompress(false);
    return cli.Get("/big", {{"Accept-Encoding", accept_encoding}});
  }

 private:
  std::string body_;
  httplib::Server server_;
  int port_ = 0;
  std::thread thread_;
};

std::string vtu_like_text() {
  std::string text = "<VTKFile type=\"UnstructuredGrid\">\n";
  for (int i = 0; i < 200000; ++i) text += std::to_string(i * 0.001) + " 0.25 0\n";
  return text + "</VTKFile>\n";
}

TEST(LargeBody, ABrowserGetsGzipNotBrotli) {
  const std::string text = vtu_like_text();
  LargeBodyServer server(text);
  auto res = server.get("gzip, deflate, br");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(res->get_header_value("Content-Encoding"), "gzip");
  EXPECT_EQ(res->get_header_value("Content-Type"), "application/xml");
  EXPECT_EQ(res->get_header_value("Vary"), "Accept-Encoding");
  EXPECT_LT(res->body.size(), text.size() / 2);
  EXPECT_EQ(gzip_decompress(res->body), text);
}

TEST(LargeBody, WithoutGzipTheBodyIsSentAsItIs) {
  const std::string text = vtu_like_text();
  LargeBodyServer server(text);
  for (const char* accept : {"br", "identity", ""}) {
    auto res = server.get(accept);
    ASSERT_TRUE(res) << accept;
    EXPECT_FALSE(res->has_header("Content-Encoding")) << accept;
    EXPECT_EQ(res->get_header_value("Content-Length"), std::to_string(text.size())) << accept;
    EXPECT_EQ(res->body, text) << accept;
  }
}

}  // namespace
}  // namespace fosls::service
