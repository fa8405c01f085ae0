#include "process/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace fosls {

namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kParentPidVariable = "FOSLS_PARENT_PID";
constexpr std::size_t kErrorTail = 16 * 1024;
constexpr auto kPollStep = std::chrono::milliseconds(20);

/// A file descriptor closed on scope exit.
class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() { reset(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  void reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  int* out() { return &fd_; }

 private:
  int fd_ = -1;
};

/// A pipe whose ends are closed on exec, so that children started by other threads at the
/// same time never inherit them (an inherited write end would hide this child's EOF).
struct Pipe {
  Fd read, write;
  Pipe() {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
      throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
    *read.out() = fds[0];
    *write.out() = fds[1];
  }
};

void set_nonblocking(int fd) { ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK); }

/// Spawn attributes: own process group, empty signal mask (the server blocks its stop signals
/// in every thread, and masks are inherited), default dispositions (the server ignores
/// SIGPIPE, and ignored signals stay ignored across exec).
class SpawnAttributes {
 public:
  SpawnAttributes() {
    posix_spawnattr_init(&attr_);
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGCHLD, SIGXCPU, SIGXFSZ, SIGUSR1,
                  SIGUSR2, SIGALRM})
      sigaddset(&defaults, s);
    posix_spawnattr_setsigmask(&attr_, &none);
    posix_spawnattr_setsigdefault(&attr_, &defaults);
    posix_spawnattr_setpgroup(&attr_, 0);
    posix_spawnattr_setflags(
        &attr_, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);
  }
  ~SpawnAttributes() { posix_spawnattr_destroy(&attr_); }
  SpawnAttributes(const SpawnAttributes&) = delete;
  SpawnAttributes& operator=(const SpawnAttributes&) = delete;
  const posix_spawnattr_t* get() const { return &attr_; }

 private:
  posix_spawnattr_t attr_;
};

class FileActions {
 public:
  FileActions() { posix_spawn_file_actions_init(&actions_); }
  ~FileActions() { posix_spawn_file_actions_destroy(&actions_); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
  void dup2(int from, int to) { posix_spawn_file_actions_adddup2(&actions_, from, to); }
  const posix_spawn_file_actions_t* get() const { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

/// This process's environment with `extra` entries and FOSLS_PARENT_PID (for
/// die_with_parent() in the child) replacing any of the same names.
std::vector<std::string> child_environment(std::vector<std::string> extra) {
  extra.push_back(std::string(kParentPidVariable) + "=" + std::to_string(::getpid()));
  auto replaced = [&extra](const char* entry) {
    for (const auto& e : extra) {
      const auto eq = e.find('=');
      if (std::strncmp(entry, e.c_str(), eq + 1) == 0) return true;
    }
    return false;
  };
  std::vector<std::string> env;
  for (char** e = environ; e && *e; ++e)
    if (!replaced(*e)) env.emplace_back(*e);
  env.insert(env.end(), extra.begin(), extra.end());
  return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> p;
  for (auto& s : strings) p.push_back(s.data());
  p.push_back(nullptr);
  return p;
}

void apply_limits(pid_t pid, const ChildLimits& limits) {
  if (kAddressSpaceLimitsApplied && limits.address_space_bytes > 0) {
    const rlimit r{limits.address_space_bytes, limits.address_space_bytes};
    ::prlimit(pid, RLIMIT_AS, &r, nullptr);
  }
  if (limits.cpu_seconds > 0) {
    const auto soft = static_cast<rlim_t>(std::ceil(limits.cpu_seconds));
    const rlimit r{soft, soft + 2};  // SIGXCPU at the soft limit, SIGKILL at the hard one
    ::prlimit(pid, RLIMIT_CPU, &r, nullptr);
  }
}

void kill_group(pid_t pid) {
  ::kill(-pid, SIGKILL);  // the child and anything it started in its group
  ::kill(pid, SIGKILL);
}

/// Reads what is available from fd; false on EOF or error.
bool drain(int fd, const std::function<void(const char*, std::size_t)>& sink) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      sink(buffer, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
    if (n < 0 && errno == EINTR) continue;
    return false;
  }
}

}  // namespace

bool ChildResult::ran_out_of_memory() const {
  for (const char* sign : {"bad_alloc", "out of memory", "Out of memory", "Cannot allocate memory"})
    if (errors.find(sign) != std::string::npos) return true;
  return false;
}

std::string ChildResult::describe() const {
  switch (end) {
    case End::kExited:
      return "exit code " + std::to_string(exit_code);
    case End::kSignaled: {
      const char* name = ::strsignal(signal);
      return "signal " + std::to_string(signal) + (name ? std::string(" (") + name + ")" : "");
    }
    case End::kTimedOut:
      return "killed at its time limit";
    case End::kCancelled:
      return "killed on cancel";
    case End::kOutputTooLarge:
      return "killed: its output was too large";
  }
  return "unknown end";
}

ChildResult run_child(const ChildOptions& options) {
  if (options.argv.empty()) throw std::invalid_argument("run_child: no program given");
  Pipe in, out, err;
  FileActions actions;
  actions.dup2(in.read.get(), STDIN_FILENO);
  actions.dup2(out.write.get(), STDOUT_FILENO);
  actions.dup2(err.write.get(), STDERR_FILENO);
  SpawnAttributes attributes;
  std::vector<std::string> argv = options.argv, env = child_environment(options.environment);
  std::vector<char*> argv_p = pointers(argv), env_p = pointers(env);

  const auto started = Clock::now();
  pid_t pid = -1;
  const int rc = ::posix_spawn(&pid, argv[0].c_str(), actions.get(), attributes.get(),
                               argv_p.data(), env_p.data());
  if (rc != 0) throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(rc));
  // The child reads all its input before it does anything, so limits set now apply to all of
  // its work.
  apply_limits(pid, options.limits);
  in.read.reset();
  out.write.reset();
  err.write.reset();
  set_nonblocking(in.write.get());
  set_nonblocking(out.read.get());
  set_nonblocking(err.read.get());

  ChildResult result;
  std::size_t written = 0, output_bytes = 0;
  if (options.input.empty()) in.write.reset();
  const auto deadline =
      options.limits.wall.count() > 0 ? started + options.limits.wall : Clock::time_point::max();
  std::optional<ChildResult::End> killed;
  auto on_stdout = [&](const char* data, std::size_t n) {
    output_bytes += n;
    if (options.on_output)
      options.on_output(std::string_view(data, n));
    else
      result.output.append(data, n);
  };
  auto on_stderr = [&](const char* data, std::size_t n) {
    result.errors.append(data, n);
    if (result.errors.size() > 2 * kErrorTail)
      result.errors.erase(0, result.errors.size() - kErrorTail);
  };

  int status = 0;
  bool reaped = false;
  while (!reaped) {
    if (!killed) {
      if (options.cancel && options.cancel->load(std::memory_order_relaxed))
        killed = ChildResult::End::kCancelled;
      else if (Clock::now() >= deadline)
        killed = ChildResult::End::kTimedOut;
      else if (options.limits.max_output_bytes > 0 &&
               output_bytes > options.limits.max_output_bytes)
        killed = ChildResult::End::kOutputTooLarge;
      if (killed) {
        kill_group(pid);
        in.write.reset();
      }
    }
    std::vector<pollfd> fds;
    if (in.write.get() >= 0) fds.push_back({in.write.get(), POLLOUT, 0});
    if (out.read.get() >= 0) fds.push_back({out.read.get(), POLLIN, 0});
    if (err.read.get() >= 0) fds.push_back({err.read.get(), POLLIN, 0});
    if (fds.empty()) {
      // Both outputs closed: the child is exiting (or closed them and lingers).
      const pid_t w = ::waitpid(pid, &status, WNOHANG);
      if (w == pid || (w < 0 && errno != EINTR)) {
        reaped = true;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      continue;
    }
    ::poll(fds.data(), fds.size(), static_cast<int>(kPollStep.count()));
    for (const pollfd& p : fds) {
      if (p.revents == 0) continue;
      if (p.fd == in.write.get()) {
        const ssize_t n =
            ::write(p.fd, options.input.data() + written, options.input.size() - written);
        if (n > 0) written += static_cast<std::size_t>(n);
        if ((n < 0 && errno != EAGAIN && errno != EINTR) || written == options.input.size())
          in.write.reset();  // done, or the child stopped reading (EPIPE)
      } else if (p.fd == out.read.get()) {
        if (!drain(p.fd, on_stdout)) out.read.reset();
      } else if (p.fd == err.read.get()) {
        if (!drain(p.fd, on_stderr)) err.read.reset();
      }
    }
  }
  result.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  if (result.errors.size() > kErrorTail) result.errors.erase(0, result.errors.size() - kErrorTail);
  if (killed) {
    result.end = *killed;
  } else if (WIFEXITED(status)) {
    result.end = ChildResult::End::kExited;
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.end = ChildResult::End::kSignaled;
    result.signal = WTERMSIG(status);
  }
  return result;
}

void die_with_parent() {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  // The parent may have died before prctl: then we were re-parented already.
  if (const char* expected = std::getenv(kParentPidVariable))
    if (std::to_string(::getppid()) != expected) std::_Exit(137);
}

int take_stdout_for_answer() {
  const int answer_fd = ::dup(STDOUT_FILENO);
  ::dup2(STDERR_FILENO, STDOUT_FILENO);
  return answer_fd;
}

bool write_all(int fd, std::string_view text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string sibling_program(const std::string& name, const char* override_env) {
  namespace fs = std::filesystem;
  std::vector<fs::path> tried;
  auto executable = [](const fs::path& p) { return ::access(p.c_str(), X_OK) == 0; };
  if (override_env) {
    if (const char* path = std::getenv(override_env); path && *path) {
      if (executable(path)) return path;
      throw std::runtime_error(std::string(override_env) + "=" + path +
                               " does not name an executable program");
    }
  }
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) tried.push_back(self.parent_path() / name);
#ifdef FOSLS_BUILD_BIN_DIR
  tried.push_back(fs::path(FOSLS_BUILD_BIN_DIR) / name);
#endif
  std::string places;
  for (const auto& p : tried) {
    if (executable(p)) return p.string();
    places += (places.empty() ? "" : ", ") + p.string();
  }
  throw std::runtime_error("cannot find the program " + name + " (looked in: " + places +
                           "); install it beside this program");
}

}  // namespace fosls
