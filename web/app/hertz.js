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
