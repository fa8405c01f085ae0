#pragma once
// The error every solver part throws when a matrix it needs positive definite is not: the
// weights of the functional make the discrete problem indefinite (README, "Decisions"). The
// case layer catches it by type and reports the weights.

#include <stdexcept>

namespace fosls {

/// A matrix that must be symmetric positive definite is not (a vertex patch, the contact
/// strip, a coarse level, the Galerkin chain, PDAS's factorisation).
class IndefiniteSystemError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace fosls
