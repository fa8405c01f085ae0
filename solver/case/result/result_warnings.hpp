#pragma once
// Warnings about what a result means, each with a machine-readable code (docs/result-format.md,
// "Warnings"): a converged answer that is physically empty or questionable (no contact, a body
// that starts inside the obstacle, a tangential load that a frictionless contact cannot hold,
// implausible units) is never reported without saying so, and a contact zone resolved by a
// few edges says how well its width is known.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "case/format/case_spec.hpp"
#include "mesh/mesh.hpp"
#include "post/contact_output.hpp"

namespace fosls {

struct ResultWarning {
  std::string code;     ///< machine-readable, stable: "no_contact", "initial_penetration", ...
  std::string message;  ///< the sentence: what happened, what it means, what to do
  /// The answer may be physically empty or wrong although it converged: the result's
  /// `review_required` becomes true and `fosls-contact solve` exits with code 4.
  bool review = false;
};

/// A number for a sentence: `digits` significant digits (0.005, 1.23e+05).
std::string sentence_number(double v, int digits = 4);

/// An overlap with the obstacle below this fraction of the body's size counts as touching.
inline constexpr double kTouchingOverlap = 1e-6;

/// Every code a ResultWarning may have, for the result's schema.
std::vector<std::string> warning_codes();

/// Fewer contact edges than this in the contact zone get `contact_zone_underresolved`.
inline constexpr int kResolvedZoneEdges = 10;

/// The mean length of the edges at the ends of the contact zone (an edge in contact next to one
/// that is not, or to the end of the contact boundary): the contact front lies within about
/// one such edge, so the zone's width is resolved to about ± this at each end. 0 without
/// contact.
double zone_end_edge_length(const ContactResult& contact);

/// Appends each warning to result["warnings"] (its sentence, as before), to
/// result["warning_details"] ({code, message, review}) and ORs result["review_required"].
/// Creates the three fields when absent.
void add_warnings(nlohmann::json& result, const std::vector<ResultWarning>& warnings);

/// Whether a contact condition transmits no shear. Hook for friction: a condition is
/// frictionless while it has no friction (or a coefficient of 0); until the case format has
/// friction, every contact condition is.
bool is_frictionless(const BoundaryCondition& condition);

/// From the case alone: a displacement along a frictionless plane contact that only the loaded
/// group itself holds (the body slides on the obstacle), or nothing. Not a review warning: the
/// answer is right for frictionless contact, but the tangential part of the load only slides
/// the body, which a user who expects the contact to hold it must be told.
std::optional<ResultWarning> tangential_load_warning(const CaseSpec& spec);

/// Equivalent strains above this on 1 % of the body get `large_strain`: linear elasticity's
/// small-deformation assumption no longer holds. (The shipped signorini_square, pressed by 5 %
/// of its height, reaches 5.8 % on a few triangles and stays below.)
inline constexpr double kLargeStrain = 0.10;

/// A solution whose equivalent strain exceeds kLargeStrain on 1 % of its area, or nothing.
std::optional<ResultWarning> large_strain_warning(double strain, double largest,
                                                  const Point& where);

/// After the solve, from the finest mesh and the contact output: no contact, a plane obstacle
/// whose normal faces away from the contact boundary, an initial overlap with the obstacle
/// (before any obstacle displacement), a contact zone of fewer than kResolvedZoneEdges edges.
std::vector<ResultWarning> contact_warnings(const CaseSpec& spec, const Mesh& finest,
                                            const ContactResult& contact);

}  // namespace fosls
