#include "solvers/stopping_criterion.hpp"

namespace fosls {

const char* converged_by_name(ConvergedBy c) {
  switch (c) {
    case ConvergedBy::kKktResidual:
      return "kkt_residual";
    case ConvergedBy::kAlgebraicError:
      return "algebraic_error";
    case ConvergedBy::kRoundingLevel:
      return "rounding_level";
    case ConvergedBy::kNone:
      break;
  }
  return "none";
}

}  // namespace fosls
