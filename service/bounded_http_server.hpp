#pragma once
// The HTTP server of fosls-serve: cpp-httplib's Server with its own per-connection loop, so
// that every request head is read under limits before cpp-httplib parses it. Debian's
// cpp-httplib 0.11.4 is a compiled library (its CPPHTTPLIB_* macros have no effect) whose
// head reader keeps any number of 8 KiB field lines, so one client streaming them could grow
// the server without bound. Its per-connection function is a virtual (`process_and_close_socket`)
// and `process_request(Stream&, …)` is open to subclasses, so this class reads each head into
// its own HttpConnection with a RequestHeadScanner (bounded, strict RFC 9112 field syntax,
// a deadline for the whole head) and hands cpp-httplib only heads that passed; a refused head
// is answered (400, 408, 414 or 431) and the connection closed (docs/service.md, "Hostile
// use").

#include <httplib.h>

#include <chrono>
#include <functional>

#include "request_head.hpp"

namespace fosls::service {

struct HttpServerLimits {
  RequestHeadLimits head;
  /// The whole head must arrive within this after its first byte (slow-header clients).
  std::chrono::milliseconds head_deadline{10000};
};

class BoundedHttpServer : public httplib::Server {
 public:
  /// Fills the response to a refused head (status, body, headers); `req` has the method, path
  /// and remote address when the request line got that far.
  using HeadRefusalHandler =
      std::function<void(const httplib::Request& req, const HeadRejection&, httplib::Response&)>;

  explicit BoundedHttpServer(HttpServerLimits limits = {});

  const HttpServerLimits& limits() const { return limits_; }
  BoundedHttpServer& set_head_refusal_handler(HeadRefusalHandler handler);
  /// As httplib's; this server keeps the slot for itself and calls `handler` from it.
  BoundedHttpServer& set_post_routing_handler(Handler handler);

  /// As httplib's, with a listen backlog of SOMAXCONN instead of its compiled-in 5: a burst of
  /// connections beyond the backlog has its SYNs dropped, and each of those clients waits a
  /// second (then two, …) to retry — /healthz included.
  bool bind_to_port(const std::string& host, int port, int socket_flags = 0);
  int bind_to_any_port(const std::string& host, int socket_flags = 0);

 private:
  bool process_and_close_socket(socket_t sock) override;
  void raise_listen_backlog();

  HttpServerLimits limits_;
  HeadRefusalHandler refusal_handler_;
  Handler post_routing_handler_;
};

}  // namespace fosls::service
