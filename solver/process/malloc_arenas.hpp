#pragma once
// One malloc arena for the whole process, for the programs that solve (fosls-contact,
// fosls-solve-job). glibc gives a thread that allocates while another holds the main arena an
// arena of its own, and memory freed there is reused only by allocations made there: with the
// OpenMP threads of assembly, factorisation and Galerkin products, a two-thread solve peaked
// 7–10 % above a one-thread solve of the same case (408 against 369 MiB at 524k unknowns,
// 1 511 against 1 460 at 2.1M). The threads allocate little inside their loops (work vectors
// once per region), so sharing one arena cost no measurable time (docs/performance.md).

namespace fosls {

/// Call at the start of main, before any thread exists. Returns false if glibc refused.
bool use_one_malloc_arena();

}  // namespace fosls
