// use_one_malloc_arena: threads that allocate at the same time share the main arena, so memory
// one thread frees is reused by the others (the two-thread peak of a solve equals the one-thread
// peak). keep_freed_memory: a block freed and allocated again comes back without page faults.
#include "process/malloc_arenas.hpp"

#include <gtest/gtest.h>
#include <malloc.h>
#include <omp.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace fosls {
namespace {

/// The number of arenas glibc reports (one <heap nr=…> element each in malloc_info's XML).
int malloc_arenas() {
  char* text = nullptr;
  std::size_t size = 0;
  FILE* f = open_memstream(&text, &size);
  malloc_info(0, f);
  std::fclose(f);
  const std::string xml(text, size);
  std::free(text);
  int count = 0;
  for (std::size_t at = xml.find("<heap nr="); at != std::string::npos;
       at = xml.find("<heap nr=", at + 1))
    ++count;
  return count;
}

TEST(MallocArenas, ThreadsAllocatingTogetherShareOneArena) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer replaces glibc's malloc: there are no arenas to count";
#endif
  ASSERT_TRUE(use_one_malloc_arena());
#pragma omp parallel num_threads(4)
  {
    // Each thread allocates and frees while the others do the same: without the setting
    // glibc hands the contending threads arenas of their own.
    for (int k = 0; k < 200; ++k) {
      std::vector<double> v(10000 + 1000 * omp_get_thread_num(), 1.0);
#pragma omp barrier
    }
  }
  EXPECT_EQ(malloc_arenas(), 1);
}

long minor_page_faults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

/// Allocates `bytes`, writes every page, frees it; returns the page faults that took.
long faults_of_a_written_block(std::size_t bytes) {
  const long before = minor_page_faults();
  auto* block = static_cast<volatile char*>(std::malloc(bytes));
  for (std::size_t i = 0; i < bytes; i += 4096) block[i] = 1;
  std::free(const_cast<char*>(block));
  return minor_page_faults() - before;
}

TEST(MallocArenas, AFreedBlockComesBackWithoutPageFaults) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer replaces glibc's malloc";
#endif
  ASSERT_TRUE(keep_freed_memory());
  // 64 MiB: above the largest threshold glibc picks by itself (32 MiB), so without the setting
  // the block is a mapping of its own and every one of its 16 384 pages faults again.
  constexpr std::size_t kBytes = 64u << 20;
  const long first = faults_of_a_written_block(kBytes);
  const long again = faults_of_a_written_block(kBytes);
  // With 4 KiB pages the first pass faults 16 384 times, with huge pages (an inherited
  // GLIBC_TUNABLES, a kernel that gives them always) a few hundred; either way the pages were
  // new, and kept memory comes back with at most a twentieth of those faults.
  EXPECT_GT(first, 0);
  EXPECT_LE(again * 20, first) << "first " << first << " faults, again " << again;
}

}  // namespace
}  // namespace fosls
