#include "process/malloc_arenas.hpp"

#include <malloc.h>

#include <limits>

namespace fosls {

bool use_one_malloc_arena() { return mallopt(M_ARENA_MAX, 1) == 1; }

bool keep_freed_memory() {
  // Blocks below 1 GiB come from the heap, and its top is kept up to 2 GiB (mallopt takes an
  // int): a larger block is rare enough to keep a mapping of its own.
  constexpr int kMmapThreshold = 1 << 30;
  constexpr int kTrimThreshold = std::numeric_limits<int>::max();
  // Each is set even if glibc refuses the other (old versions cap the mmap threshold at 32 MiB).
  const bool mmap_set = mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1;
  const bool trim_set = mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1;
  return mmap_set && trim_set;
}

bool give_large_blocks_back() { return mallopt(M_MMAP_THRESHOLD, 1 << 20) == 1; }

void return_freed_memory() { malloc_trim(0); }

}  // namespace fosls
