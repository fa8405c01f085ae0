#pragma once
// The real fosls-serve as a child process on a free loopback port, for integration tests.
// The destructor always stops it (SIGTERM, then SIGKILL), also when a test fails; and the
// child dies with the test process (PR_SET_PDEATHSIG) if the test itself crashes.

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fosls::service::testing {

class ServerProcess {
 public:
  /// Starts `binary` with --port 0 plus `args` and waits for its "listening on" line.
  /// stderr (the JSON log) goes to `log_path`, appended.
  ServerProcess(const std::string& binary, std::vector<std::string> args,
                const std::string& log_path)
      : log_path_(log_path) {
    int out[2];
    if (pipe(out) != 0) throw std::runtime_error("pipe failed");
    args.insert(args.begin(), {binary, "--host", "127.0.0.1", "--port", "0"});
    // Everything the child needs is prepared before fork: only async-signal-safe calls
    // are allowed between fork and exec in a multithreaded program.
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const pid_t parent = getpid();
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent) _exit(127);
      dup2(out[1], STDOUT_FILENO);
      const int log = open(log_path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
      if (log >= 0) dup2(log, STDERR_FILENO);
      close(out[0]);
      close(out[1]);
      execv(binary.c_str(), argv.data());
      _exit(127);
    }
    close(out[1]);
    stdout_fd_ = out[0];
    port_ = read_port();
    if (port_ == 0) {
      kill_hard();
      throw std::runtime_error("fosls-serve did not print its port; log:\n" + log());
    }
  }

  ~ServerProcess() {
    if (pid_ > 0) stop();
    if (stdout_fd_ >= 0) close(stdout_fd_);
  }
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  int port() const { return port_; }
  pid_t pid() const { return pid_; }

  /// SIGTERM and wait (SIGKILL after 30 s); returns the exit status (-1 if it was killed).
  int stop() {
    if (pid_ <= 0) return -1;
    kill(pid_, SIGTERM);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    int status = 0;
    while (waitpid(pid_, &status, WNOHANG) == 0) {
      if (std::chrono::steady_clock::now() > give_up) {
        kill_hard();
        return -1;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    pid_ = -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  /// kill -9: no shutdown code runs.
  void kill_hard() {
    if (pid_ <= 0) return;
    kill(pid_, SIGKILL);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
  }

  /// Everything the server logged so far (all processes sharing the log file).
  std::string log() const {
    std::ifstream in(log_path_);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

 private:
  int read_port() {
    std::string text;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < give_up) {
      pollfd p{stdout_fd_, POLLIN, 0};
      if (poll(&p, 1, 100) <= 0) continue;
      char buf[256];
      const ssize_t n = read(stdout_fd_, buf, sizeof buf);
      if (n <= 0) return 0;  // exited
      text.append(buf, static_cast<std::size_t>(n));
      const std::string marker = "listening on http://127.0.0.1:";
      const auto at = text.find(marker);
      const auto eol = at == std::string::npos ? at : text.find('\n', at);
      if (eol != std::string::npos) return std::stoi(text.substr(at + marker.size()));
    }
    return 0;
  }

  std::string log_path_;
  pid_t pid_ = -1;
  int stdout_fd_ = -1;
  int port_ = 0;
};

}  // namespace fosls::service::testing
