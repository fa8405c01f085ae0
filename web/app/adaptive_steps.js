// The steps of an adaptive run (the result's `adaptivity.steps`, docs/result-format.md): one
// row per solve with the numbers an engineer judges convergence by, and the table of them.
import { fmt, seconds } from './format.js';

/** |a − b| / |a| of two force vectors of 2 or 3 components (null without both, or when a is zero). */
function relativeChange(a, b) {
  if (!a || !b) return null;
  const size = Math.hypot(...a);
  return size > 0 ? Math.hypot(...a.map((x, k) => x - b[k])) / size : null;
}

/**
 * One row per step: {step, dofs, cells (triangles in 2D, tetrahedra in 3D), iterations,
 * estimator (J^½), force [Fx, Fy] or [Fx, Fy, Fz], forceChange, algebraicError, time}. forceChange is |F_k − F_(k−1)| / |F_k|, the change of
 * the force vector since the previous step relative to this step's force (null on the first
 * step): the force itself moves by fractions of a percent, which a log axis would show as a
 * flat line, while its change falls with refinement and says what one more step would gain.
 */
export function adaptiveRows(steps) {
  return (steps ?? []).map((s, k) => ({
    step: s.step ?? k,
    dofs: s.dofs,
    cells: s.triangles ?? s.tetrahedra,
    iterations: s.iterations,
    estimator: s.estimator,
    force: s.force ?? [NaN, NaN],
    forceChange: k > 0 ? relativeChange(s.force, steps[k - 1].force) : null,
    algebraicError: s.algebraic_error ?? null,
    time: s.time_s,
  }));
}

/** Column headings and each row's cell texts, in the order the table shows them, in 2D or 3D. */
export function stepColumns(dimension = 2) {
  const forces = ['F_x', 'F_y', 'F_z'].slice(0, dimension).map((name, k) => [name, (r) => fmt(r.force[k])]);
  return [
    ['step', (r) => String(r.step)],
    ['unknowns', (r) => String(r.dofs)],
    [dimension === 3 ? 'tetrahedra' : 'triangles', (r) => String(r.cells ?? '—')],
    ['iterations', (r) => String(r.iterations)],
    ['J^½', (r) => fmt(r.estimator)],
    ...forces,
    ['|ΔF| / |F|', (r) => fmt(r.forceChange, 2)],
    ['algebraic error', (r) => fmt(r.algebraicError, 2)],
    ['time', (r) => seconds(r.time)],
  ];
}

/** Fills `table` (a <table> with a <thead> and a <tbody>) with one row per step. */
export function renderStepTable(table, rows, dimension = 2) {
  const columns = stepColumns(dimension);
  const head = table.tHead.rows[0] ?? table.tHead.insertRow();
  head.replaceChildren(...columns.map(([title]) => Object.assign(document.createElement('th'), { scope: 'col', textContent: title })));
  const body = table.tBodies[0];
  body.replaceChildren(...rows.map((r) => {
    const tr = document.createElement('tr');
    for (const [, text] of columns) tr.append(Object.assign(document.createElement('td'), { textContent: text(r) }));
    return tr;
  }));
}
