// What the 3D surface can be coloured by: one value per boundary triangle, from the 3D VTU's
// arrays (docs/result-format.md, "VTU file", 3D). Vertex fields are averaged over the
// triangle's three vertices (the view shades each triangle flat); NaN marks a triangle drawn
// in the neutral grey, which for the contact pressure is every triangle off the contact.

/** The mean over each surface triangle of the vertex values `perVertex(v)`. */
function triangleMeans(surface, perVertex) {
  const t = surface.triangles;
  const out = new Float64Array(t.length / 3);
  for (let f = 0; f < out.length; f++) out[f] = (perVertex(t[3 * f]) + perVertex(t[3 * f + 1]) + perVertex(t[3 * f + 2])) / 3;
  return out;
}

/** u of vertex v as [ux, uy, uz] (zeros without u). */
const displacement = (mesh) => {
  const u = mesh.pointData.u;
  return (v) => (u ? [0, 1, 2].map((d) => u.values[v * u.components + d]) : [0, 0, 0]);
};

/**
 * The contact pressure of the contact faces; NaN (grey) on the rest of the surface and on a
 * contact face without pressure at any vertex, so that the pressure disc stands out on the
 * face's colour scale from 0 up.
 */
function contactPressure(mesh, surface, { contact }) {
  const p = mesh.pointData.contact_pressure?.values;
  if (!p) return null;
  const means = triangleMeans(surface, (v) => p[v]);
  return means.map((value, f) => (contact[f] && value > 0 ? value : NaN));
}

/**
 * Fields of the 3D view: id → {label, unit (as mesh_fields.js's UNITS), signed (diverging map
 * when both signs occur), fromZero (the scale starts at 0, not at the smallest value),
 * compute(mesh, surface, {contact, normal}) → per-triangle values, or null when the VTU lacks
 * the array}.
 */
export const SURFACE_FIELDS = {
  contact_pressure: { label: 'contact pressure', unit: 'S', fromZero: true, compute: contactPressure },
  displacement: {
    label: 'displacement |u|',
    unit: 'L',
    compute: (mesh, surface) => mesh.pointData.u && triangleMeans(surface, (v) => Math.hypot(...displacement(mesh)(v))),
  },
  u_normal: {
    label: 'displacement u·n (along the plane normal)',
    unit: 'L',
    signed: true,
    compute: (mesh, surface, { normal }) => {
      if (!mesh.pointData.u || !normal) return null;
      const u = displacement(mesh);
      return triangleMeans(surface, (v) => u(v).reduce((sum, c, d) => sum + c * normal[d], 0));
    },
  },
  von_mises: {
    label: 'von Mises stress (tetrahedron under the face)',
    unit: 'S',
    compute: (mesh, surface) => {
      const vm = mesh.cellData.von_mises?.values;
      return vm ? Float64Array.from(surface.cells, (c) => vm[c]) : null;
    },
  },
};
