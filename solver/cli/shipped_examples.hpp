#pragma once
// The example cases of solver/examples, embedded in the program at build time
// (solver/examples/embed.cmake generates the definition of shipped_examples()).

#include <span>
#include <string_view>

namespace fosls {

/// One shipped case: its name (the file name without .json) and the JSON text.
struct ShippedExample {
  std::string_view name;
  std::string_view text;
};

/// All shipped 2D examples, sorted by name.
std::span<const ShippedExample> shipped_examples();
/// The shipped 3D examples (solver/examples/3d), sorted by name.
std::span<const ShippedExample> shipped_3d_examples();

}  // namespace fosls
