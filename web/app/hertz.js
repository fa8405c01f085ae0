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

/**
 * The parts of a case that hertzForCase reads, rebuilt from a result (which carries the
 * material, the builtin mesh and the obstacle type of each contact group), for jobs this
 * browser did not submit. Null when the result lacks them.
 */
export function caseFromResult(result) {
  if (!result?.material || !result?.mesh?.builtin || !result?.contact?.obstacles) return null;
  const boundary = {};
  for (const [group, type] of Object.entries(result.contact.obstacles))
    boundary[group] = { type: 'contact', obstacle: { type } };
  return {
    name: result.name,
    mesh: { builtin: { name: result.mesh.builtin, ...(result.mesh.params ?? {}) } },
    material: result.material,
    boundary,
  };
}

/**
 * The Hertz comparison for a case and its result, or null when it does not apply: the case
 * name contains "hertz", the mesh is the builtin "hertz" half disk (radius R, default 1) and a
 * contact boundary has a plane obstacle. F = |force_y| of the result.
 */
export function hertzForCase(caseJson, result) {
  if (!caseJson || !result?.contact) return null;
  const name = String(caseJson.name ?? result.name ?? '');
  if (!name.toLowerCase().includes('hertz')) return null;
  const builtin = caseJson.mesh?.builtin;
  const builtinName = typeof builtin === 'string' ? builtin : builtin?.name;
  if (builtinName !== 'hertz') return null;
  const R = typeof builtin === 'object' && typeof builtin.radius === 'number' ? builtin.radius : 1;
  const planeContact = Object.values(caseJson.boundary ?? {}).some(
    (bc) => bc?.type === 'contact' && bc?.obstacle?.type === 'plane',
  );
  if (!planeContact) return null;
  const lame = lameParameters(caseJson.material);
  const F = Math.abs(result.contact.force?.[1] ?? NaN);
  if (!lame || !(F > 0) || !(R > 0)) return null;
  return { F, R, ...hertzContact(F, R, lame) };
}
