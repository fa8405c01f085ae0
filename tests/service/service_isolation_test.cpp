// The real fosls-serve under hostile input: degenerate geometries (degenerate_geometries.hpp)
// and a mesher that aborts are answered with 202 or 422 while the server stays up; gmsh runs
// in a child process, so its abort is the child's end, not the server's.

#include <gtest/gtest.h>
#include <httplib.h>
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "../unit/degenerate_geometries.hpp"
#include "service_fixture.hpp"

namespace fosls::service {
namespace {

using nlohmann::json;
using testing::example;
using testing::expect_problem;
using testing::Service;

/// The 626-byte case that used to abort the whole server: a 200 × 1e-4 rectangle, size 1e-3.
json thin_rectangle_case() {
  json j = fosls::testing::polygon_case("thin", {{0, 0}, {200, 0}, {200, 1e-4}, {0, 1e-4}}, 1e-3);
  j["boundary"]["all"] = {{"type", "dirichlet"}, {"displacement", {0, 0}}};
  return j;
}

void expect_healthy(Service& svc) {
  auto res = svc.client().Get("/healthz");
  ASSERT_TRUE(res) << "the server does not answer any more";
  EXPECT_EQ(res->status, 200);
}

TEST(ServiceIsolation, DegenerateGeometriesNeverTakeTheServerDown) {
  Service svc(1);
  auto cases = fosls::testing::degenerate_cases(7, 12);
  cases.push_back({"the 200 x 1e-4 rectangle of size 1e-3", thin_rectangle_case()});
  int accepted = 0, refused = 0;
  for (const auto& c : cases) {
    const auto t0 = std::chrono::steady_clock::now();
    auto res = svc.post(c.case_json);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_TRUE(res) << c.label << ": no answer; log:\n" << svc.log();
    std::printf("%-45s %6.2f s  %d\n", c.label.c_str(), s, res->status);
    EXPECT_TRUE(res->status == 202 || res->status == 422) << c.label << ": " << res->body;
    (res->status == 202 ? accepted : refused) += 1;
    if (res->status == 422) {
      const json p = json::parse(res->body);
      ASSERT_FALSE(p["errors"].empty()) << res->body;
      const std::string pointer = p["errors"][0]["pointer"];
      EXPECT_TRUE(pointer.rfind("/mesh", 0) == 0 || pointer.rfind("/boundary", 0) == 0)
          << res->body;
    }
    expect_healthy(svc);
  }
  std::printf("%d accepted, %d refused\n", accepted, refused);
  EXPECT_EQ(svc.server().stop(), 0) << "the server did not stop cleanly; log:\n" << svc.log();
}

/// Points FOSLS_MESHER (inherited by servers started afterwards) at a script that aborts.
class AbortingMesher {
 public:
  AbortingMesher() {
    std::ofstream(path_) << "#!/bin/sh\ncat > /dev/null\n"
                            "echo \"terminate called after throwing an instance of "
                            "'std::string'\" >&2\nkill -ABRT $$\n";
    ::chmod(path_.c_str(), 0755);
    ::setenv("FOSLS_MESHER", path_.c_str(), 1);
  }
  ~AbortingMesher() {
    ::unsetenv("FOSLS_MESHER");
    std::remove(path_.c_str());
  }

 private:
  std::string path_ = "/tmp/fosls_aborting_mesher_" + std::to_string(::getpid()) + ".sh";
};

TEST(ServiceIsolation, AMesherAbortIsRefusedAtTheMeshAndTheServerStaysUp) {
  AbortingMesher aborting;
  Service svc(1);
  json hertz = example("hertz");  // the built-in Hertz geometry is meshed by gmsh too
  auto res = svc.post(hertz);
  ASSERT_TRUE(res) << "no answer; log:\n" << svc.log();
  expect_problem(res, 422);
  const json p = json::parse(res->body);
  EXPECT_EQ(p["errors"][0]["pointer"], "/mesh/builtin") << res->body;
  EXPECT_NE(p["errors"][0]["detail"].get<std::string>().find("gmsh crashed"), std::string::npos)
      << res->body;
  expect_healthy(svc);
  // The square is built without gmsh: it is still solved.
  const auto id = svc.submit(testing::small_case(1));
  svc.wait_state(id, "succeeded");
}

}  // namespace
}  // namespace fosls::service
