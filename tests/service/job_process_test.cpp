// The solve process's plumbing: the stream protocol read in pieces of every size,
// --max-job-memory sizes, and a real fosls-solve-job stopping a mesh that outgrew its admission.
#include <gtest/gtest.h>

#include <cmath>

#include "job_process_protocol.hpp"
#include "memory_budget.hpp"
#include "process_job_runner.hpp"

namespace fosls::service {
namespace {

TEST(JobProcessProtocol, ReadsProgressAndResultInPiecesOfAnySize) {
  JobRunOutcome done;
  done.kind = JobRunOutcome::Kind::kSucceeded;
  done.result_json = R"({"converged": true, "text": "P 1 2 3\nE\n"})";
  done.vtu = std::string(100000, 'v') + "\nE\n";
  const std::string stream = progress_message({1, 0.5, -2.25}) +
                             progress_message({2, 1e-300, 1.0 / 3, 2, 3}) + outcome_message(done);
  for (std::size_t piece : {std::size_t{1}, std::size_t{7}, std::size_t{4096}, stream.size()}) {
    std::vector<JobProgress> seen;
    JobProcessReader reader([&](const JobProgress& p) { seen.push_back(p); });
    for (std::size_t i = 0; i < stream.size(); i += piece)
      reader.feed(std::string_view(stream).substr(i, piece));
    ASSERT_TRUE(reader.outcome()) << "piece " << piece << ": " << reader.malformed();
    EXPECT_EQ(reader.outcome()->kind, JobRunOutcome::Kind::kSucceeded);
    EXPECT_EQ(reader.outcome()->result_json, done.result_json);
    EXPECT_EQ(reader.outcome()->vtu, done.vtu);
    ASSERT_EQ(seen.size(), 2u);
    EXPECT_EQ(seen[1].iteration, 2);
    EXPECT_EQ(seen[1].kkt_residual, 1e-300);
    EXPECT_EQ(seen[1].energy, 1.0 / 3);  // round trip to the last bit
    EXPECT_EQ(seen[1].step, 2);
    EXPECT_EQ(seen[1].steps, 3);
  }
}

// A solve process from before steps were reported writes three numbers: step 0 of a number
// not known.
TEST(JobProcessProtocol, AProgressLineWithoutStepsIsTheFirstOfUnknownMany) {
  std::vector<JobProgress> seen;
  JobProcessReader reader([&](const JobProgress& p) { seen.push_back(p); });
  reader.feed("P 4 0.5 -1\nC\nE\n");
  ASSERT_TRUE(reader.outcome()) << reader.malformed();
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].iteration, 4);
  EXPECT_EQ(seen[0].step, 0);
  EXPECT_EQ(seen[0].steps, 0);
}

TEST(JobProcessProtocol, FailuresCancelAndGarbage) {
  JobRunOutcome failed;
  failed.kind = JobRunOutcome::Kind::kFailed;
  failed.error = "invalid case: /weights: too large";
  JobProcessReader a(nullptr);
  a.feed(outcome_message(failed));
  ASSERT_TRUE(a.outcome());
  EXPECT_EQ(a.outcome()->error, failed.error);

  JobRunOutcome cancelled;
  cancelled.kind = JobRunOutcome::Kind::kCancelled;
  JobProcessReader b(nullptr);
  b.feed(outcome_message(cancelled));
  ASSERT_TRUE(b.outcome());
  EXPECT_EQ(b.outcome()->kind, JobRunOutcome::Kind::kCancelled);

  for (const char* garbage : {"hello\n", "S abc\n", "P 1 x y\n", "P 1 2 3 4\n", "\n"}) {
    JobProcessReader c(nullptr);
    c.feed(garbage);
    EXPECT_FALSE(c.outcome()) << garbage;
    EXPECT_FALSE(c.malformed().empty()) << garbage;
  }
  JobProcessReader truncated(nullptr);
  truncated.feed("S 100\n{\"a\":");
  EXPECT_FALSE(truncated.outcome());
  EXPECT_TRUE(truncated.malformed().empty());  // waiting for the rest
}

// A solve process killed on cancel leaves the last partial result it sent (its load steps).
TEST(JobProcessProtocol, TheLastPartialResultIsKeptWhenTheProcessEndsWithoutAnOutcome) {
  JobProcessReader reader(nullptr);
  EXPECT_EQ(reader.partial_result(), "");
  reader.feed(partial_message(R"({"load_steps": {"count": 1}})") + progress_message({1, 1, 1}));
  reader.feed(partial_message(R"({"load_steps": {"count": 2}})").substr(0, 9));
  EXPECT_EQ(reader.partial_result(), R"({"load_steps": {"count": 1}})");  // the second is not whole
  reader.feed(partial_message(R"({"load_steps": {"count": 2}})").substr(9));
  EXPECT_EQ(reader.partial_result(), R"({"load_steps": {"count": 2}})");
  EXPECT_FALSE(reader.outcome());
  EXPECT_TRUE(reader.malformed().empty());
}

TEST(MemoryBudget, ParsesSizesAsOperatorsWriteThem) {
  EXPECT_EQ(parse_byte_size("512M"), std::size_t{512} << 20);
  EXPECT_EQ(parse_byte_size("2G"), std::size_t{2} << 30);
  EXPECT_EQ(parse_byte_size("2GiB"), std::size_t{2} << 30);
  EXPECT_EQ(parse_byte_size("1.5G"), std::size_t{3} << 29);
  EXPECT_EQ(parse_byte_size("300000K"), std::size_t{300000} << 10);
  EXPECT_EQ(parse_byte_size("1048576"), std::size_t{1} << 20);
  EXPECT_EQ(parse_byte_size("64mb"), std::size_t{64} << 20);
  for (const char* bad : {"", "G", "-1G", "0", "abc", "1X", "1e400", "nan", "2 G B"})
    EXPECT_FALSE(parse_byte_size(bad)) << bad;
  EXPECT_EQ(format_bytes(std::size_t{100} << 20), "100 MiB");
  EXPECT_EQ(format_bytes(std::size_t{5} << 29), "2.5 GiB");
  EXPECT_GT(default_job_memory(2), std::size_t{0});
  EXPECT_LT(default_job_memory(2), physical_memory());
}

TEST(SolveProcess, AMeshLargerThanItsAdmissionIsStoppedOnceBuiltBeforeItIsRefined) {
  // A 1000-sided polygon at size 1 and 4 refinements: about 1.2 M unknowns, 0.9 GiB. Run
  // without the API's admission against a 100 MiB budget, its process must stop it right after
  // gmsh built the coarse mesh: refined, it would run out of its address space instead.
  nlohmann::json points = nlohmann::json::array(), curves = nlohmann::json::array(),
                 all = nlohmann::json::array();
  for (int i = 0; i < 1000; ++i) {
    points.push_back({std::cos(2 * M_PI * i / 1000), std::sin(2 * M_PI * i / 1000)});
    curves.push_back({{"type", "line"}, {"points", {i, (i + 1) % 1000}}});
    all.push_back(i);
  }
  const nlohmann::json polygon = {
      {"mesh",
       {{"geometry", {{"points", points}, {"curves", curves}, {"groups", {{"all", all}}}}},
        {"size", 1},
        {"refinements", 4}}},
      {"material", {{"mu", 1}, {"lambda", 1}}},
      {"boundary", {{"all", {{"type", "dirichlet"}, {"displacement", {0, 0}}}}}}};
  ProcessJobRunnerOptions options;
  options.memory_bytes = std::size_t{100} << 20;
  options.admission_memory_bytes = options.memory_bytes;
  const std::atomic<bool> never{false};
  const JobRunOutcome outcome = process_job_runner(options)(polygon, {never, nullptr});
  EXPECT_EQ(outcome.kind, JobRunOutcome::Kind::kFailed);
  for (const char* part :
       {"/mesh/refinements: counted on the coarse mesh gmsh built: the solve needs",
        "more than the 100 MiB a job may use", "use fewer refinements"})
    EXPECT_NE(outcome.error.find(part), std::string::npos) << part << " in: " << outcome.error;
}

}  // namespace
}  // namespace fosls::service
