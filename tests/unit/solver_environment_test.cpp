// restart_with_solver_environment (solver/process/solver_environment.hpp): how GLIBC_TUNABLES
// is completed, and that fosls-contact started without the settings runs with huge pages —
// measured by its page faults against a run where the caller turned them off (where the kernel
// gives huge pages on request, as on the project's Debian machines).
#include "process/solver_environment.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../shipped_example.hpp"

namespace fosls {
namespace {

namespace fs = std::filesystem;

TEST(SolverEnvironment, CompletesGlibcTunablesAndKeepsTheCallersChoice) {
  EXPECT_EQ(tunables_with_huge_pages(nullptr), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_pages(""), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.arena_max=1"),
            "glibc.malloc.arena_max=1:glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.hugetlb=0"), std::nullopt);
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.hugetlb=1"), std::nullopt);
}

/// Runs argv with exactly `env`, output discarded; the exit status and its minor page faults.
std::pair<int, long> run_counting_faults(const std::vector<std::string>& argv,
                                         const std::vector<std::string>& env) {
  std::vector<char*> a, e;
  for (const auto& s : argv) a.push_back(const_cast<char*>(s.c_str()));
  for (const auto& s : env) e.push_back(const_cast<char*>(s.c_str()));
  a.push_back(nullptr);
  e.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    execve(a[0], a.data(), e.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, usage.ru_minflt};
}

/// Huge pages only for memory that asks for them: the mode in which the setting decides (with
/// "always" every run gets them, with "never" none does).
bool kernel_gives_huge_pages_on_request() {
  std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(f, modes);
  return modes.find("[madvise]") != std::string::npos;
}

TEST(SolverEnvironment, TheSolverRunsOnHugePagesUnlessTheCallerSaysOtherwise) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer replaces glibc's malloc";
#endif
  if (!kernel_gives_huge_pages_on_request())
    GTEST_SKIP() << "transparent huge pages are not in \"madvise\" mode here";
  const fs::path file = fs::path(::testing::TempDir()) / "fosls_env_hertz.json";
  nlohmann::json c = testing::load_shipped_example("hertz");
  c["mesh"]["refinements"] = 4;  // 108 704 unknowns: tens of megabytes touched
  std::ofstream(file) << c.dump();
  const std::vector<std::string> argv = {std::string(FOSLS_BIN_DIR) + "/fosls-contact", "solve",
                                         file.string(), "--quiet"};
  const auto [plain_status, plain_faults] =
      run_counting_faults(argv, {"OMP_NUM_THREADS=1", "GLIBC_TUNABLES=glibc.malloc.hugetlb=0"});
  const auto [huge_status, huge_faults] = run_counting_faults(argv, {"OMP_NUM_THREADS=1"});
  std::printf("minor page faults: 4 KiB pages %ld, huge pages %ld\n", plain_faults, huge_faults);
  EXPECT_EQ(plain_status, 0);
  EXPECT_EQ(huge_status, 0);
  EXPECT_LT(huge_faults * 4, plain_faults);
}

}  // namespace
}  // namespace fosls
