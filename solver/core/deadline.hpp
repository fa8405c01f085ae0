#pragma once
// A run's wall-clock deadline (solver.time_limit_s) as the stages before the first iterate see
// it: the case runner checks it once the mesh is refined, the spaces between levels and the
// assembly every so many elements, and they throw TimeLimitReached, because until the solve has
// an iterate there is nothing to stop at. The
// solve loop asks the same deadline before each iteration and stops at the last iterate
// (SolverObserver::out_of_time). Polling reads the clock only: results are the same bit for bit
// whether a deadline is set or not, as long as it does not pass.

#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>

namespace fosls {

/// The deadline passed during `stage` ("refining the mesh", "assembling the finest level", …),
/// before the solve had an iterate; the case runner rethrows it with the whole message.
class TimeLimitReached : public std::runtime_error {
 public:
  explicit TimeLimitReached(std::string stage)
      : TimeLimitReached(stage, "the time limit ran out while " + stage) {}
  TimeLimitReached(std::string stage, const std::string& message)
      : std::runtime_error(message), stage_(std::move(stage)) {}
  const std::string& stage() const { return stage_; }

 private:
  std::string stage_;
};

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  /// Elements between two polls of an element loop: a clock read is cheap next to an element's
  /// work, and this many keep it out of any profile.
  static constexpr int kPollEvery = 1024;

  Deadline() = default;  ///< none: never passes
  explicit Deadline(Clock::time_point at) : at_(at) {}

  bool is_set() const { return at_.has_value(); }
  bool passed() const { return at_ && Clock::now() >= *at_; }
  /// Throws TimeLimitReached(stage) once the deadline has passed.
  void check(const std::string& stage) const {
    if (passed()) throw TimeLimitReached(stage);
  }

 private:
  std::optional<Clock::time_point> at_;
};

}  // namespace fosls
