#include "http_connection.hpp"

#include <arpa/inet.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace fosls::service {

namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;

/// What one recv asks for; also the most a buffer holds beyond a head.
constexpr std::size_t kChunk = 16 * 1024;

/// poll() on one socket for `events`, EINTR retried with the time left; true if ready.
bool wait_for(socket_t sock, short events, microseconds timeout) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left = std::chrono::ceil<milliseconds>(until - std::chrono::steady_clock::now());
    pollfd p{sock, events, 0};
    const int n = ::poll(&p, 1, static_cast<int>(std::max<milliseconds::rep>(0, left.count())));
    if (n >= 0) return n > 0;
    if (errno != EINTR) return false;
  }
}

ssize_t receive(socket_t sock, char* ptr, std::size_t size) {
  for (;;) {
    const ssize_t n = ::recv(sock, ptr, size, 0);
    if (n >= 0 || errno != EINTR) return n;
  }
}

void ip_and_port(const sockaddr_storage& addr, std::string& ip, int& port) {
  char host[NI_MAXHOST];
  const auto len = addr.ss_family == AF_INET6 ? sizeof(sockaddr_in6) : sizeof(sockaddr_in);
  if (getnameinfo(reinterpret_cast<const sockaddr*>(&addr), static_cast<socklen_t>(len), host,
                  sizeof host, nullptr, 0, NI_NUMERICHOST) == 0)
    ip = host;
  if (addr.ss_family == AF_INET)
    port = ntohs(reinterpret_cast<const sockaddr_in*>(&addr)->sin_port);
  else if (addr.ss_family == AF_INET6)
    port = ntohs(reinterpret_cast<const sockaddr_in6*>(&addr)->sin6_port);
}

}  // namespace

HttpConnection::HttpConnection(socket_t sock, microseconds read_timeout, microseconds write_timeout)
    : sock_(sock), read_timeout_(read_timeout), write_timeout_(write_timeout) {}

bool HttpConnection::socket_readable(microseconds timeout) const {
  return wait_for(sock_, POLLIN, timeout);
}

bool HttpConnection::is_readable() const {
  return begin_ < buffer_.size() || socket_readable(read_timeout_);
}

bool HttpConnection::is_writable() const { return wait_for(sock_, POLLOUT, write_timeout_); }

ssize_t HttpConnection::fill() {
  const std::size_t old = buffer_.size();
  buffer_.resize(old + kChunk);
  const ssize_t n = receive(sock_, buffer_.data() + old, kChunk);
  buffer_.resize(old + static_cast<std::size_t>(std::max<ssize_t>(0, n)));
  return n;
}

ssize_t HttpConnection::read(char* ptr, size_t size) {
  if (begin_ == buffer_.size()) {
    buffer_.clear();
    begin_ = 0;
    if (buffer_.capacity() > 8 * kChunk) std::string().swap(buffer_);  // after a large head
    if (!socket_readable(read_timeout_)) return -1;
    if (size >= kChunk) return receive(sock_, ptr, size);  // bodies: straight to the caller
    if (const ssize_t n = fill(); n <= 0) return n;
  }
  const std::size_t n = std::min(size, buffer_.size() - begin_);
  std::memcpy(ptr, buffer_.data() + begin_, n);
  begin_ += n;
  return static_cast<ssize_t>(n);
}

ssize_t HttpConnection::write(const char* ptr, size_t size) {
  if (!is_writable()) return -1;
  for (;;) {
    const ssize_t n = ::send(sock_, ptr, size, MSG_NOSIGNAL);
    if (n >= 0 || errno != EINTR) return n;
  }
}

bool HttpConnection::write_all(const std::string& data) {
  for (std::size_t sent = 0; sent < data.size();) {
    const ssize_t n = write(data.data() + sent, data.size() - sent);
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

void HttpConnection::get_remote_ip_and_port(std::string& ip, int& port) const {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  if (getpeername(sock_, reinterpret_cast<sockaddr*>(&addr), &len) == 0)
    ip_and_port(addr, ip, port);
}

void HttpConnection::get_local_ip_and_port(std::string& ip, int& port) const {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  if (getsockname(sock_, reinterpret_cast<sockaddr*>(&addr), &len) == 0)
    ip_and_port(addr, ip, port);
}

bool HttpConnection::wait_for_request(milliseconds timeout, const std::function<bool()>& stop) {
  if (begin_ < buffer_.size()) return true;
  const auto until = Clock::now() + timeout;
  while (!stop()) {
    const auto left = until - Clock::now();
    if (left <= Clock::duration::zero()) return false;
    const auto slice = std::min<Clock::duration>(left, milliseconds(100));
    if (socket_readable(std::chrono::duration_cast<microseconds>(slice))) return true;
  }
  return false;
}

HttpConnection::HeadOutcome HttpConnection::read_head(RequestHeadScanner& scanner,
                                                      Clock::time_point deadline) {
  buffer_.erase(0, begin_);  // bounds the buffer by one head and one chunk
  begin_ = 0;
  std::size_t scanned = 0;
  for (;;) {
    if (scanned < buffer_.size()) {
      scanned += scanner.scan(std::string_view(buffer_).substr(scanned));
      if (scanner.state() == RequestHeadScanner::State::kComplete) {
        begin_ = scanner.leading_empty_bytes();
        return HeadOutcome::kComplete;
      }
      if (scanner.state() == RequestHeadScanner::State::kRejected) return HeadOutcome::kRejected;
    }
    const auto left = deadline - Clock::now();
    if (left <= Clock::duration::zero()) return HeadOutcome::kTimedOut;
    const auto wait = std::min(std::chrono::duration_cast<microseconds>(left), read_timeout_);
    if (!socket_readable(wait))
      return Clock::now() >= deadline ? HeadOutcome::kTimedOut : HeadOutcome::kClosed;
    if (fill() <= 0) return HeadOutcome::kClosed;
  }
}

void HttpConnection::linger_and_close() {
  if (sock_ == INVALID_SOCKET) return;
  ::shutdown(sock_, SHUT_WR);
  const auto until = Clock::now() + milliseconds(200);
  char sink[kChunk];
  for (std::size_t dropped = 0; dropped < 256 * 1024;) {
    const auto left = until - Clock::now();
    if (left <= Clock::duration::zero() ||
        !socket_readable(std::chrono::duration_cast<microseconds>(left)))
      break;
    const ssize_t n = receive(sock_, sink, sizeof sink);
    if (n <= 0) break;
    dropped += static_cast<std::size_t>(n);
  }
  close();
}

void HttpConnection::close() {
  if (sock_ == INVALID_SOCKET) return;
  ::shutdown(sock_, SHUT_RDWR);
  ::close(sock_);
  sock_ = INVALID_SOCKET;
}

}  // namespace fosls::service
