#pragma once
// Raw HTTP/1.1 over a loopback socket, for requests a normal client will not send (chunked
// bodies, missing Content-Length, dot segments): the exact bytes are the point of the test.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <string>

namespace fosls::service::testing {

/// A socket connected to 127.0.0.1:port, or -1.
inline int connect_loopback(int port) {
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

/// Response status code and the full response text.
struct RawResponse {
  int status = 0;
  std::string text;
};

/// Sends `request` verbatim to 127.0.0.1:port and reads until the server closes the
/// connection or `timeout_s` passes without data. Send "Connection: close" requests.
inline RawResponse raw_http(int port, const std::string& request, int timeout_s = 10) {
  RawResponse out;
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return out;
  timeval tv{timeout_s, 0};
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0) {
    std::size_t sent = 0;
    while (sent < request.size()) {
      const ssize_t n = send(fd, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) break;  // the server may refuse before reading everything
      sent += static_cast<std::size_t>(n);
    }
    char buf[4096];
    for (;;) {
      const ssize_t n = recv(fd, buf, sizeof buf, 0);
      if (n <= 0) break;
      out.text.append(buf, static_cast<std::size_t>(n));
    }
  }
  close(fd);
  if (out.text.rfind("HTTP/1.1 ", 0) == 0 && out.text.size() >= 12) {
    out.status = std::stoi(out.text.substr(9, 3));
  }
  return out;
}

/// The body of a raw response (after the blank line).
inline std::string raw_body(const RawResponse& r) {
  const auto pos = r.text.find("\r\n\r\n");
  return pos == std::string::npos ? std::string() : r.text.substr(pos + 4);
}

}  // namespace fosls::service::testing
