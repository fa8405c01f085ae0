// The child-process runner on small shell programs: exit codes, input and output of any size,
// signals, the deadline, cancel, the output cap, the limits the child really gets, its signal
// mask, and that a killed child's own children die with it.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <thread>

#include "process/child_process.hpp"

namespace fosls {
namespace {

using End = ChildResult::End;

ChildResult shell(const std::string& script, ChildLimits limits = {}, std::string input = "",
                  const std::atomic<bool>* cancel = nullptr) {
  ChildOptions o;
  o.argv = {"/bin/sh", "-c", script};
  o.input = std::move(input);
  o.limits = limits;
  o.cancel = cancel;
  return run_child(o);
}

TEST(ChildProcess, ExitCodeOutputAndErrors) {
  const ChildResult r = shell("echo out; echo err >&2; exit 7");
  EXPECT_EQ(r.end, End::kExited);
  EXPECT_EQ(r.exit_code, 7);
  EXPECT_EQ(r.output, "out\n");
  EXPECT_EQ(r.errors, "err\n");
  EXPECT_EQ(r.describe(), "exit code 7");
}

TEST(ChildProcess, LargeInputAndOutputDoNotDeadlock) {
  // 4 MiB each way: far beyond a pipe's buffer, so writing and reading must interleave.
  std::string input(4 << 20, 'x');
  for (std::size_t i = 0; i < input.size(); i += 4096) input[i] = static_cast<char>('a' + i % 26);
  const ChildResult r = shell("cat", {}, input);
  EXPECT_EQ(r.end, End::kExited);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.output, input);
}

TEST(ChildProcess, StreamsOutputWhenAsked) {
  ChildOptions o;
  o.argv = {"/bin/sh", "-c", "echo one; echo two"};
  std::string seen;
  o.on_output = [&](std::string_view s) { seen += s; };
  const ChildResult r = run_child(o);
  EXPECT_EQ(seen, "one\ntwo\n");
  EXPECT_TRUE(r.output.empty());
}

TEST(ChildProcess, ACrashIsASignalNotOurs) {
  const ChildResult r = shell(
      "echo \"terminate called after throwing 'std::bad_alloc'\" >&2; "
      "kill -ABRT $$");
  EXPECT_EQ(r.end, End::kSignaled);
  EXPECT_EQ(r.signal, SIGABRT);
  EXPECT_TRUE(r.ran_out_of_memory());
  EXPECT_NE(r.describe().find("signal 6"), std::string::npos) << r.describe();
  EXPECT_FALSE(shell("kill -ABRT $$").ran_out_of_memory());
}

TEST(ChildProcess, DeadlineKillsTheChildAndItsChildren) {
  ChildLimits limits;
  limits.wall = std::chrono::milliseconds(300);
  ChildOptions o;
  o.argv = {"/bin/sh", "-c", "sleep 30 & echo $!; wait"};
  o.limits = limits;
  std::string pid_text;
  o.on_output = [&](std::string_view s) { pid_text += s; };
  const ChildResult r = run_child(o);
  EXPECT_EQ(r.end, End::kTimedOut);
  EXPECT_LT(r.seconds, 5.0);
  const pid_t grandchild = std::atoi(pid_text.c_str());
  ASSERT_GT(grandchild, 0) << pid_text;
  // Killed with its group; give init a moment to reap it.
  bool gone = false;
  for (int i = 0; i < 200 && !gone; ++i) {
    gone = ::kill(grandchild, 0) != 0;
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(gone) << "the background sleep survived its killed parent";
}

TEST(ChildProcess, CancelKillsAtOnce) {
  std::atomic<bool> cancel{false};
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    cancel = true;
  });
  const ChildResult r = shell("sleep 30", {}, "", &cancel);
  canceller.join();
  EXPECT_EQ(r.end, End::kCancelled);
  EXPECT_LT(r.seconds, 5.0);
}

TEST(ChildProcess, OutputBeyondTheCapKillsTheChild) {
  ChildLimits limits;
  limits.max_output_bytes = 1000;
  const ChildResult r = shell("while true; do echo 0123456789; done", limits);
  EXPECT_EQ(r.end, End::kOutputTooLarge);
}

TEST(ChildProcess, TheChildRunsUnderTheLimits) {
  if (!kAddressSpaceLimitsApplied) GTEST_SKIP() << "no address-space limit under ASan";
  ChildLimits limits;
  limits.address_space_bytes = std::size_t{512} << 20;
  limits.cpu_seconds = 7;
  // The shell reads its script before the limits are set, but `ulimit` runs after.
  const ChildResult r = shell("read line; ulimit -v; ulimit -t", limits, "go\n");
  EXPECT_EQ(r.output, "524288\n7\n");
}

TEST(ChildProcess, TheChildHasAnEmptySignalMaskAndDefaultDispositions) {
  // The service blocks SIGTERM and ignores SIGPIPE in all its threads; its children must not.
  sigset_t block, old;
  sigemptyset(&block);
  sigaddset(&block, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &block, &old);
  auto previous = std::signal(SIGPIPE, SIG_IGN);
  const ChildResult r = shell("grep -E '^Sig(Blk|Ign)' /proc/self/status");
  std::signal(SIGPIPE, previous);
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  EXPECT_NE(r.output.find("SigBlk:\t0000000000000000"), std::string::npos) << r.output;
  // SIGPIPE is bit 13 (0x1000): not ignored.
  const auto ign = r.output.find("SigIgn:\t");
  ASSERT_NE(ign, std::string::npos);
  const unsigned long long ignored = std::stoull(r.output.substr(ign + 8, 16), nullptr, 16);
  EXPECT_EQ(ignored & (1ull << (SIGPIPE - 1)), 0u) << r.output;
}

TEST(ChildProcess, FindsTheMesherBesideThisProgramAndHonoursTheOverride) {
  EXPECT_NE(sibling_program("fosls-mesher", nullptr).find("fosls-mesher"), std::string::npos);
  EXPECT_THROW(sibling_program("no-such-program-here", nullptr), std::runtime_error);
  ::setenv("FOSLS_TEST_OVERRIDE", "/bin/sh", 1);
  EXPECT_EQ(sibling_program("fosls-mesher", "FOSLS_TEST_OVERRIDE"), "/bin/sh");
  ::setenv("FOSLS_TEST_OVERRIDE", "/nonexistent/program", 1);
  EXPECT_THROW(sibling_program("fosls-mesher", "FOSLS_TEST_OVERRIDE"), std::runtime_error);
  ::unsetenv("FOSLS_TEST_OVERRIDE");
}

TEST(ChildProcess, AMissingProgramIsAnErrorOfTheCaller) {
  ChildOptions o;
  o.argv = {"/nonexistent/program"};
  EXPECT_THROW(run_child(o), std::runtime_error);
}

}  // namespace
}  // namespace fosls
