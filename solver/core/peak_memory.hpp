#pragma once
// The peak resident set of this process so far, for the memory that the stages of a solve
// report (docs/result-format.md, `memory`).

namespace fosls {

/// Peak resident set size of the calling process since it started, in MiB (monotone: a stage
/// that needs less than an earlier one does not lower it).
double peak_rss_mib();

}  // namespace fosls
