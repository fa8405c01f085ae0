// gmsh runs in the mesher process: every way it can end (an abort inside gmsh, a hang, running
// out of memory, garbage, cancel) becomes a MeshError at the mesh source's field, or
// MeshingCancelled, never the end of this process. Fake meshers (shell scripts, through
// FOSLS_MESHER) stand for each failure; the real gmsh abort is reproduced once.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "case/run/mesh_factory.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "mesh/mesher_protocol.hpp"
#include "process/child_process.hpp"

namespace fosls {
namespace {

namespace fs = std::filesystem;
using Curve = GeometrySpec::Curve;

GeometrySpec rectangle(double length, double height) {
  GeometrySpec g;
  g.points = {Point(0, 0), Point(length, 0), Point(length, height), Point(0, height)};
  g.curves = {{false, {0, 1}, -1}, {false, {1, 2}, -1}, {false, {2, 3}, -1}, {false, {3, 0}, -1}};
  g.groups = {{"bottom", {0}}, {"right", {1}}, {"top", {2}}, {"left", {3}}};
  return g;
}

/// Points FOSLS_MESHER at a shell script for the lifetime of the object.
class FakeMesher {
 public:
  explicit FakeMesher(const std::string& body) {
    std::ofstream(path_) << "#!/bin/sh\ncat > /dev/null\n" << body << "\n";
    ::chmod(path_.c_str(), 0755);
    ::setenv("FOSLS_MESHER", path_.c_str(), 1);
  }
  ~FakeMesher() {
    ::unsetenv("FOSLS_MESHER");
    fs::remove(path_);
  }

 private:
  fs::path path_ =
      fs::temp_directory_path() / ("fosls_fake_mesher_" + std::to_string(::getpid()) + ".sh");
};

/// The problem of meshing the unit square, as "field: detail".
std::string problem_of(const MeshingControl& control = {}) {
  try {
    mesh_from_geometry(rectangle(1, 1), 0.5, control);
  } catch (const MeshError& e) {
    return e.problems().at(0).field + ": " + e.problems().at(0).detail;
  }
  return "no error";
}

TEST(GmshIsolation, TheRealGmshAbortStaysInTheMesher) {
  // gmsh 4.8 throws a std::string inside an OpenMP region on this rectangle (200 × 1e-4,
  // size 1e-3) and the process aborts. The library refuses it before meshing (boundary
  // edges), so the request goes to the mesher directly.
  ChildOptions o;
  o.argv = {sibling_program("fosls-mesher", nullptr)};
  SizeField size;
  size.size = 1e-3;
  o.input = request_to_json(GeometryMeshRequest{rectangle(200, 1e-4), size}).dump();
  o.limits.wall = std::chrono::seconds(120);
  const ChildResult r = run_child(o);
  EXPECT_EQ(r.end, ChildResult::End::kSignaled) << r.describe() << "\n" << r.errors;
  EXPECT_EQ(r.signal, SIGABRT) << r.describe();
}

TEST(GmshIsolation, TheThinRectangleIsRefusedBeforeMeshing) {
  try {
    mesh_from_geometry(rectangle(200, 1e-4), 1e-3);
    FAIL() << "meshed";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.problems().at(0).field, "/size");
    EXPECT_NE(e.problems().at(0).detail.find("boundary edges"), std::string::npos);
  }
  EXPECT_THROW(mesh_from_geometry(rectangle(100, 1e-4), 1e-3), MeshError);
}

TEST(GmshIsolation, AnAbortBecomesAMeshErrorAtTheGeometry) {
  FakeMesher fake(
      "echo \"terminate called after throwing an instance of 'std::string'\" >&2\n"
      "kill -ABRT $$");
  const std::string p = problem_of();
  EXPECT_EQ(p.rfind("/geometry: gmsh crashed while meshing this geometry (signal 6", 0), 0u) << p;
}

TEST(GmshIsolation, AHangIsKilledAtTheDeadline) {
  FakeMesher fake("sleep 30");
  MeshingControl control;
  control.limits.time = std::chrono::milliseconds(300);
  const auto t0 = std::chrono::steady_clock::now();
  const std::string p = problem_of(control);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(p,
            "/geometry: gmsh did not finish meshing within 0.3 s; use a larger mesh size or a "
            "simpler geometry");
  EXPECT_LT(s, 10.0);
}

TEST(GmshIsolation, RunningOutOfMemoryIsSaid) {
  FakeMesher fake(
      "echo \"terminate called after throwing an instance of 'std::bad_alloc'\" >&2\n"
      "kill -ABRT $$");
  EXPECT_NE(problem_of().find("gmsh ran out of memory while meshing (the mesher may use 2048 MiB)"),
            std::string::npos);
}

TEST(GmshIsolation, TheRealMesherUnderATinyMemoryLimitFailsCleanly) {
  if (!kAddressSpaceLimitsApplied) GTEST_SKIP() << "no address-space limit under ASan";
  MeshingControl control;
  control.limits.memory_bytes = std::size_t{160} << 20;  // gmsh alone maps ~115 MiB
  try {
    mesh_from_geometry(rectangle(1, 1), 0.004, control);  // ~140 000 triangles
    FAIL() << "meshed within 160 MiB";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.problems().at(0).field, "/geometry");
    EXPECT_NE(e.problems().at(0).detail.find("out of memory"), std::string::npos)
        << e.problems().at(0).detail;
  }
}

TEST(GmshIsolation, GarbageOrAFailedMesherIsAnInternalError) {
  {
    FakeMesher fake("echo 'not json'");
    EXPECT_THROW(problem_of(), std::runtime_error);
    try {
      problem_of();
    } catch (const MeshError&) {
      ADD_FAILURE() << "garbage from the mesher is not the user's fault";
    } catch (const std::runtime_error&) {
    }
  }
  FakeMesher fake("echo '{\"mesh\": {\"vertices\": [0, 0]}}'");
  EXPECT_THROW(problem_of(), std::runtime_error);
}

TEST(GmshIsolation, AnInvalidMeshFromTheMesherIsReportedAtItsField) {
  // Two triangles with the same orientation across their shared edge.
  FakeMesher fake(R"(echo '{"mesh": {"vertices": [0,0, 1,0, 0,1, 1,1], "triangles": [0,1,2, 1,2,3],
                  "segments": [], "groups": ["all"], "curves": []}}')");
  EXPECT_EQ(problem_of().rfind("/geometry: the generated mesh is not valid", 0), 0u)
      << problem_of();
}

TEST(GmshIsolation, CancelKillsTheMesher) {
  FakeMesher fake("sleep 30");
  std::atomic<bool> cancel{false};
  std::thread canceller([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    cancel = true;
  });
  MeshingControl control;
  control.cancel = &cancel;
  EXPECT_THROW(mesh_from_geometry(rectangle(1, 1), 0.5, control), MeshingCancelled);
  canceller.join();
}

TEST(GmshIsolation, TheCaseLayerPutsMesherFailuresUnderMesh) {
  FakeMesher fake("kill -ABRT $$");
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kGeometry;
  spec.geometry = rectangle(1, 1);
  spec.size = 0.5;
  try {
    build_coarse_mesh(spec);
    FAIL();
  } catch (const CaseException& e) {
    EXPECT_EQ(e.errors().at(0).pointer, "/mesh/geometry");
  }
  spec = MeshSpec{};
  spec.builtin = "hertz";  // meshed by gmsh as well: the error is where the user wrote it
  spec.size = 0.1;
  try {
    build_coarse_mesh(spec);
    FAIL();
  } catch (const CaseException& e) {
    EXPECT_EQ(e.errors().at(0).pointer, "/mesh/builtin");
  }
}

}  // namespace
}  // namespace fosls
