#include "process/solver_environment.hpp"

#include <unistd.h>

#include <cstdlib>

namespace fosls {

std::optional<std::string> tunables_with_huge_pages(const char* current) {
  constexpr const char* kHugePages = "glibc.malloc.hugetlb=1";
  if (current == nullptr || *current == '\0') return std::string(kHugePages);
  const std::string value(current);
  if (value.find("glibc.malloc.hugetlb") != std::string::npos) return std::nullopt;
  return value + ":" + kHugePages;  // GLIBC_TUNABLES separates its entries by colons
}

void restart_with_solver_environment(char** argv) {
  bool changed = false;
  if (!std::getenv("OMP_WAIT_POLICY")) changed |= setenv("OMP_WAIT_POLICY", "passive", 1) == 0;
  if (const auto tunables = tunables_with_huge_pages(std::getenv("GLIBC_TUNABLES")))
    changed |= setenv("GLIBC_TUNABLES", tunables->c_str(), 1) == 0;
  if (changed) execv("/proc/self/exe", argv);  // returns only on failure
}

}  // namespace fosls
