#pragma once
// Runs a program as a child process under limits: its input is written to its stdin, its
// stdout is collected (or streamed), the tail of its stderr is kept. The child is started with
// posix_spawn (never by forking this multithreaded, OpenMP-using process and continuing in the
// copy), in its own process group, with default signal dispositions and an empty signal mask,
// and it is killed on a wall-clock deadline, on cancel, or when its output grows too large.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fosls {

#if defined(__SANITIZE_ADDRESS__)
#define FOSLS_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FOSLS_ADDRESS_SANITIZER 1
#endif
#endif

/// Whether ChildLimits::address_space_bytes is applied. Not in AddressSanitizer builds
/// (`tests/run.sh --sanitize`): ASan reserves terabytes of address space for its shadow memory
/// when a program starts, so a child under RLIMIT_AS aborts before main — every gmsh child did.
#ifdef FOSLS_ADDRESS_SANITIZER
inline constexpr bool kAddressSpaceLimitsApplied = false;
#else
inline constexpr bool kAddressSpaceLimitsApplied = true;
#endif

/// Limits applied to a child. Zero means "no limit".
struct ChildLimits {
  /// Wall-clock time from start to exit; the child is killed (SIGKILL) when it passes.
  std::chrono::milliseconds wall{0};
  /// CPU seconds (RLIMIT_CPU: the kernel sends SIGXCPU when they are used up).
  double cpu_seconds = 0;
  /// Address space in bytes (RLIMIT_AS: allocations beyond it fail inside the child).
  std::size_t address_space_bytes = 0;
  /// Collected stdout beyond this kills the child.
  std::size_t max_output_bytes = std::size_t{1} << 30;
};

/// What to run and how.
struct ChildOptions {
  std::vector<std::string> argv;  ///< argv[0] is the path of the program
  std::string input;              ///< written to the child's stdin, which is then closed
  /// NAME=value entries added to (or replacing) this process's environment for the child.
  std::vector<std::string> environment;
  ChildLimits limits;
  /// When set and it becomes true, the child is killed (checked every 20 ms).
  const std::atomic<bool>* cancel = nullptr;
  /// When set, stdout is passed here as it arrives instead of being collected.
  std::function<void(std::string_view)> on_output;
};

/// How a child ended.
struct ChildResult {
  enum class End {
    kExited,          ///< exited on its own; see exit_code
    kSignaled,        ///< killed by a signal it did not expect (crash, abort, SIGXCPU, OOM killer)
    kTimedOut,        ///< killed by us at the wall-clock deadline
    kCancelled,       ///< killed by us on cancel
    kOutputTooLarge,  ///< killed by us: stdout exceeded max_output_bytes
  };
  End end = End::kExited;
  int exit_code = -1;  ///< kExited
  int signal = 0;      ///< kSignaled
  std::string output;  ///< stdout (empty when on_output was given)
  std::string errors;  ///< the last 16 KiB of stderr
  double seconds = 0;  ///< wall-clock time from start to exit
  /// The child's peak resident memory (its own, from wait4; 0 if unknown).
  std::size_t peak_rss_bytes = 0;
  /// Whether the kernel's out-of-memory killer killed a process while the child ran (the
  /// oom_kill count of /proc/vmstat grew): with an unexpected SIGKILL, most likely the child.
  bool oom_kill_meanwhile = false;
  /// Whether stderr shows that an allocation failed (std::bad_alloc, "out of memory").
  bool ran_out_of_memory() const;
  /// Killed by a SIGKILL that was not ours while the out-of-memory killer was at work.
  bool killed_by_oom_killer() const;
  /// "exit code 3", "signal 6 (Aborted)", "timed out", ... for messages.
  std::string describe() const;
};

/// Starts the child and waits for it. Throws std::runtime_error when it cannot be started
/// (missing program, no processes left); every way the child itself ends is a ChildResult.
ChildResult run_child(const ChildOptions& options);

/// For child programs, first thing in main(): die with SIGKILL when the parent dies, so that
/// nothing outlives a killed server or CLI. Exits at once when the parent is already gone.
void die_with_parent();

/// For child programs: a descriptor of their own for the answer to the parent, after which
/// fd 1 writes to stderr, so that nothing a library prints can corrupt the answer.
int take_stdout_for_answer();

/// Writes all of `text` to `fd`; false when the reader is gone.
bool write_all(int fd, std::string_view text);

/// The path of a program installed beside this one: `override_env` (when that environment
/// variable is set), else the folder of /proc/self/exe, else the build's bin folder. Throws
/// std::runtime_error naming the places it looked when none holds an executable `name`.
std::string sibling_program(const std::string& name, const char* override_env);

}  // namespace fosls
