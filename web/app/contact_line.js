// Pressure along a line in the contact plane of a 3D result: the plane's frame, the default
// centre (the pressure-weighted centroid of the contact vertices) and the samples of a vertex
// field (the VTU's contact_pressure) on the contact faces, projected to the plane and
// interpolated linearly within each face, where the line crosses them.

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (a) => {
  const l = Math.hypot(...a);
  return a.map((c) => c / l);
};

/**
 * An orthonormal frame of the plane with normal `normal`: {n, t1, t2}. t1 is global x projected
 * onto the plane (or y when x lies along the normal), so θ = 0 reads as "along x" whenever it
 * can; t2 = n × t1 makes (t1, t2, n) right-handed. Null for a zero normal.
 */
export function planeFrame(normal) {
  if (!(Math.hypot(...normal) > 0)) return null;
  const n = unit(normal);
  const along = (axis) => axis.map((c, k) => c - dot(axis, n) * n[k]);
  let t = along([1, 0, 0]);
  if (Math.hypot(...t) < 1e-6) t = along([0, 1, 0]);
  const t1 = unit(t);
  const t2 = [n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]];
  return { n, t1, t2 };
}

/** The point x moved along n onto the plane through `point`. */
export function projectToPlane(x, point, n) {
  const h = (x[0] - point[0]) * n[0] + (x[1] - point[1]) * n[1] + (x[2] - point[2]) * n[2];
  return [x[0] - h * n[0], x[1] - h * n[1], x[2] - h * n[2]];
}

/**
 * The contact vertices' centroid weighted by `values` (their pressure); without pressure their
 * plain centroid; without contact vertices null.
 */
function pressureCentroid(points3, flags, values) {
  const sum = [0, 0, 0], plain = [0, 0, 0];
  let weight = 0, count = 0;
  for (let v = 0; v < flags.length; v++) {
    if (!(flags[v] > 0.5)) continue;
    const w = Math.max(0, values[v]);
    for (let d = 0; d < 3; d++) {
      sum[d] += w * points3[3 * v + d];
      plain[d] += points3[3 * v + d];
    }
    weight += w;
    count++;
  }
  if (count === 0) return null;
  return weight > 0 ? sum.map((c) => c / weight) : plain.map((c) => c / count);
}

/**
 * The default centre of the line: the contact vertices' centroid weighted by `values` (their
 * pressure), projected onto the plane. Without pressure the plain centroid of the contact
 * vertices; without contact vertices the plane's point.
 */
export function pressureCentre(points3, flags, values, plane) {
  const centroid = pressureCentroid(points3, flags, values);
  if (!centroid) return [...plane.point];
  return projectToPlane(centroid, plane.point, unit(plane.normal));
}

/**
 * A sphere obstacle's plane for the line: tangent to the sphere where the line from its centre
 * through the contact's pressure centroid meets it, the normal pointing from the ball into the
 * body. Null without contact vertices or when the centroid is the centre.
 */
export function sphereTangentPlane(points3, flags, values, sphere) {
  const centroid = pressureCentroid(points3, flags, values);
  if (!centroid) return null;
  const d = centroid.map((c, k) => c - sphere.center[k]);
  const length = Math.hypot(...d);
  if (!(length > 0)) return null;
  const normal = d.map((c) => c / length);
  return { point: sphere.center.map((c, k) => c + sphere.radius * normal[k]), normal };
}

/**
 * Where the line s ↦ s·(cos θ, sin θ) (plane coordinates about the centre) runs through each
 * contact triangle: [{vertices, lambda0, slope, from, to}] with the barycentric weights
 * λ(s) = lambda0 + s·slope, all ≥ 0 for s in [from, to]. Triangles seen edge-on from the plane
 * (zero projected area) are skipped: the faces next to them cover that part of the plane.
 */
function lineCrossings(points3, faces, frame, centre, theta) {
  const d = [Math.cos(theta), Math.sin(theta)];
  const toPlane = (v) => {
    const x = [0, 1, 2].map((k) => points3[3 * v + k] - centre[k]);
    return [dot(x, frame.t1), dot(x, frame.t2)];
  };
  const cross = (a, b) => a[0] * b[1] - a[1] * b[0];
  const out = [];
  for (const vertices of faces) {
    const [A, B, C] = vertices.map(toPlane);
    const area2 = cross([B[0] - A[0], B[1] - A[1]], [C[0] - A[0], C[1] - A[1]]);
    if (Math.abs(area2) < 1e-14 * (Math.hypot(...A) + Math.hypot(...B) + Math.hypot(...C)) ** 2) continue;
    // λ_A(q) = cross(B − q, C − q) / area2 and cyclically; linear in s for q = s·d.
    const weight = (P, Q, s) => cross([P[0] - s * d[0], P[1] - s * d[1]], [Q[0] - s * d[0], Q[1] - s * d[1]]) / area2;
    const lambda0 = [weight(B, C, 0), weight(C, A, 0), weight(A, B, 0)];
    const slope = [weight(B, C, 1) - lambda0[0], weight(C, A, 1) - lambda0[1], weight(A, B, 1) - lambda0[2]];
    let from = -Infinity, to = Infinity;
    const eps = 1e-12;
    for (let k = 0; k < 3; k++) {
      if (Math.abs(slope[k]) < 1e-15) {
        if (lambda0[k] < -eps) from = Infinity;
      } else if (slope[k] > 0) from = Math.max(from, (-eps - lambda0[k]) / slope[k]);
      else to = Math.min(to, (-eps - lambda0[k]) / slope[k]);
    }
    if (from <= to) out.push({ vertices, lambda0, slope, from, to });
  }
  return out;
}

/**
 * Samples of the vertex field `values` along the line through `centre` (on the plane) at angle
 * θ (degrees) from the frame's t1 towards t2, over the contact triangles `faces` ([[a, b, c],
 * ...] vertex triples) projected to the plane: `count` evenly spaced points over the stretch
 * the line crosses, plus the points where it enters and leaves each triangle (so a field linear
 * on each triangle is drawn exactly). Returns [{s, value, point: [x, y, z]}] sorted by the
 * signed distance s from the centre; a sample outside every contact triangle has value null
 * (not drawn); an empty list when the line misses them all.
 */
export function sampleLine({ points3, faces, values, frame, centre, thetaDegrees, count = 201 }) {
  const theta = (thetaDegrees * Math.PI) / 180;
  const crossings = lineCrossings(points3, faces, frame, centre, theta);
  if (crossings.length === 0) return [];
  const lo = Math.min(...crossings.map((c) => c.from));
  const hi = Math.max(...crossings.map((c) => c.to));
  const where = new Set(crossings.flatMap((c) => [c.from, c.to]));
  for (let k = 0; k < count; k++) where.add(count === 1 ? lo : lo + ((hi - lo) * k) / (count - 1));
  const direction = [0, 1, 2].map((k) => Math.cos(theta) * frame.t1[k] + Math.sin(theta) * frame.t2[k]);
  return [...where].sort((a, b) => a - b).map((s) => {
    const hit = crossings.find((c) => s >= c.from && s <= c.to);
    const value = hit ? hit.vertices.reduce((sum, v, k) => sum + (hit.lambda0[k] + s * hit.slope[k]) * values[v], 0) : null;
    return { s, value, point: centre.map((c, k) => c + s * direction[k]) };
  });
}
