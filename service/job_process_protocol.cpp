#include "job_process_protocol.hpp"

#include <charconv>
#include <cstdio>

namespace fosls::service {

namespace {

std::string framed(char tag, const std::string& bytes) {
  return std::string(1, tag) + " " + std::to_string(bytes.size()) + "\n" + bytes;
}

}  // namespace

std::string progress_message(const JobProgress& p) {
  char line[128];
  std::snprintf(line, sizeof line, "P %d %.17g %.17g %d %d\n", p.iteration, p.kkt_residual,
                p.energy, p.step, p.steps);
  return line;
}

std::string outcome_message(const JobRunOutcome& outcome) {
  switch (outcome.kind) {
    case JobRunOutcome::Kind::kSucceeded:
      return framed('S', outcome.result_json) + framed('V', outcome.vtu) + "E\n";
    case JobRunOutcome::Kind::kFailed:
      return framed('F', outcome.error) + "E\n";
    case JobRunOutcome::Kind::kCancelled:
      return "C\nE\n";
  }
  return "E\n";
}

std::string partial_message(const std::string& result_json) { return framed('K', result_json); }

void JobProcessReader::feed(std::string_view data) {
  if (!malformed_.empty() || outcome_) return;
  buffer_.append(data);
  while (malformed_.empty() && !outcome_ && parse_one()) {
  }
}

bool JobProcessReader::parse_one() {
  const auto eol = buffer_.find('\n');
  if (eol == std::string::npos) {
    if (buffer_.size() > 256) malformed_ = "a header line longer than 256 bytes";
    return false;
  }
  const std::string header = buffer_.substr(0, eol);
  if (header.empty()) {
    malformed_ = "an empty header line";
    return false;
  }
  const char tag = header[0];
  if (tag == 'P') {
    JobProgress p;
    const int read = std::sscanf(header.c_str(), "P %d %lf %lf %d %d", &p.iteration,
                                 &p.kkt_residual, &p.energy, &p.step, &p.steps);
    if (read != 3 && read != 5) {
      malformed_ = "a progress line that does not parse: " + header;
      return false;
    }
    buffer_.erase(0, eol + 1);
    if (on_progress_) on_progress_(p);
    return true;
  }
  if (tag == 'C' || tag == 'E') {
    buffer_.erase(0, eol + 1);
    if (tag == 'C') pending_.kind = JobRunOutcome::Kind::kCancelled;
    if (tag == 'E') outcome_ = std::move(pending_);
    return true;
  }
  if (tag != 'S' && tag != 'V' && tag != 'F' && tag != 'K') {
    malformed_ = "an unknown message: " + header.substr(0, 40);
    return false;
  }
  std::size_t n = 0;
  const char* first = header.data() + 2;
  const char* last = header.data() + header.size();
  if (header.size() < 3 || header[1] != ' ' || std::from_chars(first, last, n).ptr != last) {
    malformed_ = "a length that does not parse: " + header.substr(0, 40);
    return false;
  }
  if (buffer_.size() < eol + 1 + n) return false;  // wait for the whole payload
  std::string payload = buffer_.substr(eol + 1, n);
  buffer_.erase(0, eol + 1 + n);
  if (tag == 'K') {
    partial_ = std::move(payload);
  } else if (tag == 'S') {
    pending_.kind = JobRunOutcome::Kind::kSucceeded;
    pending_.result_json = std::move(payload);
  } else if (tag == 'V') {
    pending_.vtu = std::move(payload);
  } else {
    pending_.kind = JobRunOutcome::Kind::kFailed;
    pending_.error = std::move(payload);
  }
  return true;
}

}  // namespace fosls::service
