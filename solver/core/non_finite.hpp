#pragma once
// The error a solve throws when its numbers stop being numbers: a residual, an energy or the
// assembled data that are infinite or NaN. Such a run has no answer — "converged in 1 iteration,
// relative KKT residual nan" was once reported as a success — so it is a failure with its cause;
// the case layer reports it against the case's data (a displacement, traction or pressure beyond
// what double precision can square).

#include <stdexcept>

namespace fosls {

class NonFiniteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace fosls
