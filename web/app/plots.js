// The two uPlot charts of a job: contact pressure along the contact boundary (with the
// Hertz curve when it applies) and the KKT residual per iteration on a log axis.
import uPlot from '../dist/uPlot.esm.js';
import { hertzPressure } from './hertz.js';

export const COLOURS = {
  pressure: '#1f5fbf',
  sweep: '#1f5fbf',
  unconverged: '#c0392b',
  hertz: '#c0392b',
  kkt: '#1f5fbf',
  correction: '#8e44ad',
};

const plotHeight = 260;

function fitWidth(container) {
  return Math.max(280, Math.floor(container.clientWidth));
}

/** Keeps a chart as wide as its container. Returns the chart. */
function responsive(chart, container) {
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

function sci(v) {
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

/**
 * Contact pressure against x (or arc length s) of the contact edge midpoints, sorted along
 * the abscissa. With `hertz` ({a, p0}) the analytic curve is drawn over [−1.2a, 1.2a]
 * clipped to the data range.
 */
export function pressurePlot(container, contact, hertz, abscissa = 'x') {
  const xs = contact[abscissa] ?? [];
  const order = xs.map((_, i) => i).sort((i, j) => xs[i] - xs[j]);
  const x = order.map((i) => xs[i]);
  const p = order.map((i) => contact.pressure[i]);
  const tables = [[x, p]];
  const series = [
    { label: abscissa === 'x' ? 'x' : 's', value: (u, v) => sci(v) },
    { label: 'FOSLS pressure', stroke: COLOURS.pressure, width: 2, value: (u, v) => sci(v), points: { show: x.length < 120, size: 4 } },
  ];
  if (hertz && abscissa === 'x' && x.length > 0) {
    const lo = Math.max(x[0], -1.2 * hertz.a);
    const hi = Math.min(x[x.length - 1], 1.2 * hertz.a);
    const hx = [];
    const n = 241;
    for (let k = 0; k < n; k++) hx.push(lo + ((hi - lo) * k) / (n - 1));
    // Sample the corners of the curve at ±a exactly so the edge of the contact zone is sharp.
    for (const edge of [-hertz.a, hertz.a]) if (edge > lo && edge < hi) hx.push(edge);
    hx.sort((a, b) => a - b);
    tables.push([hx, hx.map((v) => hertzPressure(v, hertz))]);
    series.push({ label: 'Hertz (plane strain)', stroke: COLOURS.hertz, width: 1.5, dash: [6, 4], value: (u, v) => sci(v), points: { show: false } });
  }
  const data = tables.length > 1 ? uPlot.join(tables) : [x, p];
  const opts = {
    width: fitWidth(container),
    height: plotHeight,
    scales: { x: { time: false } },
    series: series.map((s, i) => (i === 0 ? s : { ...s, spanGaps: true })),
    axes: [
      { label: abscissa === 'x' ? 'x (contact edge midpoints)' : 'arc length s', size: 46 },
      { label: 'contact pressure', size: 64, values: (u, vals) => vals.map(sci) },
    ],
    legend: { live: false },
  };
  const chart = responsive(new uPlot(opts, data, container), container);
  container.dataset.points = String(x.length);
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

/**
 * A sweep's curve: the contact force F_y of each point against the swept value, in order;
 * points that did not converge are marked in red on a series of their own.
 */
export function sweepPlot(container, sweep) {
  const points = sweep.points ?? [];
  const value = points.map((p) => p.value);
  const force = points.map((p) => p.force?.[1] ?? null);
  const unconverged = points.map((p, i) => (p.converged ? null : force[i]));
  const opts = {
    width: fitWidth(container),
    height: plotHeight,
    scales: { x: { time: false } },
    legend: { live: false },
    series: [
      { label: sweep.pointer },
      { label: 'F_y (per unit thickness)', stroke: COLOURS.sweep, width: 2, value: (u, v) => sci(v), points: { show: true, size: 6 } },
      { label: 'not converged', stroke: COLOURS.unconverged, width: 0, value: (u, v) => sci(v), points: { show: true, size: 9, fill: COLOURS.unconverged } },
    ],
    axes: [
      { label: sweep.pointer, size: 46, values: (u, vals) => vals.map(sci) },
      { label: 'contact force F_y', size: 64, values: (u, vals) => vals.map(sci) },
    ],
  };
  const chart = responsive(new uPlot(opts, [value, force, unconverged], container), container);
  container.dataset.points = String(points.length);
  container.dataset.unconverged = String(unconverged.filter((v) => v !== null).length);
  return chart;
}
