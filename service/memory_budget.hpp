#pragma once
// The memory a job may use (--max-job-memory): sizes written as operators write them, and the
// default share of the machine.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace fosls::service {

/// "512M", "2G", "1.5G", "300000K", "1048576" (bytes; K, M, G, T are powers of 1024, an
/// optional trailing "B" or "iB" is accepted). Nothing for anything else or for zero.
std::optional<std::size_t> parse_byte_size(std::string_view text);

/// "512 MiB", "2.5 GiB": a byte count for messages.
std::string format_bytes(std::size_t bytes);

/// The machine's physical memory (sysconf), or 4 GiB when it cannot be read.
std::size_t physical_memory();

/// The default --max-job-memory: three quarters of the physical memory shared by `workers`
/// solves at once, so that all of them together leave room for the API and the system.
std::size_t default_job_memory(int workers);

}  // namespace fosls::service
