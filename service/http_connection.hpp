#pragma once
// One client connection of the HTTP server as a cpp-httplib Stream, kept for all the requests
// of the connection (cpp-httplib makes a new stream per request and drops bytes it had read
// ahead). Its buffer holds the next request's head while RequestHeadScanner checks it, so
// cpp-httplib only ever parses a head that is complete, bounded and well-formed.

#include <httplib.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

#include "request_head.hpp"

namespace fosls::service {

class HttpConnection : public httplib::Stream {
 public:
  using Clock = std::chrono::steady_clock;

  HttpConnection(socket_t sock, std::chrono::microseconds read_timeout,
                 std::chrono::microseconds write_timeout);

  bool is_readable() const override;
  bool is_writable() const override;
  ssize_t read(char* ptr, size_t size) override;
  ssize_t write(const char* ptr, size_t size) override;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  socket_t socket() const override { return sock_; }

  /// Waits until the next request's first byte is here (buffered or on the socket). False when
  /// the client closed, `timeout` passed, or `stop()` became true (checked every 100 ms).
  bool wait_for_request(std::chrono::milliseconds timeout, const std::function<bool()>& stop);

  enum class HeadOutcome { kComplete, kRejected, kClosed, kTimedOut };
  /// Reads until `scanner` has the whole head of the next request, or refuses it. The head's
  /// bytes stay buffered for cpp-httplib to read (empty lines before it are dropped). Timed
  /// out: the whole head did not arrive by `deadline`; closed: the client closed or went
  /// silent for the read timeout.
  HeadOutcome read_head(RequestHeadScanner& scanner, Clock::time_point deadline);

  /// Writes all of `data`; false if the client stopped taking it.
  bool write_all(const std::string& data);

  /// Ends the connection after a refusal: stops sending, reads and drops what the client still
  /// sends (up to 256 KiB or 200 ms, so that it gets the refusal instead of a reset), closes.
  void linger_and_close();
  /// Ends the connection (both directions) and closes the socket.
  void close();

 private:
  /// Waits up to `timeout` for the socket to be readable (poll; EINTR retried).
  bool socket_readable(std::chrono::microseconds timeout) const;
  /// Appends what the socket has (at most one chunk) to the buffer; <= 0 as recv.
  ssize_t fill();

  socket_t sock_;
  std::chrono::microseconds read_timeout_;
  std::chrono::microseconds write_timeout_;
  std::string buffer_;     ///< bytes read from the socket and not yet taken by read()
  std::size_t begin_ = 0;  ///< first byte of buffer_ not yet taken
};

}  // namespace fosls::service
