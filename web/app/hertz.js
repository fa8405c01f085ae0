// Plane-strain Hertz contact of a cylinder of radius R pressed on a rigid plane by a force F
// per unit thickness (K. L. Johnson, Contact Mechanics, §5.2, with a rigid plane):
//   E* = 4μ(λ+μ)/(λ+2μ)  (= E/(1−ν²); 4μ for an incompressible material, λ = ∞)
//   a  = sqrt(4FR/(πE*)),   p0 = 2F/(πa),   p(x) = p0 sqrt(1 − x²/a²) for |x| < a.

/** Lamé parameters {mu, lambda} of a case's material (lambda may be Infinity), or null. */
export function lameParameters(material) {
  if (!material || typeof material !== 'object') return null;
  const num = (v) => (v === 'inf' ? Infinity : typeof v === 'number' ? v : NaN);
  if ('mu' in material) {
    const mu = num(material.mu);
    const lambda = num(material.lambda);
    return mu > 0 && lambda >= 0 ? { mu, lambda } : null;
  }
  if ('E' in material) {
    const E = num(material.E);
    const nu = num(material.nu);
    if (!(E > 0) || !(nu > -1 && nu <= 0.5)) return null;
    const mu = E / (2 * (1 + nu));
    const lambda = nu === 0.5 ? Infinity : (E * nu) / ((1 + nu) * (1 - 2 * nu));
    return { mu, lambda };
  }
  return null;
}

/** Plane-strain contact modulus E* from μ and λ (λ = Infinity allowed). */
export function contactModulus({ mu, lambda }) {
  if (!Number.isFinite(lambda)) return 4 * mu;
  return (4 * mu * (lambda + mu)) / (lambda + 2 * mu);
}

/** {a, p0, Estar} for force F (per unit thickness, > 0), radius R and material. */
export function hertzContact(F, R, lame) {
  const Estar = contactModulus(lame);
  const a = Math.sqrt((4 * F * R) / (Math.PI * Estar));
  const p0 = (2 * F) / (Math.PI * a);
  return { a, p0, Estar };
}

/** The Hertz pressure at x (0 outside the contact zone). */
export function hertzPressure(x, { a, p0 }) {
  const r = 1 - (x * x) / (a * a);
  return r > 0 ? p0 * Math.sqrt(r) : 0;
}

/** Lamé parameters {mu, lambda} from a result's material echo ({mu, lambda: number | "inf"}). */
function resultLame(material) {
  const mu = material?.mu;
  const lambda = material?.lambda === 'inf' ? Infinity : material?.lambda;
  return typeof mu === 'number' && mu > 0 && (lambda === Infinity || (typeof lambda === 'number' && lambda >= 0))
    ? { mu, lambda }
    : null;
}

/**
 * The Hertz comparison for a result, or null when it does not apply. Offered by geometry, not
 * by name: the contact boundary is one circular arc (`contact.shape.type` "arc", radius R) and
 * every contact group has a plane obstacle with one normal ν (`contact.plane_normal`); the load
 * is the normal force F = |F·ν| of the result.
 */
export function hertzForResult(result) {
  const contact = result?.contact;
  const shape = contact?.shape;
  const normal = contact?.plane_normal;
  if (shape?.type !== 'arc' || !Array.isArray(normal) || !Array.isArray(contact.force)) return null;
  const R = shape.radius;
  const lame = resultLame(result.material);
  const F = Math.abs(contact.force[0] * normal[0] + contact.force[1] * normal[1]);
  if (!lame || !(F > 0) || !(R > 0)) return null;
  return { F, R, ...hertzContact(F, R, lame) };
}

// 3D: a sphere of radius R pressed on a rigid plane by a force F (Johnson §4.2, one body rigid):
//   E = μ(3λ+2μ)/(λ+μ), ν = λ/(2(λ+μ)) (λ = ∞: E = 3μ, ν = 1/2), E* = E/(1−ν²),
//   a = (3FR/(4E*))^(1/3),   p0 = 3F/(2πa²),   p(r) = p0 sqrt(1 − r²/a²) for r < a.
// E/(1−ν²) written out in μ and λ is 4μ(λ+μ)/(λ+2μ): the plane-strain modulus above, so
// contactModulus serves both.

/** {a, p0, Estar} of 3D Hertz for force F (> 0), sphere radius R and material {mu, lambda}. */
export function hertzSphereContact(F, R, lame) {
  const Estar = contactModulus(lame);
  const a = Math.cbrt((3 * F * R) / (4 * Estar));
  const p0 = (3 * F) / (2 * Math.PI * a * a);
  return { a, p0, Estar };
}

/** A 3D obstacle's point moved by its displacement, when it has one. */
function moved(point, obstacle) {
  const d = obstacle?.displacement;
  return Array.isArray(d) && d.length === 3 ? point.map((x, k) => x + d[k]) : point;
}

/**
 * The plane obstacles of a 3D case's "contact" groups: [{group, point, normal}], given as point
 * and normal or as an obstacle of type plane, moved by its displacement (a sphere or gap
 * obstacle has no plane).
 */
export function contactPlanes(caseDoc) {
  const boundary = caseDoc?.boundary;
  if (!boundary || typeof boundary !== 'object') return [];
  const planeOf = (c) => (c?.obstacle?.type === 'plane' ? c.obstacle : c);
  return Object.entries(boundary)
    .filter(([, c]) => c?.type === 'contact' && Array.isArray(planeOf(c).point) && Array.isArray(planeOf(c).normal))
    .map(([group, c]) => ({ group, point: moved(planeOf(c).point, c.obstacle), normal: planeOf(c).normal }));
}

/** The sphere obstacles of a 3D case's "contact" groups: [{group, center, radius}], moved by their displacement. */
export function contactSpheres(caseDoc) {
  const boundary = caseDoc?.boundary;
  if (!boundary || typeof boundary !== 'object') return [];
  return Object.entries(boundary)
    .filter(([, c]) => c?.type === 'contact' && c.obstacle?.type === 'sphere' && Array.isArray(c.obstacle.center))
    .map(([group, c]) => ({ group, center: moved(c.obstacle.center, c.obstacle), radius: c.obstacle.radius }));
}

/** The builtin half ball's radius (default 1), or null when the case's mesh is something else. */
export function halfBallRadius(caseDoc) {
  const builtin = caseDoc?.mesh?.builtin;
  const name = typeof builtin === 'string' ? builtin : builtin?.name;
  if (name !== 'half_ball') return null;
  const R = typeof builtin === 'object' && 'radius' in builtin ? builtin.radius : 1;
  return typeof R === 'number' && R > 0 ? R : null;
}

/**
 * 3D Hertz for a result and its case, or null when it does not apply: the mesh is the builtin
 * half ball (a sphere of radius R at its pole) against one contact plane (the case's), loaded
 * by the normal force F = 2^k |F·n| of the result (n the plane's unit normal; k the symmetry
 * planes the zone lies against: a quarter ball carries a quarter of the force).
 */
export function hertzForResult3d(result, caseDoc) {
  const R = halfBallRadius(caseDoc);
  const planes = contactPlanes(caseDoc);
  const force = result?.contact?.force;
  const lame = resultLame(result?.material);
  if (R === null || planes.length !== 1 || !Array.isArray(force) || force.length !== 3 || !lame) return null;
  const n = planes[0].normal;
  const length = Math.hypot(...n);
  // A model cut at symmetry planes carries 1/2^k of the ball's force (contact.zone.symmetry_planes).
  const k = result.contact.zone?.symmetry_planes ?? 0;
  const F = Math.abs((force[0] * n[0] + force[1] * n[1] + force[2] * n[2]) / length) * 2 ** k;
  if (!(F > 0) || !(length > 0)) return null;
  return { F, R, ...hertzSphereContact(F, R, lame) };
}
