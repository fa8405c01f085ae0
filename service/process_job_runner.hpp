#pragma once
// The JobRunner that solves each job in its own process (fosls-solve-job): a solve that runs
// out of memory or crashes fails its job with a clear message and nothing else; cancel and
// shutdown kill the process at once, in any stage (meshing, assembly, set-up, solving); the
// memory of every job returns to the system when its process exits.

#include <chrono>
#include <cstddef>
#include <string>

#include "job_runner.hpp"

namespace fosls::service {

/// Address space a solve process needs beyond its resident data: shared libraries, thread
/// stacks, malloc arenas and OpenBLAS buffers (measured with a margin: docs/service.md,
/// "Isolation").
inline constexpr std::size_t kSolveAddressSpaceHeadroom = std::size_t{768} << 20;

struct ProcessJobRunnerOptions {
  /// Memory a job may use (--max-job-memory): its address space is limited to this plus
  /// kSolveAddressSpaceHeadroom.
  std::size_t memory_bytes = std::size_t{2} << 30;
  /// OpenMP and OpenBLAS threads of each solve process.
  int threads = 1;
  /// The most wall-clock time a job may run (--max-job-seconds); 0: no limit. Each job gets
  /// job_time_limit(the estimate stored with it) within it (case_job_runner.hpp), and is killed
  /// at it.
  double max_job_seconds = 0;
  /// The budget cases were admitted against (0: none, --admit-over-budget): the solve process
  /// checks the exact mesh against it once built and fails at once if it outgrew it.
  std::size_t admission_memory_bytes = 0;
  /// The solve program; empty: fosls-solve-job beside this program (FOSLS_SOLVE_JOB overrides).
  std::string program;
};

/// A JobRunner that runs each case in a child process under `options`.
JobRunner process_job_runner(ProcessJobRunnerOptions options);

}  // namespace fosls::service
