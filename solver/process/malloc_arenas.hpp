#pragma once
// One malloc arena for the whole process, for the programs that solve (fosls-contact,
// fosls-solve-job). glibc gives each new thread that allocates an arena of its own (up to eight
// per core), and memory freed in an arena is reused only by allocations made from it: with the
// OpenMP threads of assembly, factorisation and Galerkin products, a two-thread solve peaked
// above a one-thread solve of the same case (408 against 369 MiB at 524k unknowns, +11 %;
// 1 511 against 1 460 MiB at 2.1M, +3.5 %). The hot loops allocate only small vectors (served
// by glibc's per-thread cache without the arena's lock), so sharing one arena cost no
// measurable time (docs/performance.md).

namespace fosls {

/// Call at the start of main, before any thread exists. Returns false if glibc refused.
bool use_one_malloc_arena();

}  // namespace fosls
