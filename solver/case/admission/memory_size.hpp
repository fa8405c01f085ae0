#pragma once
// Memory sizes as people write and read them, and the machine's memory: for the budgets a solve
// is admitted against (the service's --max-job-memory, the CLI's --max-memory).

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace fosls {

/// "512M", "2G", "1.5G", "300000K", "1048576" (bytes; K, M, G, T are powers of 1024, an
/// optional trailing "B" or "iB" is accepted). Nothing for anything else or for zero.
std::optional<std::size_t> parse_byte_size(std::string_view text);

/// "512 MiB", "2.5 GiB": a byte count for messages.
std::string format_bytes(double bytes);

/// The machine's physical memory (sysconf), or 4 GiB when it cannot be read.
std::size_t physical_memory();

}  // namespace fosls
