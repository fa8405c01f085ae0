// One point of a case, in 2D and 3D (point_runner.hpp).

#include "case/run/point_runner.hpp"

#include <chrono>
#include <optional>

#include "case/result/contact_faces.hpp"
#include "case/result/level_loop_json.hpp"
#include "case/result/result_annotations.hpp"
#include "case/result/result_json.hpp"
#include "case/run/case_mesh.hpp"
#include "case/run/case_problem_data.hpp"
#include "case/run/indefinite_weights.hpp"
#include "case/run/level_loop_options.hpp"
#include "case/run/solve_observer.hpp"
#include "core/indefinite_system.hpp"
#include "core/peak_memory.hpp"
#include "mesh/length_scale.hpp"
#include "post/strain_measure.hpp"
#include "post/tet_vtu_writer.hpp"
#include "post/vtu_writer.hpp"

namespace fosls {

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// u at every vertex from a full (rotated) DOF vector (2D: the reference of a load step).
std::vector<Point> vertex_displacements(const FoslsSpace<2>& space, const Vector& x_full) {
  const Vector cartesian = space.rotation() * x_full;
  std::vector<Point> u(space.mesh().num_vertices());
  for (int v = 0; v < static_cast<int>(u.size()); ++v)
    u[v] = Point(cartesian[space.u_dof(v, 0)], cartesian[space.u_dof(v, 1)]);
  return u;
}

template <int dim>
ProblemSize problem_size(const LevelSolution<dim>& solution) {
  const SimplexMesh<dim>& finest = solution.disc->meshes().finest();
  ProblemSize size;
  size.levels = solution.disc->num_levels();
  size.dofs = solution.dofs;
  size.dofs_total = solution.dofs_total;
  size.vertices = finest.num_vertices();
  if constexpr (dim == 2)
    size.cells = finest.num_triangles();
  else
    size.cells = finest.num_tets();
  return size;
}

/// The VTU of the last solve.
template <int dim>
std::string vtu_text(const LevelSolution<dim>& s, const RunControl& control) {
  const Discretization<dim>& disc = *s.disc;
  const VtuEncoding encoding = control.vtu_ascii ? VtuEncoding::kAscii : VtuEncoding::kBinary;
  if constexpr (dim == 2)
    return write_vtu(disc.assembler(), disc.problem(), s.full, s.parts, s.contact, s.generation,
                     encoding);
  else
    return write_tet_vtu(disc.assembler(), disc.problem(), s.full, encoding);
}

/// Step 5: the result of the last solve, with the dimension's contact output and warnings.
template <int dim>
void write_result(RunOutput& out, const CaseSpec& used, const LevelSolution<dim>& solution,
                  const RunTiming& timing, const RunMemory& memory) {
  const Discretization<dim>& disc = *solution.disc;
  const auto result = [&](nlohmann::json contact) {
    nlohmann::json r = result_json(used, solution.report, std::move(contact), solution.parts,
                                   problem_size(solution), timing, memory);
    if (used.adaptivity) r["adaptivity"] = adaptivity_json(solution, *used.adaptivity);
    if (used.accuracy) r["accuracy"] = accuracy_json(solution, *used.accuracy);
    return r;
  };
  if constexpr (dim == 2) {
    out.result = result(contact_json(solution.contact));
    annotate_result(out.result, used, disc.meshes().finest(), solution.contact,
                    largest_strain(disc.assembler(), disc.problem(), solution.full));
    out.displacement = vertex_displacements(disc.finest_space(), solution.full);
  } else {
    const FaceContact contact = face_contact(used, disc, solution.full);
    out.result = result(face_contact_json(contact));
    annotate_result(out.result, used, disc.finest_space(), contact);
  }
}

}  // namespace

template <int dim>
RunOutput run_point(const CaseSpec& spec, const RunControl& control, const CaseLimits& limits) {
  const auto t0 = Clock::now();
  // The limit counts the whole run: a user sets it for the answer's latency, not the loop's.
  const Deadline deadline = run_deadline(t0, spec.solver.time_limit_s);
  std::optional<SimplexMesh<dim>> coarse =
      checked_coarse_mesh<dim>(spec, MeshingControl{control.mesher, control.cancel}, limits);
  if (!coarse) {
    RunOutput cancelled;
    cancelled.cancelled = true;
    return cancelled;
  }
  CaseSpec used = spec;  // the case with the weights as used
  used.weights.length_scale = length_scale(*coarse);
  const SimplexMesh<dim> coarse_mesh = *coarse;  // small; for the message of indefinite weights
  SimplexHierarchy<dim> meshes = build_uniform_hierarchy(std::move(*coarse), spec.mesh.refinements);
  deadline.check("refining the mesh");  // refinement is a small part of the set-up
  check_finest_mesh<dim>(spec, meshes.finest());
  ProblemData<dim> data = problem_data<dim>(used, meshes.finest());
  if constexpr (dim == 2)
    if (control.reference) data.reference_displacement = *control.reference;
  const auto t_mesh = Clock::now();
  RunMemory memory;
  memory.mesh_mib = peak_rss_mib();
  choose_contact_weight<dim>(used, meshes, data);
  LevelSolution<dim> solution;
  try {
    solution = solve_levels<dim>(std::move(meshes), data, level_loop_options(spec),
                                 solve_observer(control, deadline), control.start);
  } catch (const IndefiniteSystemError& e) {
    // Positive definiteness failing inside a solver is the user's weights, not a crash.
    throw indefinite_weights<dim>(used, coarse_mesh, data, e.what());
  }
  memory.assembly_mib = solution.assembly_mib;
  memory.hierarchy_mib = solution.hierarchy_mib;
  const auto t_solve = Clock::now();

  RunOutput out;
  out.cancelled = solution.report.cancelled;
  if (control.want_vtu) out.vtu = vtu_text<dim>(solution, control);
  RunTiming timing;
  timing.mesh_s = seconds(t0, t_mesh);
  timing.assembly_s = solution.assembly_s;
  // Estimation and refinement between the solves of an adaptive run count as solving.
  timing.solve_s = seconds(t_mesh, t_solve) - solution.assembly_s;
  timing.total_s = seconds(t0, Clock::now());
  memory.peak_mib = peak_rss_mib();
  write_result<dim>(out, used, solution, timing, memory);
  out.solution = std::move(solution.x);
  return out;
}

template RunOutput run_point<2>(const CaseSpec&, const RunControl&, const CaseLimits&);
template RunOutput run_point<3>(const CaseSpec&, const RunControl&, const CaseLimits&);

}  // namespace fosls
