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
#include <cstdio>
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

/// The kernel's count of out-of-memory kills since boot (/proc/vmstat); -1 if unknown.
long long oom_kill_count() {
  std::FILE* f = std::fopen("/proc/vmstat", "r");
  if (!f) return -1;
  char name[64];
  long long value = 0, found = -1;
  while (std::fscanf(f, "%63s %lld", name, &value) == 2)
    if (std::strcmp(name, "oom_kill") == 0) found = value;
  std::fclose(f);
  return found;
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

bool ChildResult::killed_by_oom_killer() const {
  return end == End::kSignaled && signal == SIGKILL && oom_kill_meanwhile;
}

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

namespace {

/// One started child with the pipes to it: run_child's steps.
class RunningChild {
 public:
  /// Spawns the child with its stdin, stdout and stderr on pipes and applies the limits.
  explicit RunningChild(const ChildOptions& options);

  /// Kills the child (and its group) once it was cancelled, passed its deadline or wrote too
  /// much; what killed it is what the result says.
  void enforce_limits();
  /// Writes input and reads output for up to one poll step. True once the child is reaped.
  bool exchange_io();
  ChildResult finish();

 private:
  bool try_reap();
  void write_input();

  const ChildOptions& options_;
  Pipe in_, out_, err_;
  pid_t pid_ = -1;
  Clock::time_point started_, deadline_;
  std::optional<ChildResult::End> killed_;
  std::size_t written_ = 0, output_bytes_ = 0;
  int status_ = 0;
  rusage usage_{};
  long long oom_kills_at_start_ = -1;
  ChildResult result_;
};

RunningChild::RunningChild(const ChildOptions& options) : options_(options) {
  FileActions actions;
  actions.dup2(in_.read.get(), STDIN_FILENO);
  actions.dup2(out_.write.get(), STDOUT_FILENO);
  actions.dup2(err_.write.get(), STDERR_FILENO);
  SpawnAttributes attributes;
  std::vector<std::string> argv = options.argv, env = child_environment(options.environment);
  std::vector<char*> argv_p = pointers(argv), env_p = pointers(env);

  started_ = Clock::now();
  oom_kills_at_start_ = oom_kill_count();
  const int rc = ::posix_spawn(&pid_, argv[0].c_str(), actions.get(), attributes.get(),
                               argv_p.data(), env_p.data());
  if (rc != 0) throw std::runtime_error("cannot start " + argv[0] + ": " + std::strerror(rc));
  // The child reads all its input before it does anything, so limits set now apply to all of
  // its work.
  apply_limits(pid_, options.limits);
  in_.read.reset();
  out_.write.reset();
  err_.write.reset();
  set_nonblocking(in_.write.get());
  set_nonblocking(out_.read.get());
  set_nonblocking(err_.read.get());
  if (options.input.empty()) in_.write.reset();
  deadline_ =
      options.limits.wall.count() > 0 ? started_ + options.limits.wall : Clock::time_point::max();
}

void RunningChild::enforce_limits() {
  if (killed_) return;
  if (options_.cancel && options_.cancel->load(std::memory_order_relaxed))
    killed_ = ChildResult::End::kCancelled;
  else if (Clock::now() >= deadline_)
    killed_ = ChildResult::End::kTimedOut;
  else if (options_.limits.max_output_bytes > 0 && output_bytes_ > options_.limits.max_output_bytes)
    killed_ = ChildResult::End::kOutputTooLarge;
  if (killed_) {
    kill_group(pid_);
    in_.write.reset();
  }
}

bool RunningChild::exchange_io() {
  std::vector<pollfd> fds;
  if (in_.write.get() >= 0) fds.push_back({in_.write.get(), POLLOUT, 0});
  if (out_.read.get() >= 0) fds.push_back({out_.read.get(), POLLIN, 0});
  if (err_.read.get() >= 0) fds.push_back({err_.read.get(), POLLIN, 0});
  // Both outputs closed: the child is exiting (or closed them and lingers).
  if (fds.empty()) return try_reap();
  ::poll(fds.data(), fds.size(), static_cast<int>(kPollStep.count()));
  auto on_stdout = [&](const char* data, std::size_t n) {
    output_bytes_ += n;
    if (options_.on_output)
      options_.on_output(std::string_view(data, n));
    else
      result_.output.append(data, n);
  };
  auto on_stderr = [&](const char* data, std::size_t n) {
    result_.errors.append(data, n);
    if (result_.errors.size() > 2 * kErrorTail)
      result_.errors.erase(0, result_.errors.size() - kErrorTail);
  };
  for (const pollfd& p : fds) {
    if (p.revents == 0) continue;
    if (p.fd == in_.write.get()) {
      write_input();
    } else if (p.fd == out_.read.get()) {
      if (!drain(p.fd, on_stdout)) out_.read.reset();
    } else if (p.fd == err_.read.get()) {
      if (!drain(p.fd, on_stderr)) err_.read.reset();
    }
  }
  return false;
}

void RunningChild::write_input() {
  const ssize_t n =
      ::write(in_.write.get(), options_.input.data() + written_, options_.input.size() - written_);
  if (n > 0) written_ += static_cast<std::size_t>(n);
  if ((n < 0 && errno != EAGAIN && errno != EINTR) || written_ == options_.input.size())
    in_.write.reset();  // done, or the child stopped reading (EPIPE)
}

bool RunningChild::try_reap() {
  const pid_t w = ::wait4(pid_, &status_, WNOHANG, &usage_);
  if (w == pid_ || (w < 0 && errno != EINTR)) return true;
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  return false;
}

ChildResult RunningChild::finish() {
  result_.seconds = std::chrono::duration<double>(Clock::now() - started_).count();
  if (result_.errors.size() > kErrorTail)
    result_.errors.erase(0, result_.errors.size() - kErrorTail);
  result_.peak_rss_bytes = static_cast<std::size_t>(usage_.ru_maxrss) * 1024;  // KiB on Linux
  const long long oom_kills = oom_kill_count();
  result_.oom_kill_meanwhile = oom_kills_at_start_ >= 0 && oom_kills > oom_kills_at_start_;
  if (killed_) {
    result_.end = *killed_;
  } else if (WIFEXITED(status_)) {
    result_.end = ChildResult::End::kExited;
    result_.exit_code = WEXITSTATUS(status_);
  } else if (WIFSIGNALED(status_)) {
    result_.end = ChildResult::End::kSignaled;
    result_.signal = WTERMSIG(status_);
  }
  return std::move(result_);
}

}  // namespace

ChildResult run_child(const ChildOptions& options) {
  if (options.argv.empty()) throw std::invalid_argument("run_child: no program given");
  RunningChild child(options);
  do {
    child.enforce_limits();
  } while (!child.exchange_io());
  return child.finish();
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
