#include "bounded_http_server.hpp"

#include <sys/socket.h>

#include <string_view>

#include "http_connection.hpp"
#include "problem.hpp"

namespace fosls::service {

namespace {

/// What the response to the request being served on this thread decided about its connection
/// (a connection is served start to finish on one thread).
struct ConnectionState {
  bool close_after_response = false;
};
thread_local ConnectionState* current_connection = nullptr;

std::chrono::microseconds microseconds(time_t sec, time_t usec) {
  return std::chrono::seconds(sec) + std::chrono::microseconds(usec);
}

/// Method and path of a request line, as far as they are there ("GET /v1/jobs?x HTTP/1.1").
httplib::Request request_of(const std::string& request_line, HttpConnection& connection) {
  httplib::Request req;
  const std::string_view line(request_line);
  const auto method_end = line.find(' ');
  req.method = std::string(line.substr(0, method_end));
  if (method_end != std::string_view::npos) {
    std::string_view target = line.substr(method_end + 1);
    target = target.substr(0, target.find(' '));
    req.target = std::string(target);
    req.path = std::string(target.substr(0, target.find('?')));
  }
  connection.get_remote_ip_and_port(req.remote_addr, req.remote_port);
  return req;
}

/// The response to a refused head as bytes; always the last one on its connection.
std::string response_text(const httplib::Response& res) {
  std::string text = "HTTP/1.1 " + std::to_string(res.status) + " " +
                     std::string(reason_phrase(res.status)) + "\r\n";
  for (const auto& [name, value] : res.headers)
    if (name != "Content-Length" && name != "Connection") text += name + ": " + value + "\r\n";
  text += "Content-Length: " + std::to_string(res.body.size()) + "\r\nConnection: close\r\n\r\n";
  return text + res.body;
}

void refuse(HttpConnection& connection, const std::string& request_line,
            const HeadRejection& rejection, const BoundedHttpServer::HeadRefusalHandler& handler) {
  const httplib::Request req = request_of(request_line, connection);
  httplib::Response res;
  res.status = rejection.status;
  if (handler)
    handler(req, rejection, res);
  else
    res.set_content(rejection.detail, "text/plain");
  connection.write_all(response_text(res));
  connection.linger_and_close();
}

}  // namespace

BoundedHttpServer::BoundedHttpServer(HttpServerLimits limits) : limits_(limits) {
  Server::set_post_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (post_routing_handler_) post_routing_handler_(req, res);
    // cpp-httplib keeps reading after "Connection: close" (e.g. a refused Content-Length,
    // whose body must never be read as the next request); this loop does not.
    if (current_connection && res.get_header_value("Connection") == "close")
      current_connection->close_after_response = true;
  });
}

BoundedHttpServer& BoundedHttpServer::set_head_refusal_handler(HeadRefusalHandler handler) {
  refusal_handler_ = std::move(handler);
  return *this;
}

BoundedHttpServer& BoundedHttpServer::set_post_routing_handler(Handler handler) {
  post_routing_handler_ = std::move(handler);
  return *this;
}

bool BoundedHttpServer::bind_to_port(const std::string& host, int port, int socket_flags) {
  if (!Server::bind_to_port(host, port, socket_flags)) return false;
  raise_listen_backlog();
  return true;
}

int BoundedHttpServer::bind_to_any_port(const std::string& host, int socket_flags) {
  const int port = Server::bind_to_any_port(host, socket_flags);
  if (port >= 0) raise_listen_backlog();
  return port;
}

void BoundedHttpServer::raise_listen_backlog() {
  // listen() again on a listening socket only changes its backlog.
  ::listen(svr_sock_, SOMAXCONN);
}

bool BoundedHttpServer::process_and_close_socket(socket_t sock) {
  HttpConnection connection(sock, microseconds(read_timeout_sec_, read_timeout_usec_),
                            microseconds(write_timeout_sec_, write_timeout_usec_));
  ConnectionState state;
  current_connection = &state;
  const auto stopping = [this] { return svr_sock_ == INVALID_SOCKET; };
  bool ok = true;
  bool closing = false;  // by the last response: what the client sent after it is not a request
  for (std::size_t served = 0; served < keep_alive_max_count_; ++served) {
    if (!connection.wait_for_request(std::chrono::seconds(keep_alive_timeout_sec_), stopping))
      break;
    RequestHeadScanner scanner(limits_.head);
    const auto outcome =
        connection.read_head(scanner, HttpConnection::Clock::now() + limits_.head_deadline);
    if (outcome == HttpConnection::HeadOutcome::kClosed) break;
    if (outcome != HttpConnection::HeadOutcome::kComplete) {
      const HeadRejection timed_out{408, "the request head did not arrive within " +
                                             std::to_string(limits_.head_deadline.count()) +
                                             " ms of its first byte"};
      refuse(connection, scanner.request_line(),
             outcome == HttpConnection::HeadOutcome::kTimedOut ? timed_out : scanner.rejection(),
             refusal_handler_);
      break;
    }
    bool closed_by_request = false;
    state.close_after_response = false;
    ok = process_request(connection, served + 1 == keep_alive_max_count_, closed_by_request,
                         nullptr);
    closing = closed_by_request || state.close_after_response;
    if (!ok || closing) break;
  }
  current_connection = nullptr;
  // A refused body may still be arriving; dropping it instead of resetting the connection lets
  // the client read the refusal.
  if (closing)
    connection.linger_and_close();
  else
    connection.close();
  return ok;
}

}  // namespace fosls::service
