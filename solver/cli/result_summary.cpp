#include "cli/result_summary.hpp"

#include <cstdio>
#include <string>

#include "cli/exit_codes.hpp"

namespace fosls {

namespace {

using nlohmann::json;

std::string g(const json& v, int digits = 4) {
  if (!v.is_number()) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.*g", digits, v.get<double>());
  return text;
}

/// `text` left-aligned in a table column of `width` characters (one space after it at least).
std::string column(const std::string& text, std::size_t width) {
  return text + std::string(text.size() < width ? width - text.size() : 1, ' ');
}

/// "14", or "200  NOT converged (max_iterations)": a sweep point's or load step's solve.
std::string iterations_text(const json& solve) {
  return std::to_string(solve["iterations"].get<int>()) +
         (solve["converged"].get<bool>()
              ? ""
              : "  NOT converged (" + solve["stop_reason"].get<std::string>() + ")");
}

/// " mm" after a length when the case declared units, else "".
std::string unit(const json& r, const char* which) {
  const json& u = r.value("units", json::object());
  const json& name = u.value(which, json());
  return name.is_string() ? " " + name.get<std::string>() : "";
}

std::string thickness(const json& r) {
  const std::string force = unit(r, "force_per_thickness");
  if (force.empty())
    return "per unit thickness (stress unit x length unit of the case; no units declared)";
  return force.substr(1) + " (per" + unit(r, "length") + " of thickness)";
}

void print_contact(std::ostream& out, const json& r) {
  const auto& c = r["contact"];
  const auto& z = c["zone"];
  const std::string L = unit(r, "length"), S = unit(r, "stress");
  out << "  force on the body   F = (" << g(c["force"][0]) << ", " << g(c["force"][1]) << ") "
      << thickness(r) << ", the obstacle's force on the body\n";
  if (c["x"].empty()) {
    out << "  contact             none: the case has no contact group\n";
  } else if (z["edges"] == 0) {
    out << "  contact zone        NO edge in contact (" << c["x"].size()
        << " contact edges): see the warning\n";
  } else {
    out << "  peak pressure       p_max = " << g(z["peak_pressure"]) << S << " at ("
        << g(z["peak_location"][0]) << ", " << g(z["peak_location"][1]) << ")" << L << "\n"
        << "  contact zone        " << z["edges"].get<int>() << " of " << c["x"].size()
        << " contact edges, width " << g(z["width"]) << L
        << " (loaded edges from s = " << g(z["s_start"]) << " to " << g(z["s_end"]) << ", edges of "
        << g(z["end_edge_length"], 3) << L << " at its ends)\n";
  }
}

/// Where the body sticks and slides, and how the Coulomb bounds settled.
void print_friction(std::ostream& out, const json& r) {
  const auto& c = r["contact"];
  const auto& stick = c["stick_zone"];
  const std::string L = unit(r, "length");
  int slip = 0;
  for (const auto& state : c["state"]) slip += state == "slip";
  out << "  friction            ";
  if (stick["edges"] == 0)
    out << "no edge sticks";
  else
    out << stick["edges"].get<int>() << " edges stick, length " << g(stick["length"]) << L
        << " (s = " << g(stick["s_start"]) << " to " << g(stick["s_end"]) << ")";
  out << ", " << slip << " slip";
  const auto& f = r["friction"];
  if (f["updates"].get<int>() > 0)
    out << "; Coulomb bounds updated " << f["updates"].get<int>() << " times, last change "
        << g(f["last_change"], 2);
  out << "\n";
}

/// Why an adaptive run stopped, and what its target means.
void print_adaptivity(std::ostream& out, const json& a) {
  const auto& steps = a["steps"];
  if (steps.empty()) return;
  out << "  adaptive run        " << steps.size() << " solves, " << steps.front()["dofs"] << " to "
      << steps.back()["dofs"] << " unknowns; "
      << a.value("stop_message", "stopped: " + a["stop_reason"].get<std::string>()) << '\n';
}

/// The levels of a run to a requested force accuracy, and whether it was reached.
void print_accuracy(std::ostream& out, const json& a) {
  const auto& steps = a["steps"];
  if (steps.empty()) return;
  out << "  force accuracy      " << (a["reached"].get<bool>() ? "reached" : "NOT reached")
      << " after " << steps.size() << " levels (" << steps.front()["dofs"] << " to "
      << steps.back()["dofs"] << " unknowns): " << a["stop_message"].get<std::string>() << '\n';
}

/// "F_x            F_y            " (and F_z in 3D): the force columns' header.
std::string force_header(int dim) {
  std::string h;
  for (int i = 0; i < dim; ++i) h += column(std::string("F_") + "xyz"[i], 15);
  return h;
}

void print_force(std::ostream& out, const json& force) {
  for (const json& v : force) out << column(g(v), 15);
}

/// One line per point of a sweep: its force, peak pressure, the zone's width (2D) or radius
/// (3D), and iterations.
void print_sweep(std::ostream& out, const json& sweep, int dim) {
  out << "  sweep of " << sweep["pointer"].get<std::string>() << ":\n"
      << "    value          " << force_header(dim) << "p_max          "
      << (dim == 3 ? "radius         " : "width          ") << "iterations\n";
  for (const auto& p : sweep["points"]) {
    out << "    " << column(g(p["value"]), 15);
    print_force(out, p["force"]);
    for (const json& v : {p["peak_pressure"], p[dim == 3 ? "contact_radius" : "contact_width"]})
      out << column(g(v), 15);
    out << iterations_text(p);
    for (const auto& code : p.value("warning_codes", json::array()))
      out << "  [" << code.get<std::string>() << "]";
    out << '\n';
  }
}

/// One line per load step: its force, stick zone (2D) and iterations (the summary above is the
/// last step's).
void print_load_steps(std::ostream& out, const json& load_steps, int dim) {
  out << "  load steps (the lines above are the last step's):\n"
      << "    step  " << force_header(dim) << (dim == 3 ? "" : "stick length   ") << "iterations\n";
  for (const auto& s : load_steps["steps"]) {
    out << "    " << column(std::to_string(s["step"].get<int>()), 6);
    const json& contact = s["contact"];
    print_force(out, contact["force"]);
    if (dim == 2)
      out << column(g(contact.contains("stick_zone") ? contact["stick_zone"]["length"] : json()),
                    15);
    out << iterations_text(s) << '\n';
  }
}

/// What the outcome line adds when the discretisation rule or the rounding level stopped the
/// solve.
std::string stopped_by(const json& r) {
  if (!r.contains("stopping")) return "";
  if (r["stopping"]["converged_by"] == "rounding_level")
    return "; stopped where the residual stalled at its rounding level (see the warning)";
  if (r["stopping"]["converged_by"] != "algebraic_error") return "";
  return "; stopped at the discretisation error: algebraic error " +
         g(r["stopping"]["algebraic_error"], 2) + " <= " + g(r["stopping"]["fraction"], 2) +
         " x J^1/2, J^1/2 = " + g(r["stopping"]["estimator"], 2);
}

void print_review(std::ostream& out, const json& r) {
  if (r.value("converged", false) && r.value("review_required", false))
    out << "REVIEW: converged, but the warnings above say the answer may be physically empty or "
           "wrong (exit code 4)\n";
}

}  // namespace

void print_result_summary_3d(std::ostream& out, const json& r) {
  const bool converged = r.value("converged", false);
  out << (converged ? "converged in " : "NOT converged: stopped after ")
      << r["iterations"].get<int>() << " iterations (3D, " << r["levels"].get<int>() << " levels, "
      << r["tetrahedra"].get<long long>() << " tetrahedra, " << r["dofs"].get<long long>()
      << " unknowns, " << g(r["timing"]["total_s"], 3) << " s; relative KKT residual "
      << g(r["relative_kkt_residual"], 2) << ")\n";
  const auto& c = r["contact"];
  if (c["faces"].get<int>() > 0) {
    out << "  contact force       F = [" << g(c["force"][0], 6) << ", " << g(c["force"][1], 6)
        << ", " << g(c["force"][2], 6) << "], peak pressure " << g(c["max_pressure"], 4)
        << ", area in contact " << g(c["area"], 4) << " (" << c["faces_in_contact"].get<int>()
        << " faces)\n";
    const auto& z = c["zone"];
    const int mirrored = z.value("symmetry_planes", 0);
    if (c["faces_in_contact"].get<int>() > 0)
      out << "  contact zone        radius " << g(z["radius"], 4)
          << (mirrored > 0 ? " (the whole zone, mirrored across " + std::to_string(mirrored) +
                                 " symmetry plane" + (mirrored > 1 ? "s)" : ")")
                           : std::string())
          << ", its front located within the faces\n";
  }
  out << "  error estimator     J^1/2 = " << g(r["functional"]["estimator"], 3)
      << " (scaled units)\n";
  if (r.contains("sweep")) print_sweep(out, r["sweep"], 3);
  if (r.contains("load_steps")) print_load_steps(out, r["load_steps"], 3);
  if (r.contains("adaptivity")) print_adaptivity(out, r["adaptivity"]);
  if (r.contains("accuracy")) print_accuracy(out, r["accuracy"]);
  print_review(out, r);
}

void print_result_summary(std::ostream& out, const json& r) {
  const bool converged = r.value("converged", false);
  const std::string what = converged ? "converged in " : "NOT converged: stopped after ";
  out << what << r["iterations"].get<int>() << " iterations (" << r["levels"].get<int>()
      << " levels, " << r["dofs"].get<long long>() << " unknowns"
      << (r["mesh"].value("order", 1) == 2 ? " of order 2" : "") << ", "
      << g(r["timing"]["total_s"], 3) << " s; relative KKT residual "
      << g(r["relative_kkt_residual"], 2) << ", tolerance " << g(r["tolerance"], 2) << stopped_by(r)
      << ")\n";
  print_contact(out, r);
  out << "  error estimator     J^1/2 = " << g(r["functional"]["estimator"], 3)
      << " (scaled units)\n";
  if (r.contains("friction")) print_friction(out, r);
  if (r.contains("adaptivity")) print_adaptivity(out, r["adaptivity"]);
  if (r.contains("accuracy")) print_accuracy(out, r["accuracy"]);
  if (r.contains("sweep")) print_sweep(out, r["sweep"], 2);
  if (r.contains("load_steps")) print_load_steps(out, r["load_steps"], 2);
  print_review(out, r);
}

int result_exit_code(const json& r) {
  if (!r.value("converged", false)) return kExitNotConverged;
  return r.value("review_required", false) ? kExitReviewRequired : kExitOk;
}

}  // namespace fosls
