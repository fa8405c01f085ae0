#pragma once
// A throwaway PostgreSQL server for tests: initdb in a temporary folder, the server as a child
// process on a free loopback port (as `nobody` when the tests run as root, since PostgreSQL
// refuses to run as root), one fresh database per test, everything removed at the end. The
// server dies with the test process (setpriv --pdeathsig) even if the test crashes.
//
// Missing binaries are a test failure naming the Debian package, never a silent pass.

#include <arpa/inet.h>
#include <fcntl.h>
#include <libpq-fe.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "temp_dir.hpp"

namespace fosls::service::testing {

/// Starts `args` (argv[0] a full path) as a child with stdout and stderr appended to `log`;
/// with `die_with_parent` the child gets SIGQUIT when this thread ends. Returns its pid.
inline pid_t spawn(std::vector<std::string> args, const std::string& log,
                   bool die_with_parent = false) {
  // Prepared before fork: only async-signal-safe calls between fork and exec.
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid != 0) return pid;
  if (die_with_parent) {
    prctl(PR_SET_PDEATHSIG, SIGQUIT);
    if (getppid() != parent) _exit(127);
  }
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  if (fd >= 0) {
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
  }
  execv(argv[0], argv.data());
  _exit(127);
}

/// Runs `args` to the end; returns its exit status (-1 if it did not exit normally).
inline int run_program(const std::vector<std::string>& args, const std::string& log) {
  const pid_t pid = spawn(args, log);
  if (pid < 0) return -1;
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The whole text of a file ("" when it cannot be read).
inline std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// A loopback TCP port nobody listens on right now.
inline int free_port() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
  socklen_t len = sizeof addr;
  getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
  close(fd);
  return ntohs(addr.sin_port);
}

class PostgresCluster {
 public:
  /// Creates and starts the server; throws std::runtime_error saying what is missing or what
  /// the server logged.
  PostgresCluster() {
    const std::string bin = find_bin_dir();
    const bool as_root = geteuid() == 0;
    if (as_root) {
      // The folder and everything in it belong to the unprivileged user running the server.
      if (chown(dir_.path().c_str(), 65534, 65534) != 0) {
        throw std::runtime_error("cannot hand " + dir_.path().string() + " to nobody");
      }
    }
    const std::string data = dir_.file("data");
    const std::string log = dir_.file("server.log");
    if (run_program(as_user({bin + "/initdb", "-D", data, "-U", "fosls", "--auth=trust", "-N", "-E",
                             "UTF8", "--locale=C"}),
                    log) != 0) {
      throw std::runtime_error("initdb failed:\n" + read_file(log));
    }
    bin_ = bin;
    port_ = free_port();
    start();
  }

  /// Starts the server (again, after stop(): same data, same port).
  void start() {
    const std::string log = dir_.file("server.log");
    // fsync off: a test server's data is thrown away; the stores' own durability settings are
    // what the tests exercise, not the disk.
    // (setpriv re-arms the parent-death signal after changing the user, which clears it.)
    pid_ = spawn(
        as_user({bin_ + "/postgres", "-D", dir_.file("data"), "-p", std::to_string(port_), "-k",
                 dir_.path(), "-h", "127.0.0.1", "-c", "fsync=off", "-c", "max_connections=200"},
                /*die_with_parent=*/true),
        log, /*die_with_parent=*/true);
    if (pid_ < 0) throw std::runtime_error("fork failed");
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    const std::string ping = url("postgres");
    while (PQping(ping.c_str()) != PQPING_OK) {
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_ || std::chrono::steady_clock::now() > give_up) {
        pid_ = -1;
        throw std::runtime_error("the PostgreSQL server did not start:\n" + read_file(log));
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  }

  ~PostgresCluster() { stop(); }
  PostgresCluster(const PostgresCluster&) = delete;
  PostgresCluster& operator=(const PostgresCluster&) = delete;

  /// Fast shutdown (SIGINT) and wait.
  void stop() {
    if (pid_ <= 0) return;
    kill(pid_, SIGINT);
    int status = 0;
    waitpid(pid_, &status, 0);
    pid_ = -1;
  }

  int port() const { return port_; }

  /// The libpq URL of database `name`.
  std::string url(const std::string& name) const {
    return "postgresql://fosls@127.0.0.1:" + std::to_string(port_) + "/" + name;
  }

  /// Creates a new empty database and returns its URL.
  std::string create_database(const std::string& name) {
    PGconn* c = PQconnectdb(url("postgres").c_str());
    PGresult* r = PQexec(c, ("CREATE DATABASE " + name).c_str());
    const bool ok = PQresultStatus(r) == PGRES_COMMAND_OK;
    const std::string error = PQerrorMessage(c);
    PQclear(r);
    PQfinish(c);
    if (!ok) throw std::runtime_error("CREATE DATABASE " + name + ": " + error);
    return url(name);
  }

 private:
  /// The server binaries: pg_config's bindir, else Debian's versioned folders.
  static std::string find_bin_dir() {
    std::vector<std::string> candidates;
    if (FILE* p = popen("pg_config --bindir 2>/dev/null", "r")) {
      char buf[512] = {};
      if (fgets(buf, sizeof buf, p)) {
        std::string dir(buf);
        while (!dir.empty() && (dir.back() == '\n' || dir.back() == ' ')) dir.pop_back();
        candidates.push_back(dir);
      }
      pclose(p);
    }
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator("/usr/lib/postgresql", ec)) {
      candidates.push_back((e.path() / "bin").string());
    }
    for (const auto& dir : candidates) {
      if (access((dir + "/initdb").c_str(), X_OK) == 0 &&
          access((dir + "/postgres").c_str(), X_OK) == 0) {
        return dir;
      }
    }
    throw std::runtime_error(
        "PostgreSQL server binaries (initdb, postgres) not found: install the Debian package "
        "'postgresql' (docker/install-deps.sh does)");
  }

  /// Prefixes setpriv to run as nobody when the tests run as root.
  static std::vector<std::string> as_user(std::vector<std::string> args,
                                          bool die_with_parent = false) {
    if (geteuid() != 0) return args;
    std::vector<std::string> out = {"/usr/bin/setpriv", "--reuid=65534", "--regid=65534",
                                    "--clear-groups"};
    // Changing the user clears the parent-death signal; setpriv sets it again afterwards.
    if (die_with_parent) out.insert(out.end(), {"--pdeathsig", "QUIT"});
    out.insert(out.end(), args.begin(), args.end());
    return out;
  }

  TempDir dir_;
  std::string bin_;
  pid_t pid_ = -1;
  int port_ = 0;
};

}  // namespace fosls::service::testing
