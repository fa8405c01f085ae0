#pragma once
// What users look at: contact pressure per contact edge, gap, contact zone and resultant
// force, from a solution in the space's rotated, scaled coordinates (docs/result-format.md,
// docs/method.md §6).

#include <array>
#include <vector>

#include "assembly/fosls_assembler.hpp"

namespace fosls {

struct ContactEdgeResult {
  int edge = -1;
  double x = 0, y = 0;  ///< midpoint
  double s = 0;         ///< arc length along the contact boundary (chain order)
  double length = 0;    ///< of the edge
  double pressure = 0;  ///< p = −σ_nn (physical units), constant on the edge
  double gap = 0;       ///< remaining gap g − u·n, mean over the edge
  bool active = false;  ///< in contact: pressure > 0
  /// σ_nt (physical units) with t = (−n_y, n_x) for the body's outward normal n: the tangential
  /// traction of the obstacle on the body (0 on a frictionless edge).
  double shear = 0;
  double slip = 0;  ///< u·t − its reference value, mean over the edge: the slip of the step
  /// The edge's vertices in the order of the contact boundary (at s − length/2, s + length/2),
  /// and the slip of the step at each: what locates a stick zone's
  /// front within an edge (post/stick_front.hpp).
  std::array<int, 2> ends = {-1, -1};
  std::array<double, 2> end_slip = {0, 0};
  /// kOpen out of contact; in contact kStick where the step's slip is zero at both vertices
  /// (to kStickSlipTolerance of the largest), kSlip where it is not (always on a frictionless
  /// edge).
  enum class State { kOpen, kStick, kSlip } state = State::kOpen;
  /// |σ_nt| at the slip bound (to 1e-6 of the largest bound): what a slipping edge should be.
  bool at_bound = false;
};

/// A contact edge sticks when the slip of the step at both its vertices is at most this times
/// the largest over the contact edges in contact: the solvers hold a sticking U_t exactly at its
/// kink (docs/method.md §8.3), so the slips there are 0 in floating point, and this only keeps
/// a slip at the solver's tolerance from counting.
inline constexpr double kStickSlipTolerance = 1e-6;

const char* state_name(ContactEdgeResult::State state);

/// A vertex of the contact boundary.
struct ContactVertexResult {
  int vertex = -1;
  double gap = 0;       ///< remaining gap g − u·n along the constraint direction
  double pressure = 0;  ///< mean pressure of the adjacent contact edges
  double shear = 0;     ///< mean σ_nt of the adjacent contact edges
  int state = 0;        ///< the adjacent edges' largest state: 0 open, 1 stick, 2 slip
};

/// Where the body touches the obstacle: the edges with pressure > 0.
struct ContactZone {
  int edges = 0;       ///< edges in contact
  double length = 0;   ///< their total length
  double s_start = 0;  ///< arc length at the start of the first edge in contact
  double s_end = 0;    ///< arc length at the end of the last edge in contact
  double peak_pressure = 0;
  double peak_x = 0, peak_y = 0;  ///< midpoint of the edge with the peak pressure
};

struct ContactResult {
  std::vector<ContactEdgeResult> edges;       ///< ordered along the contact boundary
  std::vector<ContactVertexResult> vertices;  ///< the vertices of the contact edges
  double force_x = 0, force_y = 0;            ///< ∫_Γ_C σn ds: the obstacle's force on the body
  ContactZone zone() const;
  /// The edges in state kStick: `edges`, `length`, and the extent s_start..s_end.
  ContactZone stick_zone() const;
  /// The state from the slip against |σ_nt| against the bound (a consistency check of the
  /// discrete solution, docs/result-format.md): frictional edges in contact that slip with
  /// |σ_nt| below the bound, and that stick with |σ_nt| at it.
  int slipping_below_bound = 0, sticking_at_bound = 0;
  bool frictional = false;  ///< some contact edge has friction
};

ContactResult contact_output(const FoslsAssembler<2>& assembler, const AssembledProblem& problem,
                             const Vector& x_full);

}  // namespace fosls
