#pragma once
// The head of an HTTP/1.1 request (request line and header fields) checked byte by byte while
// it arrives, before cpp-httplib parses it: bounded in bytes and field count, so one client
// cannot make the server hold an unbounded head (cpp-httplib 0.11.4 keeps every field line of
// up to 8 KiB, without a count limit), and strict where RFC 9112 requires it, so that every
// proxy in front frames the request as this server does (docs/service.md, "Hostile use").

#include <cstddef>
#include <string>
#include <string_view>

namespace fosls::service {

struct RequestHeadLimits {
  std::size_t max_request_line = 8192;  ///< with its CRLF; longer: 414 (cpp-httplib's limit)
  std::size_t max_field_line = 8192;    ///< one field line with its CRLF; longer: 431
  std::size_t max_fields = 100;         ///< header fields; more: 431
  std::size_t max_head_bytes = 65536;   ///< request line and fields together; more: 431
};

/// Why a head is refused: 400 (malformed), 414 (request line) or 431 (fields), and a sentence
/// that names the field and the limit.
struct HeadRejection {
  int status = 400;
  std::string detail;
};

/// Reads one request head incrementally. Feed it the connection's bytes as they come; it stops
/// at the blank line that ends the head, or at the first byte that breaks a limit or the syntax,
/// so nothing beyond that byte needs to be read or kept.
class RequestHeadScanner {
 public:
  enum class State { kReading, kComplete, kRejected };

  explicit RequestHeadScanner(RequestHeadLimits limits = {}) : limits_(limits) {}

  /// Scans the next bytes; returns how many it consumed: all of `bytes` while the head goes
  /// on, those up to and including the blank line once complete, and none after a rejection
  /// (the rejected byte included).
  std::size_t scan(std::string_view bytes);

  State state() const { return state_; }
  const HeadRejection& rejection() const { return rejection_; }
  /// Bytes of empty lines before the request line, which RFC 9112 §2.2 says to ignore.
  std::size_t leading_empty_bytes() const { return leading_empty_bytes_; }
  /// The request line without CRLF (so far, and at most max_request_line bytes).
  const std::string& request_line() const { return request_line_; }

 private:
  bool take(char c);  // false once the head is complete or rejected
  bool end_line();
  bool request_line_byte(char c);
  bool field_byte(char c);
  bool reject(int status, std::string detail);

  RequestHeadLimits limits_;
  State state_ = State::kReading;
  HeadRejection rejection_;
  std::size_t head_bytes_ = 0;  ///< of the request line and the fields
  std::size_t leading_empty_bytes_ = 0;
  std::size_t line_bytes_ = 0;  ///< of the current line, CR included
  bool after_cr_ = false;
  bool in_request_line_ = true;
  std::size_t fields_ = 0;
  std::string request_line_;
  std::string field_name_;  ///< of the current field line (at most max_field_line bytes)
  bool after_colon_ = false;
};

}  // namespace fosls::service
