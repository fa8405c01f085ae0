// The uPlot charts of friction and load steps: the shear traction σ_nt with the pressure along
// the contact boundary over a band coloured by each edge's state (stick, slip, open), and the
// tangential against the normal contact force of the load steps, one point per step.
import uPlot from '../dist/uPlot.esm.js';
import { COLOURS, fitWidth, plotHeight, responsive, sci, sortedAlong } from './plots.js';
import { STATE_COLOURS, stateRuns } from './friction.js';

export const FRICTION_COLOURS = { shear: '#6c3483', bound: '#7f8c8d', stepForce: '#1f5fbf', limit: '#c0392b' };

/** Draws the plotting area's canvas work of `paint(ctx, u)` clipped to the plotting area. */
function clipped(u, paint) {
  const { ctx } = u;
  const { left, top, width, height } = u.bbox;
  ctx.save();
  ctx.beginPath();
  ctx.rect(left, top, width, height);
  ctx.clip();
  paint(ctx, u);
  ctx.restore();
}

/**
 * A hook that shades each run of equal state lightly over the plot's height and draws a solid
 * strip of its colour along the bottom, under the curves: where the body sticks and slips
 * reads off the same abscissa as the tractions that cause it.
 */
function stateBand(runs) {
  return (u) => clipped(u, (ctx) => {
    const { top, height } = u.bbox;
    const strip = Math.round(9 * uPlot.pxRatio);
    for (const run of runs) {
      const x0 = u.valToPos(run.from, 'x', true);
      const x1 = u.valToPos(run.to, 'x', true);
      ctx.fillStyle = STATE_COLOURS[run.state] ?? STATE_COLOURS.open;
      ctx.globalAlpha = run.state === 'open' ? 0.06 : 0.13;
      ctx.fillRect(x0, top, x1 - x0, height);
      ctx.globalAlpha = 1;
      ctx.fillRect(x0, top + height - strip, x1 - x0, strip);
    }
  });
}

/**
 * Shear traction σ_nt and contact pressure p (both stresses, one axis) against x or arc
 * length s of the contact edge midpoints, over the state band. With `coefficient` (Coulomb,
 * one 𝔣 for every group) the slip bounds ±𝔣p are drawn dashed: a slipping edge has its shear
 * on one of them, a sticking edge between them.
 */
export function frictionPlot(container, contact, { abscissa = 'x', coefficient = null, units = null } = {}) {
  const inUnit = (id) => (units?.declared ? ` (${units[id]})` : '');
  const [x, p] = sortedAlong(contact, abscissa, 'pressure');
  const shear = sortedAlong(contact, abscissa, 'shear')[1];
  const runs = stateRuns(x, sortedAlong(contact, abscissa, 'state')[1]);
  const value = (u, v) => sci(v);
  const series = [
    { label: abscissa === 'x' ? 'x' : 's', value },
    { label: 'pressure p', stroke: COLOURS.pressure, width: 2, value, points: { show: false } },
    { label: 'shear σ_nt', stroke: FRICTION_COLOURS.shear, width: 2, value, points: { show: x.length < 120, size: 4 } },
  ];
  const data = [x, p, shear];
  if (coefficient !== null) {
    const bound = p.map((v) => (v === null ? null : coefficient * v));
    data.push(bound, bound.map((v) => (v === null ? null : -v)));
    for (const sign of ['+', '−']) {
      series.push({ label: `${sign}𝔣p (slip bound)`, stroke: FRICTION_COLOURS.bound, width: 1, dash: [5, 4], value, points: { show: false } });
    }
  }
  const opts = {
    width: fitWidth(container),
    height: plotHeight,
    scales: { x: { time: false } },
    series,
    axes: [
      { label: (abscissa === 'x' ? 'x (contact edge midpoints)' : 'arc length s') + inUnit('L'), size: 46 },
      { label: `traction${inUnit('S')}`, size: 64, values: (u, vals) => vals.map(sci) },
    ],
    hooks: { drawAxes: [stateBand(runs)] },
    legend: { live: false },
  };
  const chart = responsive(new uPlot(opts, data, container), container);
  Object.assign(container.dataset, {
    points: String(x.length),
    series: series.slice(1).map((s) => s.label).join('|'),
    states: runs.map((r) => `${r.state}:${r.edges}`).join('|'),
  });
  return chart;
}

/** [min, max] of the finite values, widened by 8 % (and to include 0) so no point sits on a frame. */
function paddedRange(values) {
  const finite = values.filter(Number.isFinite);
  const lo = Math.min(0, ...finite);
  const hi = Math.max(0, ...finite);
  const pad = 0.08 * (hi - lo || Math.abs(hi) || 1);
  return [lo - pad, hi + pad];
}

/**
 * A hook writing each step's number beside its point, skipping a number that would overlap
 * one already written (steps of a slow load path crowd together; the table has them all).
 */
function stepLabels(xs, ys, steps) {
  return (u) => clipped(u, (ctx) => {
    const px = uPlot.pxRatio;
    ctx.fillStyle = FRICTION_COLOURS.stepForce;
    ctx.font = `${Math.round(11 * px)}px system-ui, sans-serif`;
    const written = [];
    steps.forEach((step, k) => {
      if (!Number.isFinite(xs[k]) || !Number.isFinite(ys[k])) return;
      const x = u.valToPos(xs[k], 'x', true) + 6 * px;
      const y = u.valToPos(ys[k], 'y', true) - 5 * px;
      if (written.some(([wx, wy]) => Math.abs(wx - x) < 18 * px && Math.abs(wy - y) < 12 * px)) return;
      written.push([x, y]);
      ctx.fillText(String(step), x, y);
    });
  });
}

/**
 * The load path: the tangential against the normal contact force of each step (`rows` of
 * loadStepRows), joined in step order (the x values need not ascend: a path may unload), from
 * the origin of both axes so the distance to Coulomb's limit |F_t| = 𝔣 F_n (drawn dashed
 * with `coefficient`) shows how near the body is to sliding as a whole.
 */
export function stepForcePlot(container, rows, { axes, coefficient = null } = {}) {
  const xs = rows.map((r) => r.normal);
  const ys = rows.map((r) => r.tangential);
  const xRange = paddedRange(xs);
  const value = (u, v) => sci(v);
  const series = [
    { label: axes.normalLabel, value },
    { label: `${axes.tangentialLabel} of each step`, stroke: FRICTION_COLOURS.stepForce, width: 2, value, points: { show: true, size: 7 } },
  ];
  const data = [xs.slice(), ys.slice()];
  if (coefficient !== null) {
    // The limit lines go through two extra x values (0 and the right end) where the steps' series is null.
    const ends = [0, xRange[1]];
    data[0].push(...ends);
    data[1].push(null, null);
    const none = rows.map(() => null);
    data.push([...none, ...ends.map((v) => coefficient * v)], [...none, ...ends.map((v) => -coefficient * v)]);
    for (const sign of ['+', '−']) {
      series.push({ label: `${sign}𝔣 ${axes.normalLabel} (Coulomb limit)`, stroke: FRICTION_COLOURS.limit, width: 1, dash: [6, 4], value, points: { show: false } });
    }
  }
  const yRange = paddedRange(data.slice(1).flat());
  const opts = {
    width: fitWidth(container),
    height: plotHeight,
    // Fixed ranges: uPlot takes an x range from the first and last x, which a path need not have.
    scales: { x: { time: false, auto: false, range: () => xRange }, y: { auto: false, range: () => yRange } },
    // The cursor looks points up by a sorted x; these x values are in step order instead.
    cursor: { show: false },
    series,
    axes: [
      { label: `normal force ${axes.normalLabel}`, size: 46, values: (u, vals) => vals.map(sci) },
      { label: `tangential force ${axes.tangentialLabel}`, size: 64, values: (u, vals) => vals.map(sci) },
    ],
    hooks: { draw: [stepLabels(xs, ys, rows.map((r) => r.step))] },
    legend: { live: false },
  };
  const chart = responsive(new uPlot(opts, data, container), container);
  Object.assign(container.dataset, {
    points: String(xs.filter(Number.isFinite).length),
    series: series.slice(1).map((s) => s.label).join('|'),
  });
  return chart;
}
