#pragma once
// The memory a job may use (--max-job-memory): sizes written as operators write them, and the
// default share of the machine.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "case/admission/memory_size.hpp"

namespace fosls::service {

// Sizes and the machine's memory are the case layer's (the CLI admits against them too).
using fosls::format_bytes;
using fosls::parse_byte_size;
using fosls::physical_memory;

/// The default --max-job-memory: three quarters of the physical memory shared by `workers`
/// solves at once, so that all of them together leave room for the API and the system.
std::size_t default_job_memory(int workers);

}  // namespace fosls::service
