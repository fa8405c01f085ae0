// Benchmark (not a test): DOFs, refinement and assembly time and peak memory of the FOSLS
// system on `square` over 5 levels, up to more than 1M DOFs.
//
//   build/bin/fosls-bench-assembly [first_level=6] [last_level=10]
//
// Each level runs in a child process so that the peak memory (ru_maxrss) is its own.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "assembly/discretization.hpp"
#include "mesh/builtin_meshes.hpp"

namespace {

using Clock = std::chrono::steady_clock;

void run_level(int level) {
  using namespace fosls;
  const auto t0 = Clock::now();
  MeshHierarchy meshes = build_mesh_hierarchy(make_square({.size = 0.5}), level - 1);
  const auto t1 = Clock::now();
  ProblemData<2> data;
  data.groups.resize(4);
  data.groups[0].role = GroupRole::kDirichlet;  // bottom
  data.groups[1].role = data.groups[2].role = data.groups[3].role = GroupRole::kNeumann;
  data.body_force[1] = [](double, double) { return -1.0; };
  Discretization disc(std::move(meshes), std::move(data));
  const auto t2 = Clock::now();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("%5d %10d %10d %12lld %10.3f %10.3f %10.1f\n", level,
              disc.meshes().finest().num_triangles(), disc.problem().qp.size(),
              static_cast<long long>(disc.problem().qp.A.nonZeros()),
              std::chrono::duration<double>(t1 - t0).count(),
              std::chrono::duration<double>(t2 - t1).count(), usage.ru_maxrss / 1024.0);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int first = argc > 1 ? std::atoi(argv[1]) : 6;
  const int last = argc > 2 ? std::atoi(argv[2]) : 10;
  std::printf("%5s %10s %10s %12s %10s %10s %10s\n", "level", "triangles", "dofs", "nnz(A)",
              "refine_s", "assemble_s", "peak_MiB");
  std::fflush(stdout);
  for (int level = first; level <= last; ++level) {
    const pid_t pid = fork();
    if (pid == 0) {
      run_level(level);
      _exit(0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    if (status != 0) std::printf("%5d failed (status %d)\n", level, status);
  }
}
