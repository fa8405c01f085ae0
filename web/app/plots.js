// The uPlot charts of a job: contact pressure and gap along the contact boundary (with the
// Hertz curve when it applies, and a second job's curves to compare), the KKT residual per
// iteration on a log axis, a sweep's force against the swept value, and an adaptive run's
// estimator and force change against the unknowns.
import uPlot from '../dist/uPlot.esm.js';
import { hertzPressure } from './hertz.js';

export const COLOURS = {
  pressure: '#1f5fbf',
  gap: '#2e8b57',
  comparePressure: '#e67e22',
  compareGap: '#b8860b',
  sweep: '#1f5fbf',
  unconverged: '#c0392b',
  hertz: '#c0392b',
  kkt: '#1f5fbf',
  correction: '#8e44ad',
  estimator: '#1f5fbf',
  forceChange: '#2e8b57',
  slope: '#7f8c8d',
};

export const plotHeight = 260;

export function fitWidth(container) {
  return Math.max(280, Math.floor(container.clientWidth));
}

/** Keeps a chart as wide as its container. Returns the chart. */
export function responsive(chart, container) {
  const observer = new ResizeObserver(() => {
    const w = fitWidth(container);
    if (w !== chart.width) chart.setSize({ width: w, height: plotHeight });
  });
  observer.observe(container);
  const destroy = chart.destroy.bind(chart);
  chart.destroy = () => {
    observer.disconnect();
    destroy();
  };
  return chart;
}

/** A number for an axis or legend: 4 digits, exponential outside [1e-3, 1e4). */
export function sci(v) {
  if (v === null || v === undefined || !Number.isFinite(v)) return '—';
  if (v === 0) return '0';
  return Math.abs(v) >= 1e-3 && Math.abs(v) < 1e4 ? String(Number(v.toPrecision(4))) : v.toExponential(2);
}

/** Ticks at whole decades only (every k-th when there are many), for a log axis. */
function decadeSplits(u, axisIndex, min, max) {
  const lo = Math.ceil(Math.log10(min) - 1e-9);
  const hi = Math.floor(Math.log10(max) + 1e-9);
  const step = Math.max(1, Math.ceil((hi - lo + 1) / 8));
  const out = [];
  for (let e = hi; e >= lo; e -= step) out.unshift(10 ** e);
  return out;
}

/** x and y of `contact` sorted along the abscissa, for uPlot (which needs ascending x). */
export function sortedAlong(contact, abscissa, field) {
  const xs = contact[abscissa] ?? [];
  const order = xs.map((_, i) => i).sort((i, j) => xs[i] - xs[j]);
  return [order.map((i) => xs[i]), order.map((i) => contact[field]?.[i] ?? null)];
}

/**
 * [x, p(x)] of the Hertz pressure ({a, p0}) over [−1.2a, 1.2a] clipped to [from, to], with the
 * corners at ±a sampled exactly so that the edge of the contact zone is sharp.
 */
function hertzCurve(hertz, from, to) {
  const lo = Math.max(from, -1.2 * hertz.a);
  const hi = Math.min(to, 1.2 * hertz.a);
  const hx = [];
  const n = 241;
  for (let k = 0; k < n; k++) hx.push(lo + ((hi - lo) * k) / (n - 1));
  for (const edge of [-hertz.a, hertz.a]) if (edge > lo && edge < hi) hx.push(edge);
  hx.sort((a, b) => a - b);
  return [hx, hx.map((v) => hertzPressure(v, hertz))];
}

/**
 * Contact pressure (left axis) and remaining gap (right axis) against x (or arc length s) of
 * the contact edge midpoints. With `hertz` ({a, p0}) the analytic pressure is drawn over
 * [−1.2a, 1.2a] clipped to the data range; with `compare` ({label, contact}) a second job's
 * pressure and gap are drawn dashed over the first.
 */
export function boundaryPlot(container, contact, { hertz = null, abscissa = 'x', compare = null, units = null } = {}) {
  // The case's declared units in the axis labels (" (mm)"), nothing when it declared none.
  const inUnit = (id) => (units?.declared ? ` (${units[id]})` : '');
  const [x, p] = sortedAlong(contact, abscissa, 'pressure');
  const tables = [[x, p, sortedAlong(contact, abscissa, 'gap')[1]]];
  const value = (u, v) => sci(v);
  const series = [
    { label: abscissa === 'x' ? 'x' : 's', value },
    { label: 'pressure', stroke: COLOURS.pressure, width: 2, value, points: { show: x.length < 120, size: 4 } },
    { label: 'gap', scale: 'gap', stroke: COLOURS.gap, width: 1.5, value, points: { show: false } },
  ];
  if (hertz && abscissa === 'x' && x.length > 0) {
    tables.push(hertzCurve(hertz, x[0], x[x.length - 1]));
    series.push({ label: 'Hertz pressure (plane strain)', stroke: COLOURS.hertz, width: 1.5, dash: [6, 4], value, points: { show: false } });
  }
  if (compare) {
    const [cx, cp] = sortedAlong(compare.contact, abscissa, 'pressure');
    tables.push([cx, cp, sortedAlong(compare.contact, abscissa, 'gap')[1]]);
    series.push(
      { label: `${compare.label} pressure`, stroke: COLOURS.comparePressure, width: 2, dash: [8, 4], value, points: { show: false } },
      { label: `${compare.label} gap`, scale: 'gap', stroke: COLOURS.compareGap, width: 1.5, dash: [3, 3], value, points: { show: false } },
    );
  }
  const data = tables.length > 1 ? uPlot.join(tables) : tables[0];
  const opts = {
    width: fitWidth(container),
    height: plotHeight,
    scales: { x: { time: false } },
    series: series.map((s, i) => (i === 0 ? s : { ...s, spanGaps: true })),
    axes: [
      { label: (abscissa === 'x' ? 'x (contact edge midpoints)' : 'arc length s') + inUnit('L'), size: 46 },
      { label: `contact pressure${inUnit('S')}`, size: 64, values: (u, vals) => vals.map(sci) },
      { label: `gap${inUnit('L')}`, scale: 'gap', side: 1, size: 64, grid: { show: false }, values: (u, vals) => vals.map(sci) },
    ],
    legend: { live: false },
  };
  const chart = responsive(new uPlot(opts, data, container), container);
  Object.assign(container.dataset, {
    points: String(x.length),
    series: series.slice(1).map((s) => s.label).join('|'),
    comparePoints: String(compare ? compare.contact.x?.length ?? 0 : 0),
  });
  return chart;
}

/** KKT residual (and, unless told not to, the correction size) per iteration, log y axis. */
export function residualPlot(container, history, { correction: showCorrection = true } = {}) {
  const it = history.map((h) => h.iteration);
  const positive = (v) => (typeof v === 'number' && v > 0 ? v : null);
  const kkt = history.map((h) => positive(h.kkt_residual));
  const correction = history.map((h) => positive(h.correction));
  const opts = {
    width: fitWidth(container),
    height: plotHeight,
    scales: { x: { time: false }, y: { distr: 3 } },
    legend: { live: false },
    series: [
      { label: 'iteration' },
      { label: 'KKT residual', stroke: COLOURS.kkt, width: 2, value: (u, v) => sci(v), points: { show: it.length < 60, size: 4 } },
      { label: 'correction', stroke: COLOURS.correction, width: 1, dash: [4, 3], value: (u, v) => sci(v), points: { show: false } },
    ],
    axes: [
      { label: 'iteration', size: 46 },
      { label: 'residual', size: 64, splits: decadeSplits, values: (u, vals) => vals.map((v) => (v === null ? '' : `1e${Math.round(Math.log10(v))}`)) },
    ],
  };
  if (!showCorrection) opts.series.pop();
  const data = showCorrection ? [it, kkt, correction] : [it, kkt];
  const chart = responsive(new uPlot(opts, data, container), container);
  container.dataset.points = String(kkt.filter((v) => v !== null).length);
  return chart;
}

/** [values, F_y, F_y of the points that did not converge] of a sweep, by ascending value. */
function sweepTable(sweep, dimension = 2) {
  const points = [...(sweep.points ?? [])].sort((a, b) => a.value - b.value);
  const normal = (f) => (dimension === 3 ? (f ? Math.hypot(...f) : null) : f?.[1] ?? null);
  const force = points.map((p) => normal(p.force));
  return [points.map((p) => p.value), force, points.map((p, i) => (p.converged ? null : force[i]))];
}

/**
 * A sweep's curve: the contact force of each point against the swept value (F_y per unit
 * thickness in 2D, |F| in 3D, where no axis is the normal one by default); points that did
 * not converge are marked in red on a series of their own. With `compare` ({label, sweep}) a
 * second job's sweep is drawn dashed over it.
 */
export function sweepPlot(container, sweep, compare = null, dimension = 2) {
  const table = sweepTable(sweep, dimension);
  const force = dimension === 3 ? '|F|' : 'F_y';
  const value = (u, v) => sci(v);
  const series = [
    { label: sweep.pointer },
    { label: dimension === 3 ? '|F|' : 'F_y (per unit thickness)', stroke: COLOURS.sweep, width: 2, value, points: { show: true, size: 6 } },
    { label: 'not converged', stroke: COLOURS.unconverged, width: 0, value, points: { show: true, size: 9, fill: COLOURS.unconverged } },
  ];
  let data = table;
  if (compare) {
    const other = sweepTable(compare.sweep, dimension);
    data = uPlot.join([table, other.slice(0, 2)]);
    series.push({ label: `${compare.label} ${force}`, stroke: COLOURS.comparePressure, width: 2, dash: [8, 4], value, points: { show: true, size: 5 } });
  }
  const opts = {
    width: fitWidth(container),
    height: plotHeight,
    scales: { x: { time: false } },
    legend: { live: false },
    series: series.map((s, i) => (i === 0 ? s : { ...s, spanGaps: i !== 2 })),
    axes: [
      { label: sweep.pointer, size: 46, values: (u, vals) => vals.map(sci) },
      { label: `contact force ${force}`, size: 64, values: (u, vals) => vals.map(sci) },
    ],
  };
  const chart = responsive(new uPlot(opts, data, container), container);
  Object.assign(container.dataset, {
    points: String(table[0].length),
    unconverged: String(table[2].filter((v) => v !== null).length),
    comparePoints: String(compare ? compare.sweep.points?.length ?? 0 : 0),
  });
  return chart;
}

/** Labels of a log axis: every tick when it spans less than a decade, else mantissas 1, 2, 5. */
function logTicks(u, vals) {
  const shown = vals.filter((v) => v > 0);
  const narrow = shown.length > 0 && shown[shown.length - 1] < 10 * shown[0];
  return vals.map((v) => {
    const mantissa = Math.round(v / 10 ** Math.floor(Math.log10(v) + 1e-9));
    if (!narrow && ![1, 2, 5].includes(mantissa)) return '';
    return Number.isInteger(v) && v < 1e7 ? String(v) : sci(v);  // unknowns as counts
  });
}

/**
 * An adaptive run, log–log against the unknowns, one point per step (`rows` of
 * adaptiveRows): the estimator J^½ with the reference slope N^(−1/d) through its first point
 * (the optimal rate of P1/RT0 in d dimensions: h ∝ N^(−1/d)), and on a second log axis the
 * relative change of the contact force since the previous step.
 */
export function adaptivityPlot(container, rows, dimension = 2) {
  const value = (u, v) => sci(v);
  const positive = (v) => (typeof v === 'number' && v > 0 ? v : null);
  const dofs = rows.map((r) => r.dofs);
  const estimator = rows.map((r) => positive(r.estimator));
  const first = rows.findIndex((r, k) => estimator[k] !== null);
  const slope = dofs.map((n) => (first < 0 ? null : estimator[first] * (dofs[first] / n) ** (1 / dimension)));
  const opts = {
    width: fitWidth(container),
    height: plotHeight,
    scales: { x: { time: false, distr: 3 }, y: { distr: 3 }, change: { distr: 3 } },
    legend: { live: false },
    series: [
      { label: 'unknowns', value },
      { label: 'J^½ (estimator)', stroke: COLOURS.estimator, width: 2, value, points: { show: true, size: 6 } },
      { label: dimension === 3 ? 'N^(−⅓) (optimal rate)' : 'N^(−½) (optimal rate)', stroke: COLOURS.slope, width: 1, dash: [5, 4], value, points: { show: false } },
      { label: '|ΔF| / |F| (force change)', scale: 'change', stroke: COLOURS.forceChange, width: 2, dash: [8, 3], value, points: { show: true, size: 6 }, spanGaps: true },
    ],
    axes: [
      { label: 'unknowns N', size: 46, values: logTicks },
      { label: 'J^½', size: 64, values: logTicks },
      { label: '|ΔF| / |F|', scale: 'change', side: 1, size: 64, grid: { show: false }, values: logTicks },
    ],
  };
  const data = [dofs, estimator, slope, rows.map((r) => positive(r.forceChange))];
  const chart = responsive(new uPlot(opts, data, container), container);
  Object.assign(container.dataset, {
    points: String(estimator.filter((v) => v !== null).length),
    series: opts.series.slice(1).map((s) => s.label).join('|'),
  });
  return chart;
}

/**
 * A 3D result's contact pressure along a line in the contact plane (`samples` of
 * contact_line.js's sampleLine: s and the value, null off the contact faces: a gap in the
 * curve) against the signed distance s from the line's centre; with `hertz` ({a, p0}) the 3D
 * Hertz pressure p0 √(1 − s²/a²) dashed, centred on the line's centre.
 */
export function linePlot(container, samples, { hertz = null } = {}) {
  const value = (u, v) => sci(v);
  const tables = [[samples.map((x) => x.s), samples.map((x) => x.value)]];
  const series = [
    { label: 's', value },
    { label: 'pressure', stroke: COLOURS.pressure, width: 2, value, points: { show: false } },
  ];
  if (hertz && samples.length > 0) {
    tables.push(hertzCurve(hertz, samples[0].s, samples[samples.length - 1].s));
    series.push({ label: 'Hertz pressure (3D)', stroke: COLOURS.hertz, width: 1.5, dash: [6, 4], value, points: { show: false }, spanGaps: true });
  }
  const opts = {
    width: fitWidth(container),
    height: plotHeight,
    scales: { x: { time: false } },
    series,
    axes: [
      { label: 'distance s from the centre along the line', size: 46, values: (u, vals) => vals.map(sci) },
      { label: 'contact pressure', size: 64, values: (u, vals) => vals.map(sci) },
    ],
    legend: { live: false },
  };
  const chart = responsive(new uPlot(opts, tables.length > 1 ? uPlot.join(tables) : tables[0], container), container);
  const drawn = samples.filter((x) => x.value !== null);
  Object.assign(container.dataset, {
    points: String(drawn.length),
    peak: String(drawn.length ? Math.max(...drawn.map((x) => x.value)) : 0),
    series: series.slice(1).map((x) => x.label).join('|'),
  });
  return chart;
}
