// The job view of a finished job: key numbers, warnings, downloads, the charts (pressure and
// gap along the contact boundary, residuals, sweep, adaptive steps, friction and load steps), and the
// coloured mesh with its colour bar. `view` is the page's record of the job shown: {result, mesh,
// meshError, hertz, compare, caseDoc, loadStep, charts}; `plots` the chart modules (null when
// uPlot is missing).
import * as api from './api.js';
import { accuracyNumber } from './accuracy.js';
import { adaptiveRows, renderStepTable } from './adaptive_steps.js';
import { contactCsv, sweepCsv } from './csv_export.js';
import { fmt, seconds } from './format.js';
import { frictionNumbers } from './friction.js';
import { drawFriction, drawLoadSteps } from './friction_view.js';
import { MESH_FIELDS, UNITS, resultUnits } from './mesh_fields.js';
import { autoMagnification, colourGradientCss, colourScale } from './mesh_view.js';
import { valueRange } from './mesh_drawing.js';

const $ = (id) => document.getElementById(id);

/** " mm" after a number when the case declared its units, else "". */
const unitSuffix = (units, id) => (units.declared ? ` ${units[id]}` : '');

export function addNumber(dl, term, value, title) {
  const dt = document.createElement('dt');
  dt.textContent = term;
  const dd = document.createElement('dd');
  dd.textContent = value;
  const group = document.createElement('div');  // HTML allows a div around each dt/dd pair
  if (title) group.title = title;
  group.append(dt, dd);
  dl.append(group);
}

/** The summary line of a result (2D or 3D): converged, needs review, or not converged. */
export function renderHeadline(r) {
  const summary = $('job-summary');
  const review = r.converged && r.review_required;
  summary.className = review ? 'review' : r.converged ? 'ok' : 'error';
  summary.textContent = review
    ? `Converged in ${r.iterations} iterations, but the answer needs review: see the warnings below.`
    : r.converged
      ? `Converged in ${r.iterations} iterations (${r.method ?? 'solver'}).`
      : `Did not converge: ${(r.message ?? `stopped after ${r.iterations} iterations`).replace(/\.$/, '')}.`;
}

/** Summary line, key numbers, warnings and download links of a result. */
export function renderSummary(job, view) {
  const r = view.result;
  const contact = r.contact ?? { x: [], s: [], pressure: [], active: [], force: [0, 0] };
  renderHeadline(r);

  const units = resultUnits(r);
  const dl = $('key-numbers');
  dl.innerHTML = '';
  const force = contact.force ?? [NaN, NaN];
  addNumber(dl, 'Contact force (Fx, Fy)', `${fmt(force[0])}, ${fmt(force[1])}${unitSuffix(units, 'F')}`,
    units.declared ? `per ${units.L} of thickness (plane strain)` : 'per unit thickness (plane strain; the case declares no units)');
  const hasContact = (contact.x?.length ?? 0) > 0;
  // The one definition of the contact width: contact.zone.width of the result (docs/result-format.md).
  const zone = contact.zone ?? {};
  const width = zone.width ?? NaN;
  const widthText = `${fmt(width)}${unitSuffix(units, 'L')}`;
  addNumber(
    dl,
    'Contact width',
    !hasContact ? '— (no contact boundary)' : view.hertz ? `${widthText} (Hertz 2a = ${fmt(2 * view.hertz.a)})` : widthText,
    'contact.zone.width: the zone\'s length along the boundary, each front where the pressure reaches zero' +
      (zone.end_edge_length ? ` (edges of ${fmt(zone.end_edge_length, 3)} at the zone\'s ends; the loaded edges span ${fmt(zone.length)})` : ''),
  );
  const pmax = hasContact ? zone.peak_pressure ?? Math.max(...contact.pressure) : NaN;
  const pmaxText = `${fmt(pmax)}${unitSuffix(units, 'S')}`;
  addNumber(dl, 'Peak pressure', view.hertz ? `${pmaxText} (Hertz p0 = ${fmt(view.hertz.p0)})` : pmaxText);
  addNumber(dl, 'Iterations', `${r.iterations}${r.converged ? '' : ' (not converged)'}`);
  addNumber(dl, 'Final KKT residual', fmt(r.final_kkt_residual, 3));
  addNumber(dl, 'Levels', String(r.levels));
  addNumber(dl, 'DOFs', String(r.dofs), r.dofs_total ? `${r.dofs_total} including constrained` : undefined);
  const adaptivity = r.adaptivity;
  if (adaptivity) {
    addNumber(dl, 'Adaptive steps', `${adaptivity.steps?.length ?? 0} (stopped: ${adaptivity.stop_reason ?? '—'})`,
      `Dörfler marking θ = ${adaptivity.theta}; the numbers here are the last step's. ${adaptivity.stop_message ?? ''}`);
  }
  const accuracy = accuracyNumber(r.accuracy);
  if (accuracy) addNumber(dl, 'Force accuracy', ...accuracy);
  addNumber(dl, 'Active contact edges', `${contact.active?.filter(Boolean).length ?? 0} of ${contact.active?.length ?? 0}`);
  for (const [term, value, title] of frictionNumbers(r, view.caseDoc)) addNumber(dl, term, value, title);
  addNumber(dl, 'Time', `${seconds(r.timing?.total_s)} (solve ${seconds(r.timing?.solve_s)})`,
    `mesh ${seconds(r.timing?.mesh_s)}, assembly ${seconds(r.timing?.assembly_s)}`);

  renderWarnings(r);
  setDownloads(job);
  setCsvLink($('download-contact-csv'), contactCsv(r.contact), `job-${job.id}-contact.csv`);
  $('sweep-csv-item').hidden = !r.sweep;
  if (r.sweep) setCsvLink($('download-sweep-csv'), sweepCsv(r.sweep), `job-${job.id}-sweep.csv`);
}

/** The result's warnings, a review warning marked "Check this answer". */
export function renderWarnings(r) {
  const warnings = $('job-warnings');
  warnings.innerHTML = '';
  // warning_details carries each warning's code and whether it questions the answer.
  const details = r.warning_details ?? (r.warnings ?? []).map((message) => ({ message }));
  for (const w of details) {
    const li = document.createElement('li');
    if (w.code) li.dataset.code = w.code;
    if (w.review) {
      li.className = 'review';
      const strong = document.createElement('strong');
      strong.textContent = 'Check this answer: ';
      li.append(strong);
    }
    li.append(w.message);
    warnings.append(li);
  }
}

/** The links to the result JSON and the VTU of the job. */
export function setDownloads(job) {
  $('download-result').href = api.resultUrl(job.id);
  $('download-result').download = `job-${job.id}-result.json`;
  $('download-vtu').href = api.solutionUrl(job.id);
  $('download-vtu').download = `job-${job.id}.vtu`;
}

/** Points `link` at a CSV made in the browser (the previous one's memory is released). */
export function setCsvLink(link, text, filename) {
  if (link.href.startsWith('blob:')) URL.revokeObjectURL(link.href);
  link.href = URL.createObjectURL(new Blob([text], { type: 'text/csv' }));
  link.download = filename;
}

/** The charts of the view (and of the job compared with, when one is chosen). */
export function drawCharts(view, plots) {
  for (const chart of view.charts) chart.destroy();
  view.charts = [];
  const contact = view.result.contact ?? { x: [], s: [], pressure: [], gap: [] };
  const abscissa = $('pressure-abscissa').value;
  const pressureBox = $('pressure-plot');
  const residualBox = $('residual-plot');
  pressureBox.innerHTML = '';
  residualBox.innerHTML = '';
  const note = $('hertz-note');
  if (!plots) {
    pressureBox.textContent = residualBox.textContent = 'No plots: the plotting library is missing.';
    return;
  }
  const compare = view.compare?.result.contact?.x?.length ? { label: view.compare.label, contact: view.compare.result.contact } : null;
  if (!contact.x?.length) {
    pressureBox.textContent = 'This case has no contact boundary.';
    pressureBox.dataset.points = '0';
    note.textContent = '';
  } else {
    view.charts.push(plots.boundaryPlot(pressureBox, contact, { hertz: view.hertz, abscissa, compare, units: resultUnits(view.result) }));
    note.textContent = view.hertz
      ? `Dashed red: plane-strain Hertz pressure for F = |Fy| = ${fmt(view.hertz.F)}, ` +
        `R = ${fmt(view.hertz.R)}, E* = ${fmt(view.hertz.Estar)}: a = ${fmt(view.hertz.a)}, p0 = ${fmt(view.hertz.p0)}` +
        (abscissa === 'x' ? '.' : ' (shown against x only).')
      : '';
  }
  drawSweep(view, plots);
  drawAdaptivity(view, plots);
  drawFriction(view, plots);
  drawLoadSteps(view, plots);
  drawResiduals(view, plots);
}

/** The residual history of the result, or the words saying there is none. */
export function drawResiduals(view, plots) {
  const residualBox = $('residual-plot');
  residualBox.innerHTML = '';
  const history = view.result.history ?? [];
  if (history.length) view.charts.push(plots.residualPlot(residualBox, history));
  else {
    residualBox.textContent = 'No iterations were recorded.';
    residualBox.dataset.points = '0';
  }
}

/** A case with a sweep (2D or 3D): the force of every point against the swept value (docs/web.md). */
export function drawSweep(view, plots) {
  const sweep = view.result.sweep;
  $('sweep-figure').hidden = !sweep;
  const box = $('sweep-plot');
  box.innerHTML = '';
  if (!sweep) return;
  const other = view.compare?.result.sweep;
  const dimension = view.result.dimension === 3 ? 3 : 2;
  view.charts.push(plots.sweepPlot(box, sweep, other ? { label: view.compare.label, sweep: other } : null, dimension));
  const bad = sweep.points.filter((p) => !p.converged).length;
  $('sweep-note').textContent = `${sweep.points.length} points of ${sweep.pointer}, each started from the previous solution` +
    (bad ? `; ${bad} did not converge (red).` : '; all converged.') +
    (other ? ` Dashed: ${view.compare.label} (${other.points.length} points of ${other.pointer}).` : '');
}

/** An adaptive run (2D or 3D): estimator and force change against the unknowns, and the steps' table. */
export function drawAdaptivity(view, plots) {
  const steps = view.result.adaptivity?.steps;
  $('adaptivity-section').hidden = !steps?.length;
  const box = $('adaptivity-plot');
  box.innerHTML = '';
  if (!steps?.length) return;
  const rows = adaptiveRows(steps);
  const dimension = view.result.dimension === 3 ? 3 : 2;
  view.charts.push(plots.adaptivityPlot(box, rows, dimension));
  renderStepTable($('adaptivity-table'), rows, dimension);
  const last = rows[rows.length - 1];
  const first = rows[0];
  $('adaptivity-note').textContent =
    `${rows.length} solves from ${first.dofs} to ${last.dofs} unknowns; J^½ fell from ${fmt(first.estimator)} to ${fmt(last.estimator)}` +
    (rows.length > 1 ? ` and the force changed by ${fmt(100 * last.forceChange, 2)} % in the last step.` : '.') +
    (dimension === 3 ? ' The surface below is the last step\'s.' : ' The mesh below is the last step\'s (colour by refinement generation or the error indicator).') +
    // Why the loop stopped and what adaptivity.target means (a reduction of J^½, not an accuracy).
    (view.result.adaptivity.stop_message ? ` ${view.result.adaptivity.stop_message.replace(/^stopped/, 'It stopped')}.` : '');
}

/** The colour bar's words for a unit id (the declared unit when the case has one), with the case's μ when the unit is a stress. */
export function unitText(unit, result) {
  const units = resultUnits(result);
  const name = unit in units ? units[unit] : UNITS[unit];
  const mu = result.material?.mu;
  return unit === 'S' && typeof mu === 'number' ? `${name}; here μ = ${fmt(mu)}` : name;
}

/**
 * The colour bar under a view: its ends, its gradient and what it shows, in the elements
 * `${prefix}-min`, `${prefix}-max`, `${prefix}-bar` and `${prefix}-label`.
 */
export function writeColourBar(prefix, label, units, scale, range) {
  $(`${prefix}-min`).textContent = fmt(scale.min, 3);
  $(`${prefix}-max`).textContent = fmt(scale.max, 3);
  $(`${prefix}-bar`).style.background = colourGradientCss(scale.map);
  $(`${prefix}-label`).textContent = `${label}, in ${units}` +
    (scale.map === 'coolwarm' ? `; blue < 0 < red, symmetric about 0 (values from ${fmt(range.min, 3)} to ${fmt(range.max, 3)})` : '');
}

/**
 * The start of drawing a mesh figure (2D or 3D): without a mesh its canvas is hidden, its
 * caption says why, and the answer is null; otherwise the magnification to draw with (the
 * automatic one when `resetMagnification`, written into the input).
 */
export function figureMagnification(view, { canvas, caption, input }, resetMagnification) {
  if (!view.mesh) {
    canvas.hidden = true;
    caption.textContent = view.meshError ?? 'No solution file.';
    return null;
  }
  canvas.hidden = false;
  if (resetMagnification) input.value = String(autoMagnification(view.mesh));
  return Math.max(0, Number(input.value) || 0);
}

/** Colours the mesh viewer by the chosen field and writes the colour bar and caption. */
export function drawMeshView(view, viewer, { resetMagnification = false } = {}) {
  const canvas = $('mesh-canvas');
  const caption = $('mesh-caption');
  const magnification = figureMagnification(view, { canvas, caption, input: $('mesh-magnification') }, resetMagnification);
  if (magnification === null) return;
  const field = MESH_FIELDS[$('mesh-field').value];
  const values = field.compute(view.mesh);
  if (!values) {
    caption.textContent = `The solution file has no ${field.label}.`;
    return;
  }
  const range = valueRange(values);
  const scale = colourScale(range, field.signed);
  const units = unitText(field.unit, view.result);
  viewer.setMagnification(magnification);
  viewer.setField({ label: field.label, unitText: units, values, scale });
  writeColourBar('legend', field.label, units, scale, range);
  const nTriangles = view.mesh.triangles.length / 3;
  canvas.dataset.triangles = String(nTriangles);
  Object.assign(canvas.dataset, { field: $('mesh-field').value, min: String(range.min), max: String(range.max), colourMap: scale.map });
  canvas.setAttribute('aria-label',
    `Deformed mesh of ${nTriangles} triangles coloured by ${field.label} from ${fmt(range.min, 3)} to ${fmt(range.max, 3)}, displacement magnified ${magnification} times`);
  caption.textContent = `${nTriangles} triangles, coloured by ${field.label} (per triangle). ` +
    `Displacement magnified ×${magnification}; dashed: the undeformed outline. ` +
    'Wheel or + / − zooms, drag or the arrow keys pan, 0 resets.';
}
