// A 3D case, step by step: the coarse mesh from its source, the hierarchy of uniform
// refinements, the boundary groups checked against the mesh, the problem data, the solve, the
// result.

#include "case/case3d_runner.hpp"

#include <chrono>

#include "assembly/discretization.hpp"
#include "case/case3d_admission.hpp"
#include "case/case3d_result.hpp"
#include "case/case_error.hpp"
#include "case/early_group_check.hpp"
#include "core/non_finite.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/tet_msh_reader.hpp"
#include "mesh/tet_refinement.hpp"
#include "post/tet_vtu_writer.hpp"
#include "solvers/solve_loop.hpp"

namespace fosls {

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Step 1: the coarse mesh from the case's source; its problems at the source's pointer.
TetMesh coarse_mesh(const Mesh3dSpec& m) {
  try {
    switch (m.kind) {
      case Mesh3dSpec::Kind::kBox:
        return make_box(m.cells, m.lengths);
      case Mesh3dSpec::Kind::kHalfBall:
        return make_half_ball(m.ball);
      case Mesh3dSpec::Kind::kMsh:
        return tet_mesh_from_msh(m.msh_text);
      case Mesh3dSpec::Kind::kGeoFile:
        return tet_mesh_from_geo_file(m.path, m.size);
    }
  } catch (const MeshError& e) {
    std::vector<CaseError> errors;
    for (const auto& p : e.problems())
      errors.push_back(
          {p.field == "/size" ? std::string("/mesh/size") : mesh3d_source_pointer(m), p.detail});
    throw CaseException(std::move(errors));
  } catch (const std::invalid_argument& e) {  // the half ball's grading folds a tetrahedron
    throw CaseException(mesh3d_source_pointer(m),
                        std::string("these parameters give no valid mesh (") + e.what() +
                            "); use a smaller grading or fewer cells");
  }
  throw CaseException(mesh3d_source_pointer(m), "unknown mesh source");
}

/// Refuses refinements whose finest level would exceed the limits (case3d_admission.hpp).
void check_size(double coarse_unknowns, const Case3dSpec& spec, const CaseLimits& limits) {
  std::vector<CaseError> errors =
      check_3d_size(finest_3d_unknowns(coarse_unknowns, spec.mesh), spec, limits);
  if (!errors.empty()) throw CaseException(std::move(errors));
}

/// The obstacle where its displacement puts it, in the assembly layer's terms.
RigidObstacle<3> rigid_obstacle(const Obstacle3d& o) {
  RigidObstacle<3> r;
  switch (o.kind) {
    case Obstacle3d::Kind::kPlane:
      r.kind = RigidObstacle<3>::Kind::kPlane;
      r.point = o.point + o.displacement, r.normal = o.normal;
      break;
    case Obstacle3d::Kind::kSphere:
      r.kind = RigidObstacle<3>::Kind::kBall;
      r.center = o.center + o.displacement, r.radius = o.radius;
      break;
    case Obstacle3d::Kind::kGap:
      r.kind = RigidObstacle<3>::Kind::kGap;
      break;
  }
  return r;
}

/// Step 3: every named group is one of the mesh's, and every contact face faces its plane.
void check_groups(const Case3dSpec& spec, const TetMesh& mesh) {
  std::vector<CaseError> errors = check_3d_groups(spec, mesh);
  if (!errors.empty()) throw CaseException(std::move(errors));
}

/// Step 4: the problem data on the mesh's groups.
ProblemData<3> problem_data(const Case3dSpec& spec, const TetMesh& mesh) {
  ProblemData<3> d;
  d.material = {.mu = spec.material.mu, .lambda = spec.material.lambda};
  for (int i = 0; i < 3; ++i)
    if (spec.body_force[i] != 0.0)
      d.body_force[i] = [v = spec.body_force[i]](double, double, double) { return v; };
  d.groups.resize(mesh.group_names().size());
  for (const auto& [name, bc] : spec.boundary) {
    GroupData<3>& group = d.groups[tet_group_index(mesh, name)];
    if (bc.type == Condition3d::Type::kContact) {
      group.role = GroupRole::kContact;
      group.contact.obstacle = rigid_obstacle(bc.obstacle);
      if (bc.obstacle.kind == Obstacle3d::Kind::kGap) group.contact.gap = bc.obstacle.gap;
      continue;
    }
    group.role =
        bc.type == Condition3d::Type::kDirichlet ? GroupRole::kDirichlet : GroupRole::kNeumann;
    group.normal_pressure = bc.type == Condition3d::Type::kPressure;
    group.prescribed = bc.prescribed;
    group.values = bc.values;
  }
  return d;
}

}  // namespace

Run3dOutput run_case_3d(const Case3dSpec& spec, const Run3dControl& control,
                        const CaseLimits& limits) {
  const auto t0 = Clock::now();
  // Before anything is built: a builtin of many cells or a large msh is refused at once.
  if (const auto unknowns = builtin_3d_unknowns(spec.mesh)) check_size(*unknowns, spec, limits);
  TetMesh coarse = coarse_mesh(spec.mesh);
  check_size(tet_mesh_unknowns(coarse), spec, limits);
  TetHierarchy meshes = build_tet_hierarchy(std::move(coarse), spec.mesh.refinements);
  check_groups(spec, meshes.finest());
  const double mesh_s = seconds_since(t0);

  const auto t1 = Clock::now();
  ProblemData<3> data = problem_data(spec, meshes.finest());
  const Discretization<3> disc(std::move(meshes), std::move(data));
  const double assembly_s = seconds_since(t1);

  const auto t2 = Clock::now();
  const BoxQp& qp = disc.problem().qp;
  Vector x = Vector::Zero(qp.size());
  SolverObserver observer;
  observer.on_iteration = control.on_iteration;
  if (control.cancel)
    observer.cancelled = [&control] { return control.cancel->load(std::memory_order_relaxed); };
  const bool multilevel = spec.solver.method == SolverMethod::kMmg;
  SolverReport report;
  try {
    report = solve_box_qp(qp, multilevel ? disc.build_level_hierarchy() : LevelHierarchy{},
                          spec.solver, observer, x);
  } catch (const NonFiniteError& e) {
    throw CaseException({non_finite_problem(e.what())});
  }
  const double solve_s = seconds_since(t2);

  Run3dOutput out;
  if (report.cancelled) {
    out.cancelled = true;
    return out;
  }
  out.result = case3d_result(spec, disc, x, report);
  out.result["timing"] = {{"mesh_s", mesh_s},
                          {"assembly_s", assembly_s},
                          {"solve_s", solve_s},
                          {"total_s", seconds_since(t0)}};
  if (control.want_vtu) {
    const FoslsAssembler<3>& a = disc.assembler();
    out.vtu = write_tet_vtu(a, disc.problem(), a.full_vector(disc.problem(), x),
                            control.vtu_ascii ? VtuEncoding::kAscii : VtuEncoding::kBinary);
  }
  return out;
}

}  // namespace fosls
