// The steps of an adaptive run (the result's `adaptivity.steps`, docs/result-format.md): one
// row per solve with the numbers an engineer judges convergence by, and the table of them.
import { fmt, seconds } from './format.js';

/** |a − b| / |a| of two force vectors (null without both, or when a is zero). */
function relativeChange(a, b) {
  if (!a || !b) return null;
  const size = Math.hypot(a[0], a[1]);
  return size > 0 ? Math.hypot(a[0] - b[0], a[1] - b[1]) / size : null;
}

/**
 * One row per step: {step, dofs, triangles, iterations, estimator (J^½), force [Fx, Fy],
 * forceChange, algebraicError, time}. forceChange is |F_k − F_(k−1)| / |F_k|, the change of
 * the force vector since the previous step relative to this step's force (null on the first
 * step): the force itself moves by fractions of a percent, which a log axis would show as a
 * flat line, while its change falls with refinement and says what one more step would gain.
 */
export function adaptiveRows(steps) {
  return (steps ?? []).map((s, k) => ({
    step: s.step ?? k,
    dofs: s.dofs,
    triangles: s.triangles,
    iterations: s.iterations,
    estimator: s.estimator,
    force: s.force ?? [NaN, NaN],
    forceChange: k > 0 ? relativeChange(s.force, steps[k - 1].force) : null,
    algebraicError: s.algebraic_error ?? null,
    time: s.time_s,
  }));
}

/** Column headings and each row's cell texts, in the order the table shows them. */
export const STEP_COLUMNS = [
  ['step', (r) => String(r.step)],
  ['unknowns', (r) => String(r.dofs)],
  ['triangles', (r) => String(r.triangles ?? '—')],
  ['iterations', (r) => String(r.iterations)],
  ['J^½', (r) => fmt(r.estimator)],
  ['F_x', (r) => fmt(r.force[0])],
  ['F_y', (r) => fmt(r.force[1])],
  ['|ΔF| / |F|', (r) => fmt(r.forceChange, 2)],
  ['algebraic error', (r) => fmt(r.algebraicError, 2)],
  ['time', (r) => seconds(r.time)],
];

/** Fills `table` (a <table> with a <thead> and a <tbody>) with one row per step. */
export function renderStepTable(table, rows) {
  const head = table.tHead.rows[0] ?? table.tHead.insertRow();
  head.replaceChildren(...STEP_COLUMNS.map(([title]) => Object.assign(document.createElement('th'), { scope: 'col', textContent: title })));
  const body = table.tBodies[0];
  body.replaceChildren(...rows.map((r) => {
    const tr = document.createElement('tr');
    for (const [, text] of STEP_COLUMNS) tr.append(Object.assign(document.createElement('td'), { textContent: text(r) }));
    return tr;
  }));
}
