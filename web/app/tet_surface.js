// The boundary surface of a tetrahedral mesh (a 3D VTU read by vtu.js): the faces that belong
// to one tetrahedron only, each turned so that its normal (b − a) × (c − a) points out of the
// body, and which of them are contact faces. The 3D view draws this surface; the pressure
// line samples its contact faces.

// The four faces of a tetrahedron (v0 v1 v2 v3) by local vertex, and the vertex opposite each.
const FACES = [[1, 2, 3, 0], [0, 2, 3, 1], [0, 1, 3, 2], [0, 1, 2, 3]];

/**
 * A key per vertex triple, the same for every order of the three. Numeric while n³ is exact in
 * a double (meshes below 208 063 vertices), a string beyond.
 */
function faceKey(nVertices) {
  const exact = nVertices ** 3 < Number.MAX_SAFE_INTEGER;
  return (a, b, c) => {
    const lo = Math.min(a, b, c);
    const hi = Math.max(a, b, c);
    const mid = a + b + c - lo - hi;
    return exact ? (lo * nVertices + mid) * nVertices + hi : `${lo},${mid},${hi}`;
  };
}

/** (b − a) × (c − a) for vertices a, b, c of `p` (x, y, z triples). */
export function normalOf(p, a, b, c) {
  const u = [p[3 * b] - p[3 * a], p[3 * b + 1] - p[3 * a + 1], p[3 * b + 2] - p[3 * a + 2]];
  const v = [p[3 * c] - p[3 * a], p[3 * c + 1] - p[3 * a + 1], p[3 * c + 2] - p[3 * a + 2]];
  return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
}

/** (b − a) × (c − a) · (d − a): six times the signed volume of the tetrahedron a b c d. */
function tripleProduct(p, a, b, c, d) {
  const n = normalOf(p, a, b, c);
  return n[0] * (p[3 * d] - p[3 * a]) + n[1] * (p[3 * d + 1] - p[3 * a + 1]) + n[2] * (p[3 * d + 2] - p[3 * a + 2]);
}

/**
 * The boundary surface of `mesh` ({points3, tetrahedra}): {triangles: Uint32Array (3 vertices
 * per face, ordered so that the normal points out of the body), cells: Uint32Array (the
 * tetrahedron of each face)}. A face shared by two tetrahedra is interior; a face found more
 * than twice means the mesh is not a valid tetrahedral mesh, and is refused.
 */
export function boundarySurface(mesh) {
  const { points3: p, tetrahedra: tets } = mesh;
  const key = faceKey(p.length / 3);
  const seen = new Map();  // key → [count, tetrahedron, local face]
  const nTets = tets.length / 4;
  for (let t = 0; t < nTets; t++) {
    for (let f = 0; f < 4; f++) {
      const [i, j, k] = FACES[f];
      const id = key(tets[4 * t + i], tets[4 * t + j], tets[4 * t + k]);
      const entry = seen.get(id);
      if (!entry) seen.set(id, [1, t, f]);
      else if (++entry[0] > 2) throw new Error(`tetrahedron ${t} shares a face with two others: not a valid mesh`);
    }
  }
  const triangles = [];
  const cells = [];
  for (const [count, t, f] of seen.values()) {
    if (count !== 1) continue;
    const [i, j, k, opposite] = FACES[f].map((local) => tets[4 * t + local]);
    // Outward: the opposite vertex lies behind the face, so the triple product is negative.
    if (tripleProduct(p, i, j, k, opposite) > 0) triangles.push(i, k, j);
    else triangles.push(i, j, k);
    cells.push(t);
  }
  return { triangles: Uint32Array.from(triangles), cells: Uint32Array.from(cells) };
}

/**
 * Which surface triangles are contact faces (1) and which are not (0), from the VTU's point
 * array contact_boundary (1 at the vertices of contact faces). A face counts when all three of
 * its vertices are flagged: the VTU has no per-face group, and a contact face always has its
 * three vertices flagged, while a face of another group touches the contact region at one or
 * two vertices along its rim. Only a face whose three vertices all lie on that rim would be
 * taken wrongly, and the pressure there is the rim's, where it falls to zero.
 * All zeros when the VTU has no contact_boundary.
 */
export function contactFaces(mesh, surface) {
  const flags = mesh.pointData.contact_boundary?.values;
  const n = surface.triangles.length / 3;
  const out = new Uint8Array(n);
  if (!flags) return out;
  for (let f = 0; f < n; f++) {
    const t = surface.triangles;
    out[f] = flags[t[3 * f]] > 0.5 && flags[t[3 * f + 1]] > 0.5 && flags[t[3 * f + 2]] > 0.5 ? 1 : 0;
  }
  return out;
}
