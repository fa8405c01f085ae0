// RequestHeadScanner: request heads bounded and checked byte by byte (RFC 9112 §5.1, §2.2).

#include "request_head.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fosls::service {
namespace {

using State = RequestHeadScanner::State;

/// Scans `text` in pieces of `step` bytes, as a socket would deliver it.
RequestHeadScanner scanned(const std::string& text, RequestHeadLimits limits = {},
                           std::size_t step = 7) {
  RequestHeadScanner scanner(limits);
  for (std::size_t at = 0; at < text.size() && scanner.state() == State::kReading; at += step)
    scanner.scan(std::string_view(text).substr(at, step));
  return scanner;
}

TEST(RequestHead, AWellFormedHeadEndsAtItsBlankLineAndLeavesTheBody) {
  const std::string head = "POST /v1/jobs HTTP/1.1\r\nHost: x\r\nContent-Length: 2\r\n\r\n";
  RequestHeadScanner scanner;
  EXPECT_EQ(scanner.scan(head + "{}GET / HTTP/1.1\r\n"), head.size());
  EXPECT_EQ(scanner.state(), State::kComplete);
  EXPECT_EQ(scanner.request_line(), "POST /v1/jobs HTTP/1.1");
  EXPECT_EQ(scanned(head, {}, 1).state(), State::kComplete);  // byte by byte: the same
}

TEST(RequestHead, EmptyLinesBeforeTheRequestLineAreSkippedButNotWithoutEnd) {
  RequestHeadScanner scanner;
  scanner.scan("\r\n\r\nGET / HTTP/1.1\r\n\r\n");
  EXPECT_EQ(scanner.state(), State::kComplete);
  EXPECT_EQ(scanner.leading_empty_bytes(), 4u);
  EXPECT_EQ(scanned(std::string(100, '\r') + "x").state(), State::kRejected);
  const auto many = scanned("\r\n\r\n\r\n\r\n\r\nGET / HTTP/1.1\r\n\r\n");
  EXPECT_EQ(many.state(), State::kRejected);
  EXPECT_EQ(many.rejection().status, 400);
}

TEST(RequestHead, WhitespaceBeforeTheColonIs400NamingTheField) {
  const auto s = scanned(
      "POST /v1/jobs HTTP/1.1\r\nHost: x\r\nTransfer-Encoding : chunked\r\n"
      "Content-Length: 2\r\n\r\n");
  ASSERT_EQ(s.state(), State::kRejected);
  EXPECT_EQ(s.rejection().status, 400);
  EXPECT_NE(s.rejection().detail.find("'Transfer-Encoding'"), std::string::npos)
      << s.rejection().detail;
  EXPECT_NE(s.rejection().detail.find("RFC 9112"), std::string::npos);
  EXPECT_EQ(scanned("GET / HTTP/1.1\r\nHost\t: x\r\n\r\n").rejection().status, 400);
}

TEST(RequestHead, MalformedLinesAre400) {
  for (const char* head : {
           "GET / HTTP/1.1\r\nHost: x\r\n folded\r\n\r\n",  // obsolete line folding
           "GET / HTTP/1.1\r\nHost: x\nX: y\r\n\r\n",       // bare LF
           "GET / HTTP/1.1\r\nHost: x\rX: y\r\n\r\n",       // bare CR
           "GET / HTTP/1.1\r\n: empty name\r\n\r\n",        // no name
           "GET / HTTP/1.1\r\nno colon here\r\n\r\n",       // no colon
           "GET / HTTP/1.1\r\nX(y): 1\r\n\r\n",             // not a token
           "GET / HTTP/1.1\r\nX: a\x01z\r\n\r\n",           // control character
           "GET /\x7f HTTP/1.1\r\n\r\n",                    // control in the request line
       }) {
    const auto s = scanned(head);
    EXPECT_EQ(s.state(), State::kRejected) << head;
    EXPECT_EQ(s.rejection().status, 400) << head;
  }
  // Allowed: tabs and obs-text in values, every token character in names, empty values.
  EXPECT_EQ(scanned("GET / HTTP/1.1\r\nX-a.b!#$%&'*+^_`|~9: a\tb \xe9\r\nY:\r\n\r\n").state(),
            State::kComplete);
}

TEST(RequestHead, LimitsStopReadingAtTheByteThatBreaksThem) {
  RequestHeadLimits limits;
  limits.max_head_bytes = 4096;
  limits.max_fields = 10;
  limits.max_field_line = 1024;
  limits.max_request_line = 512;
  const std::string line = "GET / HTTP/1.1\r\n";

  // One endless field line: refused after max_field_line bytes, without its end.
  RequestHeadScanner endless(limits);
  const std::string flood = line + "X-Flood: " + std::string(100000, 'a');
  const std::size_t taken = endless.scan(flood);
  EXPECT_EQ(endless.state(), State::kRejected);
  EXPECT_EQ(endless.rejection().status, 431);
  EXPECT_EQ(taken, line.size() + limits.max_field_line);
  EXPECT_NE(endless.rejection().detail.find("'X-Flood'"), std::string::npos);

  std::string many = line;
  for (int i = 0; i < 11; ++i) many += "X-" + std::to_string(i) + ": 1\r\n";
  const auto count = scanned(many + "\r\n", limits);
  EXPECT_EQ(count.rejection().status, 431);
  EXPECT_NE(count.rejection().detail.find("more than 10 header fields"), std::string::npos);

  std::string big = line;
  for (int i = 0; i < 10; ++i)
    big += "X-" + std::to_string(i) + ": " + std::string(500, 'v') + "\r\n";
  const auto total = scanned(big + "\r\n", limits);
  EXPECT_EQ(total.rejection().status, 431);
  EXPECT_NE(total.rejection().detail.find("4096 bytes"), std::string::npos);

  const auto uri = scanned("GET /" + std::string(600, 'a') + " HTTP/1.1\r\n\r\n", limits);
  EXPECT_EQ(uri.rejection().status, 414);

  // Exactly at every limit is accepted.
  std::string fits =
      "GET /" + std::string(limits.max_request_line - line.size(), 'a') + " HTTP/1.1\r\n";
  ASSERT_EQ(fits.size(), limits.max_request_line);
  fits += "X: " + std::string(limits.max_field_line - 5, 'v') + "\r\n";
  EXPECT_EQ(scanned(fits + "\r\n", limits).state(), State::kComplete);
}

}  // namespace
}  // namespace fosls::service
