#pragma once
// The environment the programs that solve (fosls-contact, fosls-solve-job) want from their
// first instruction on. Two settings are read by libraries as they load, before main runs:
//
// - OMP_WAIT_POLICY=passive: OpenMP threads that wait sleep instead of spinning: spinning
//   waiters made a two-thread solve slower than a one-thread one while another process held a
//   core (docs/performance.md).
// - glibc.malloc.hugetlb=1 in GLIBC_TUNABLES: malloc asks for transparent huge pages (2 MiB)
//   for its large blocks. A solve's matrices and vectors are touched page by page when first
//   written: huge pages make far fewer page faults and TLB misses in the sparse products
//   (measurements: docs/performance.md). The kernel must allow it ("madvise" or "always" in
//   /sys/kernel/mm/transparent_hugepage/enabled); otherwise the setting does nothing.
//
// A value the caller set is kept: the caller can turn either off.

#include <optional>
#include <string>

namespace fosls {

/// The value GLIBC_TUNABLES should have given its current value (nullptr: unset), or nothing
/// when it already says what glibc.malloc.hugetlb should be.
std::optional<std::string> tunables_with_huge_pages(const char* current);

/// Sets what is missing of the two settings and, if anything was, starts the program again
/// (execv of /proc/self/exe with `argv`, same process, same open files). Call first in main,
/// before any thread or output exists. Returns only when nothing was missing or the restart
/// failed (the program then runs as it is).
void restart_with_solver_environment(char** argv);

}  // namespace fosls
