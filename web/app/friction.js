// Friction and load steps as the page shows them (docs/web.md): the stick / slip / open runs
// along the contact boundary, the friction law and stick zone in words, the split of the
// contact force into the obstacle's tangential and normal parts, one row per load step, and
// the key numbers friction adds. Pure functions of the result (docs/result-format.md), so
// node's test runner checks them.
import { fmt } from './format.js';
import { resultUnits } from './mesh_fields.js';

/** The colours of the edge states (also the legend's swatches and the test's pixels). */
export const STATE_COLOURS = { open: '#aab2bd', stick: '#16a085', slip: '#e74c3c' };

/** Whether a result's contact carries friction output (shear per edge). */
export const hasFriction = (contact) => Array.isArray(contact?.shear) && contact.shear.length > 0;

/**
 * Runs of equal state along a sorted abscissa: [{state, from, to, edges}]. `xs` are the
 * edge midpoints in ascending order and `states` their states. A run ends halfway to the next
 * run's first midpoint, and the outer ends reach half a spacing beyond the outer midpoints,
 * so the runs tile the boundary without gaps whatever the abscissa (x or arc length s).
 */
export function stateRuns(xs, states) {
  const n = Math.min(xs.length, states.length);
  if (n === 0) return [];
  const half = (i, j) => (xs[j] - xs[i]) / 2;
  const before = n > 1 ? half(0, 1) : 0;
  const after = n > 1 ? half(n - 2, n - 1) : 0;
  const runs = [];
  let start = 0;
  for (let i = 1; i <= n; i++) {
    if (i < n && states[i] === states[start]) continue;
    runs.push({
      state: states[start],
      from: start === 0 ? xs[0] - before : xs[start] - half(start - 1, start),
      to: i === n ? xs[n - 1] + after : xs[i - 1] + half(i - 1, i),
      edges: i - start,
    });
    start = i;
  }
  return runs;
}

/**
 * Coulomb's coefficient when every frictional group has the same one (then the slip bound
 * along the whole boundary is 𝔣 p and can be drawn), else null (Tresca, or mixed laws: the
 * contact arrays do not say which group an edge belongs to).
 */
export function commonCoefficient(friction) {
  const laws = Object.values(friction?.groups ?? {});
  if (laws.length === 0 || laws.some((g) => g.law !== 'coulomb')) return null;
  const coefficients = new Set(laws.map((g) => g.coefficient));
  return coefficients.size === 1 ? laws[0].coefficient : null;
}

/** Whether a result has a Tresca group (whose bound is in the case, not in the result). */
export const hasTresca = (result) => Object.values(result?.friction?.groups ?? {}).some((g) => g.law === 'tresca');

/** One group's law: "Coulomb 𝔣 = 0.3", "Tresca s = 0.01" (the bound read from the case). */
function lawText(name, law, caseDoc) {
  if (law.law === 'coulomb') return `Coulomb 𝔣 = ${fmt(law.coefficient)}`;
  const bound = caseDoc?.boundary?.[name]?.friction?.bound;
  const shown = typeof bound === 'number' ? fmt(bound) : bound;
  return bound === undefined ? 'Tresca (bound s as in the case)' : `Tresca s = ${shown}`;
}

/**
 * The friction summary in words: each group's law (named when there are several) and, for
 * Coulomb, how the slip bounds 𝔣|σ_nn| settled: the number of updates and the last change.
 */
export function frictionText(friction, caseDoc = null) {
  const groups = Object.entries(friction?.groups ?? {});
  if (groups.length === 0) return '—';
  const laws = groups.map(([name, law]) => (groups.length > 1 ? `${name}: ` : '') + lawText(name, law, caseDoc));
  const updates = friction.updates ?? 0;
  const settled = updates > 0
    ? `; ${updates} update${updates === 1 ? '' : 's'} of the slip bounds, the last changing them by ${fmt(friction.last_change, 2)}`
    : '';
  return laws.join(', ') + settled;
}

/** Where the body sticks: "0.1493 over 10 edges, s = 0.4674 … 0.6167" (lengths with `unit`). */
export function stickZoneText(zone, unit = '') {
  if (!zone) return '—';
  if (!zone.edges) return 'none: every edge in contact slips';
  return `${fmt(zone.length)}${unit} over ${zone.edges} edge${zone.edges === 1 ? '' : 's'}, ` +
    `s = ${fmt(zone.s_start)} … ${fmt(zone.s_end)}${unit}`;
}

/**
 * The axes the contact force is split along. With one plane obstacle (contact.plane_normal ν,
 * from the obstacle into the body) the normal force is F·ν and the tangential one F·t with
 * t = (ν_y, −ν_x), ν turned clockwise, which is +x for a horizontal plane with ν = (0, 1).
 * Otherwise the result gives no obstacle direction and the split is F_x, F_y.
 */
export function forceAxes(planeNormal) {
  if (Array.isArray(planeNormal) && planeNormal.length === 2) {
    const [nx, ny] = planeNormal;
    return { tangent: [ny, -nx], normal: [nx, ny], tangentialLabel: 'F_t', normalLabel: 'F_n', byPlane: true };
  }
  return { tangent: [1, 0], normal: [0, 1], tangentialLabel: 'F_x', normalLabel: 'F_y', byPlane: false };
}

const dot = (a, b) => (a && b ? a[0] * b[0] + a[1] * b[1] : NaN);

/** Counts of each edge state ({open, stick, slip}); frictionless output has no states. */
function stateCounts(states) {
  const counts = { open: 0, stick: 0, slip: 0 };
  for (const s of states ?? []) if (s in counts) counts[s]++;
  return counts;
}

/** A step's changes as one line: "/boundary/top/displacement/0 = 0.002" (— for step 0). */
export function changesText(changes) {
  const entries = Object.entries(changes ?? {});
  if (entries.length === 0) return '— (the case as given)';
  return entries.map(([pointer, value]) => `${pointer} = ${JSON.stringify(value)}`).join(', ');
}

/**
 * One row per load step: {step, changes, iterations, converged, force, tangential, normal,
 * ratio |F_t| / F_n, stickLength, counts, contact}. `axes` from forceAxes.
 */
export function loadStepRows(loadSteps, axes) {
  return (loadSteps?.steps ?? []).map((s, k) => {
    const force = s.contact?.force ?? [NaN, NaN];
    const tangential = dot(force, axes.tangent);
    const normal = dot(force, axes.normal);
    return {
      step: s.step ?? k,
      changes: changesText(s.changes),
      iterations: s.iterations,
      converged: s.converged === true,
      force,
      tangential,
      normal,
      ratio: normal > 0 ? Math.abs(tangential) / normal : null,
      stickLength: s.contact?.stick_zone?.length ?? null,
      counts: stateCounts(s.contact?.state),
      contact: s.contact ?? null,
    };
  });
}

/** The load-step table's columns: heading and cell text (the force headings follow `axes`). */
export function loadStepColumns(axes) {
  const { tangentialLabel: t, normalLabel: n } = axes;
  return [
    ['step', (r) => String(r.step)],
    ['changes', (r) => r.changes],
    ['iterations', (r) => String(r.iterations ?? '—')],
    ['converged', (r) => (r.converged ? 'yes' : 'no')],
    [t, (r) => fmt(r.tangential)],
    [n, (r) => fmt(r.normal)],
    [`|${t}| / ${n}`, (r) => fmt(r.ratio, 3)],
    ['stick zone', (r) => fmt(r.stickLength)],
    ['stick / slip / open edges', (r) => `${r.counts.stick} / ${r.counts.slip} / ${r.counts.open}`],
  ];
}

/** The key numbers a frictional or load-stepped result adds: [term, value, tooltip]. */
export function frictionNumbers(result, caseDoc = null) {
  const units = resultUnits(result);
  const unit = units.declared ? ` ${units.L}` : '';
  const out = [];
  if (result.friction) {
    out.push(['Friction', frictionText(result.friction, caseDoc),
      'the law of each frictional contact group; Coulomb\'s slip bounds 𝔣|σ_nn| are updated until they settle (solver.friction_tolerance)']);
  }
  if (hasFriction(result.contact)) {
    out.push(['Stick zone', stickZoneText(result.contact.stick_zone, unit),
      'contact.stick_zone: the edges in contact whose shear is below the slip bound (arc length s from the start of the contact boundary)']);
  }
  const steps = result.load_steps?.steps;
  if (steps?.length) {
    const bad = steps.filter((s) => !s.converged).length;
    out.push(['Load steps', `${steps.length} (${bad ? `${bad} not converged` : 'all converged'})`,
      'step 0 is the case as given; the other numbers here are the last step\'s']);
  }
  return out;
}
