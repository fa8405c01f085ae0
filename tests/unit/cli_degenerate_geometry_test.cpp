// Fuzz-style: degenerate geometries (degenerate_geometries.hpp) given to the real command line
// program. Each must end with exit code 2 and an error line naming a field, never a signal
// (gmsh aborting used to end the CLI with exit 134). Bounded in time: the size guards refuse
// the slowest shapes, and the mesher has a deadline.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "degenerate_geometries.hpp"
#include "process/child_process.hpp"

namespace fosls {
namespace {

namespace fs = std::filesystem;

TEST(CliDegenerateGeometry, EveryCaseEndsWithExitCode2AndAField) {
  const std::string program = std::string(FOSLS_BIN_DIR) + "/fosls-contact";
  const fs::path work = fs::path(::testing::TempDir()) / "fosls_cli_degenerate";
  fs::create_directories(work);
  const auto cases = testing::degenerate_cases(20251123, 30);
  int refused_before_meshing = 0, meshed = 0;
  for (const auto& c : cases) {
    const fs::path file = work / (c.case_json["name"].get<std::string>() + ".json");
    std::ofstream(file) << c.case_json.dump();
    ChildOptions o;
    o.argv = {program, "solve", file.string(), "--quiet"};
    o.limits.wall = std::chrono::seconds(180);
    const ChildResult r = run_child(o);
    std::printf("%-45s %6.2f s  %s  %s\n", c.label.c_str(), r.seconds, r.describe().c_str(),
                r.errors.substr(0, std::min(r.errors.find('\n'), std::size_t{100})).c_str());
    EXPECT_EQ(r.end, ChildResult::End::kExited) << c.label << ": " << r.describe() << "\n"
                                                << r.errors;
    EXPECT_EQ(r.exit_code, 2) << c.label << "\n" << r.errors;
    EXPECT_EQ(r.errors.rfind("error: /", 0), 0u) << c.label << "\n" << r.errors;
    if (r.errors.find("error: /boundary:") != std::string::npos) ++meshed;
    if (r.errors.find("error: /mesh/") == 0) ++refused_before_meshing;
  }
  std::printf("%d cases: %d meshed (then refused at /boundary), %d refused at /mesh\n",
              static_cast<int>(cases.size()), meshed, refused_before_meshing);
  // The families must reach both outcomes, or the test no longer exercises the mesher.
  EXPECT_GT(meshed, 3);
  EXPECT_GT(refused_before_meshing, 3);
}

}  // namespace
}  // namespace fosls
