#pragma once
// What the result says about itself beyond the numbers of the solve: the warnings about what the
// answer means (result_warnings.hpp), the units the case declared, and the shape of the contact
// boundary (for comparisons with analytic solutions such as Hertz).

#include <nlohmann/json.hpp>

#include "case/format/case_spec.hpp"
#include "case/result/contact_faces.hpp"
#include "mesh/mesh.hpp"
#include "post/contact_output.hpp"
#include "post/strain_measure.hpp"

namespace fosls {

/// Adds to a result from result_json(): the physical warnings (warnings, warning_details,
/// review_required), `units`, and `contact.shape`. `strain` is the solution's largest strain.
void annotate_result(nlohmann::json& result, const CaseSpec& spec, const Mesh& finest,
                     const ContactResult& contact, const StrainPeak& strain);

/// The same for a body whose contact boundary is a set of faces (3D).
void annotate_result(nlohmann::json& result, const CaseSpec& spec, const FoslsSpace<3>& finest,
                     const FaceContact& contact);

}  // namespace fosls
