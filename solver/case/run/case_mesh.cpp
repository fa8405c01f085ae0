// A case's coarse mesh and its checks, in 2D and 3D (case_mesh.hpp).

#include "case/run/case_mesh.hpp"

#include <cmath>
#include <utility>

#include "case/admission/case_admission.hpp"
#include "case/run/mesh_factory.hpp"
#include "case/run/volume_mesh_checks.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/tet_msh_reader.hpp"

namespace fosls {

namespace {

/// Problems that need the 2D coarse mesh: unknown groups, no Dirichlet group, size limits.
std::vector<CaseError> check_against_mesh(const CaseSpec& spec, const Mesh& mesh,
                                          const CaseLimits& limits) {
  const auto unknowns = [&mesh](int refinements, int order) {
    return unknowns_after_refinement(mesh.num_triangles(), mesh.num_edges(), mesh.num_vertices(),
                                     refinements, order);
  };
  return check_against_groups(
      spec, mesh.group_names(),
      {unknowns(spec.mesh.refinements, spec.mesh.order), unknowns(0, 1), true, spec.mesh.order, 2},
      limits);
}

/// The 3D coarse mesh from the case's source; its problems at the source's pointer.
TetMesh volume_mesh(const MeshSpec& m) {
  try {
    switch (m.kind) {
      case MeshSpec::Kind::kBuiltin: {
        auto mesh = builtin_3d_mesh(m);
        if (auto* errors = std::get_if<std::vector<CaseError>>(&mesh))
          throw CaseException(std::move(*errors));
        return std::move(std::get<TetMesh>(mesh));
      }
      case MeshSpec::Kind::kMsh:
        return tet_mesh_from_msh(m.msh_text);
      case MeshSpec::Kind::kGeoFile:
        return tet_mesh_from_geo_file(m.geo_path, m.size);
      case MeshSpec::Kind::kGeometry:
        break;  // refused by the reader in 3D
    }
  } catch (const MeshError& e) {
    std::vector<CaseError> errors;
    for (const auto& p : e.problems())
      errors.push_back(
          {p.field == "/size" ? std::string("/mesh/size") : mesh_source_pointer(m), p.detail});
    throw CaseException(std::move(errors));
  }
  throw CaseException(mesh_source_pointer(m), "unknown mesh source");
}

/// Refuses refinements whose finest 3D level would exceed the limits (case_admission.hpp).
void check_volume_size(double coarse_unknowns, bool exact, const CaseSpec& spec,
                       const CaseLimits& limits) {
  const ProblemCount count{std::llround(finest_3d_unknowns(coarse_unknowns, spec.mesh.refinements)),
                           std::llround(coarse_unknowns), exact, spec.mesh.order, 3};
  std::vector<CaseError> errors = check_size(spec, count, limits);
  if (!errors.empty()) throw CaseException(std::move(errors));
}

/// The 3D coarse mesh and its size: a builtin of many cells is refused before it is built.
TetMesh checked_volume_mesh(const CaseSpec& spec, const CaseLimits& limits) {
  if (const auto unknowns = builtin_3d_unknowns(spec.mesh))
    check_volume_size(*unknowns, false, spec, limits);
  TetMesh coarse = volume_mesh(spec.mesh);
  check_volume_size(tet_mesh_unknowns(coarse), true, spec, limits);
  return coarse;
}

}  // namespace

template <int dim>
std::optional<SimplexMesh<dim>> checked_coarse_mesh(const CaseSpec& spec,
                                                    const MeshingControl& meshing,
                                                    const CaseLimits& limits) {
  if constexpr (dim == 3) {
    return checked_volume_mesh(spec, limits);
  } else {
    Mesh coarse;
    try {
      coarse = build_coarse_mesh(spec.mesh, meshing);
    } catch (const MeshingCancelled&) {
      return std::nullopt;
    }
    if (auto errors = check_against_mesh(spec, coarse, limits); !errors.empty())
      throw CaseException(std::move(errors));
    return coarse;
  }
}

template <int dim>
void check_finest_mesh(const CaseSpec& spec, const SimplexMesh<dim>& finest) {
  if constexpr (dim == 3) {
    std::vector<CaseError> errors = check_3d_groups(spec, finest);
    if (!errors.empty()) throw CaseException(std::move(errors));
  }
}

std::vector<CaseError> check_case_mesh(const CaseSpec& spec, const MeshingControl& meshing,
                                       const CaseLimits& limits) {
  try {
    if (spec.dimension == 3) return check_3d_groups(spec, checked_volume_mesh(spec, limits));
    return check_against_mesh(spec, build_coarse_mesh(spec.mesh, meshing), limits);
  } catch (const CaseException& e) {
    return e.errors();
  }
}

template std::optional<Mesh> checked_coarse_mesh<2>(const CaseSpec&, const MeshingControl&,
                                                    const CaseLimits&);
template std::optional<TetMesh> checked_coarse_mesh<3>(const CaseSpec&, const MeshingControl&,
                                                       const CaseLimits&);
template void check_finest_mesh<2>(const CaseSpec&, const Mesh&);
template void check_finest_mesh<3>(const CaseSpec&, const TetMesh&);

}  // namespace fosls
