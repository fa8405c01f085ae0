#pragma once
// How the programs that solve (fosls-contact, fosls-solve-job) set up malloc. One arena for
// the whole process: glibc gives each new thread that allocates an arena of its own (up to eight
// per core), and memory freed in an arena is reused only by allocations made from it: with the
// OpenMP threads of assembly, factorisation and Galerkin products, a two-thread solve peaked
// above a one-thread solve of the same case. The hot loops allocate only small vectors (served
// by glibc's per-thread cache without the arena's lock), so sharing one arena costs no
// measurable time (measurements: docs/performance.md, "One malloc arena").

namespace fosls {

/// Call at the start of main, before any thread exists. Returns false if glibc refused.
bool use_one_malloc_arena();

/// Memory a solve frees stays in the process for its next allocations, up to the solve's own
/// peak, instead of going back to the kernel and coming back page by page: glibc returns every
/// freed block above its mmap threshold (at most 32 MiB, raised as blocks are freed) and the top
/// of the heap above twice that, and a solve frees and allocates matrices of the same sizes over
/// and over (each rebuild of the coarse levels, each adaptive step). Each page that comes back
/// is a page fault, and such re-faults were a large part of a solve's system time
/// (docs/performance.md). The peak is unchanged: freed memory is reused, not added to. For the
/// programs that run one solve and exit; a long-running server should give memory back. Call at the
/// start of main. Returns false if glibc refused.
bool keep_freed_memory();

/// The opposite, for a long-running server that handles large requests now and then (a 4 MiB
/// case body parses into tens of MiB): blocks of 1 MiB and more are mapped on their own and
/// unmapped when freed, instead of glibc raising its mmap threshold after the first such free
/// and keeping later ones in its heaps. Call at the start of main. Returns false if glibc
/// refused.
bool give_large_blocks_back();

/// Returns the free memory of every malloc arena to the system (malloc_trim): after work that
/// allocated much in many small blocks (a parsed JSON document).
void return_freed_memory();

}  // namespace fosls
