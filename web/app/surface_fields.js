// What the 3D surface can be coloured by: one value per boundary triangle, from the 3D VTU's
// arrays (docs/result-format.md, "VTU file", 3D). Vertex fields are averaged over the
// triangle's three vertices and kept per vertex too (the view interpolates them over a large
// triangle); NaN marks a triangle drawn in the neutral grey, which for the contact pressure is
// every triangle off the contact.

/** The mean over each surface triangle of the vertex values `perVertex(v)`. */
function triangleMeans(surface, perVertex) {
  const t = surface.triangles;
  const out = new Float64Array(t.length / 3);
  for (let f = 0; f < out.length; f++) out[f] = (perVertex(t[3 * f]) + perVertex(t[3 * f + 1]) + perVertex(t[3 * f + 2])) / 3;
  return out;
}

/** u of vertex v as [ux, uy, uz]. */
const displacementAt = (u) => (v) => [0, 1, 2].map((d) => u.values[v * u.components + d]);

/**
 * A field given per vertex (`perVertex(mesh, context)` → Float64Array, or null when the VTU
 * lacks it): per triangle the mean of its vertices, and the vertex values themselves, with
 * which the view shades a large triangle smoothly. `onlyContact`: NaN (grey) on the faces that
 * are not contact faces and on contact faces without pressure at any vertex, so that the
 * pressure disc stands out on a scale from 0 up.
 */
function fromVertices(perVertex, { onlyContact = false } = {}) {
  return (mesh, surface, context) => {
    const vertexValues = perVertex(mesh, context);
    if (!vertexValues) return null;
    const means = triangleMeans(surface, (v) => vertexValues[v]);
    const values = onlyContact ? means.map((m, f) => (context.contact[f] && m > 0 ? m : NaN)) : means;
    return { values, vertexValues };
  };
}

/** One value per vertex from u: f(u_v) for every vertex v, or null without u. */
const fromDisplacement = (f) => (mesh, context) => {
  const u = mesh.pointData.u;
  if (!u) return null;
  const at = displacementAt(u);
  return Float64Array.from({ length: u.values.length / u.components }, (_, v) => f(at(v), context));
};

/**
 * Fields of the 3D view: id → {label, unit (as mesh_fields.js's UNITS), signed (diverging map
 * when both signs occur), fromZero (the scale starts at 0, not at the smallest value),
 * compute(mesh, surface, {contact, normal}) → {values (one per triangle), vertexValues (one per
 * vertex, for vertex fields)}, or null when the VTU lacks the array (or, for u·n, the case a
 * contact plane)}.
 */
export const SURFACE_FIELDS = {
  contact_pressure: {
    label: 'contact pressure', unit: 'S', fromZero: true,
    compute: fromVertices((mesh) => mesh.pointData.contact_pressure?.values ?? null, { onlyContact: true }),
  },
  displacement: { label: 'displacement |u|', unit: 'L', compute: fromVertices(fromDisplacement((u) => Math.hypot(...u))) },
  u_normal: {
    label: 'displacement u·n (along the plane normal)', unit: 'L', signed: true,
    compute: fromVertices((mesh, context) => (context.normal
      ? fromDisplacement((u, { normal }) => u[0] * normal[0] + u[1] * normal[1] + u[2] * normal[2])(mesh, context) : null)),
  },
  von_mises: {
    label: 'von Mises stress (tetrahedron under the face)', unit: 'S',
    compute: (mesh, surface) => {
      const vm = mesh.cellData.von_mises?.values;
      return vm ? { values: Float64Array.from(surface.cells, (c) => vm[c]) } : null;
    },
  },
};

/**
 * {min, max} of what the view colours: the vertex values of the triangles that are not grey
 * (a smoothly shaded triangle shows its vertices' values), or the triangle values for a field
 * without vertex values. {0, 0} when nothing is coloured.
 */
export function shownRange(surface, { values, vertexValues }) {
  let min = Infinity, max = -Infinity;
  const t = surface.triangles;
  for (let f = 0; f < values.length; f++) {
    if (!Number.isFinite(values[f])) continue;
    const shown = vertexValues ? [vertexValues[t[3 * f]], vertexValues[t[3 * f + 1]], vertexValues[t[3 * f + 2]]] : [values[f]];
    for (const v of shown) {
      min = Math.min(min, v);
      max = Math.max(max, v);
    }
  }
  return min <= max ? { min, max } : { min: 0, max: 0 };
}
