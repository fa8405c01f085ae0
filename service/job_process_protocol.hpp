#pragma once
// What a solve process (fosls-solve-job) says to the worker that started it, on its stdout:
// progress lines while it runs, then how the run ended. Framed with byte counts, so a VTU of
// any size passes through without being scanned:
//
//   P <iteration> <kkt_residual> <energy> <step> <steps>\n    progress (any number)
//   S <n>\n<n bytes: result JSON>V <m>\n<m bytes: VTU>E\n        succeeded
//   F <n>\n<n bytes: message>E\n                  failed (a case problem found while running)
//   C\nE\n                                         cancelled (from inside the run)
//   K <n>\n<n bytes: result JSON>                 what a cancel now would leave (load steps:
//                                                 the steps solved so far); any number, the
//                                                 last one counts when the process is killed
//
// A progress line without <step> <steps> (a solve process from before they existed) reads as
// step 0 of an unknown number; a reader from then ignores them (it scans three numbers).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "job.hpp"
#include "job_runner.hpp"

namespace fosls::service {

/// Child side: the text of one message.
std::string progress_message(const JobProgress& progress);
std::string outcome_message(const JobRunOutcome& outcome);
std::string partial_message(const std::string& result_json);

/// Parent side: reads the stream as it arrives.
class JobProcessReader {
 public:
  explicit JobProcessReader(std::function<void(const JobProgress&)> on_progress)
      : on_progress_(std::move(on_progress)) {}

  /// Consumes the next piece of the stream.
  void feed(std::string_view data);
  /// The outcome, once the end marker has been read.
  const std::optional<JobRunOutcome>& outcome() const { return outcome_; }
  /// The last partial result (K) read: what the run leaves if it is killed now; empty for none.
  const std::string& partial_result() const { return partial_; }
  /// Set when the stream is not in this format (then nothing more is read).
  const std::string& malformed() const { return malformed_; }

 private:
  /// Parses complete messages at the front of buffer_; false when more bytes are needed.
  bool parse_one();

  std::function<void(const JobProgress&)> on_progress_;
  std::string buffer_;
  JobRunOutcome pending_;
  std::optional<JobRunOutcome> outcome_;
  std::string partial_;
  std::string malformed_;
};

}  // namespace fosls::service
