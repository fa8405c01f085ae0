// The job view of a 3D result (`dimension` 3, docs/result-format.md "3D results"): key
// numbers, warnings and downloads as in 2D, the residual history, the deformed boundary
// surface coloured by a field (surface_viewer.js) and the contact pressure along a line in the
// contact plane with 3D Hertz for the builtin half ball. The 2D-only parts of the job view
// are hidden by #job-result[data-dimension="3"] (style.css).
import { accuracyNumber } from './accuracy.js';
import {
  addNumber, drawAdaptivity, drawResiduals, drawSweep, figureMagnification, renderHeadline, renderWarnings, setCsvLink, setDownloads, unitText, writeColourBar,
} from './job_result.js';
import { planeFrame, pressureCentre, sampleLine, sphereTangentPlane } from './contact_line.js';
import { contactFaces, boundarySurface } from './tet_surface.js';
import { contactPlanes, contactSpheres } from './hertz.js';
import { SURFACE_FIELDS, shownRange } from './surface_fields.js';
import { colourScale } from './mesh_view.js';
import { lineCsv, sweepCsv } from './csv_export.js';
import { fmt, seconds } from './format.js';

const $ = (id) => document.getElementById(id);

/**
 * What the 3D view needs from the VTU and the case: the surface and its contact faces (as
 * vertex triples), the contact plane and its frame and the line's centre, as view.solid. Sets
 * view.meshError instead when the file is not a tetrahedral mesh; throws on an invalid one.
 */
export function prepare3d(view) {
  const { mesh, caseDoc } = view;
  if (mesh.dimension !== 3) {
    view.meshError = 'The solution file holds triangles, not the tetrahedra of a 3D result.';
    view.mesh = null;
    return;
  }
  const surface = boundarySurface(mesh);
  const contact = contactFaces(mesh, surface);
  const faces = [];
  for (let f = 0; f < contact.length; f++) if (contact[f]) faces.push([...surface.triangles.subarray(3 * f, 3 * f + 3)]);
  // The plane of the contact groups (the first when there are several; they share the drawing);
  // against a sphere, its tangent plane at the contact.
  const pressure = mesh.pointData.contact_pressure?.values;
  const flags = mesh.pointData.contact_boundary?.values;
  const sphere = contactSpheres(caseDoc)[0];
  const plane = contactPlanes(caseDoc)[0] ??
    (sphere && pressure && flags ? sphereTangentPlane(mesh.points3, flags, pressure, sphere) : null);
  const frame = plane ? planeFrame(plane.normal) : null;
  const centre = frame && pressure && flags ? pressureCentre(mesh.points3, flags, pressure, plane) : null;
  view.solid = { surface, contact, faces, plane, frame, centre, nContact: faces.length };
}

/** Summary line, the 3D key numbers, warnings and downloads. */
export function renderSummary3d(job, view) {
  const r = view.result;
  const c = r.contact ?? {};
  const h = view.hertz;
  renderHeadline(r);
  const dl = $('key-numbers');
  dl.innerHTML = '';
  const force = Array.isArray(c.force) ? c.force : [];
  addNumber(dl, 'Contact force (Fx, Fy, Fz)', [0, 1, 2].map((k) => fmt(force[k])).join(', '),
    "∫σn dA over the contact groups: the plane's force on the body, in the case's units");
  addNumber(dl, 'Peak pressure', `${fmt(c.max_pressure)}${h ? ` (Hertz p0 = ${fmt(h.p0)})` : ''}`,
    'contact.max_pressure: the largest face pressure −σ_nn (one value per contact face)');
  addNumber(dl, 'Contact area', fmt(c.area), 'contact.area: the area of the contact faces with pressure > 0, each counted whole');
  const zone = c.zone ?? {};
  const mirrored = zone.symmetry_planes > 0 ? `, the whole zone across ${zone.symmetry_planes} symmetry plane${zone.symmetry_planes > 1 ? 's' : ''}` : '';
  addNumber(dl, 'Contact radius', `${fmt(zone.radius)}${mirrored}${h ? ` (Hertz a = ${fmt(h.a)})` : ''}`,
    "contact.zone.radius: the radius of the disc of the zone's area, its front located within the faces, mirrored across the symmetry planes it lies against");
  addNumber(dl, 'Contact faces in contact', `${c.faces_in_contact ?? '—'} of ${c.faces ?? '—'}`);
  const accuracy = accuracyNumber(r.accuracy);
  if (accuracy) addNumber(dl, 'Force accuracy', ...accuracy);
  addNumber(dl, 'Iterations', `${r.iterations}${r.converged ? '' : ' (not converged)'}`);
  addNumber(dl, 'Relative KKT residual', fmt(r.relative_kkt_residual, 3), `the final KKT residual over the initial one (tolerance ${fmt(r.tolerance, 3)})`);
  addNumber(dl, 'Levels', String(r.levels));
  addNumber(dl, 'DOFs', String(r.dofs));
  addNumber(dl, 'Tetrahedra', `${r.tetrahedra} (${r.vertices} vertices)`);
  addNumber(dl, 'Time', `${seconds(r.timing?.total_s)} (solve ${seconds(r.timing?.solve_s)})`,
    `mesh ${seconds(r.timing?.mesh_s)}, assembly ${seconds(r.timing?.assembly_s)}`);
  renderWarnings(r);
  setDownloads(job);
  $('sweep-csv-item').hidden = !r.sweep;
  if (r.sweep) setCsvLink($('download-sweep-csv'), sweepCsv(r.sweep, 3), `job-${job.id}-sweep.csv`);
}

/** The residual history (in view.charts) and the pressure line (view.lineChart, redrawn alone when θ changes). */
export function drawCharts3d(view, plots, viewer) {
  for (const chart of view.charts) chart.destroy();
  view.charts = [];
  view.lineChart?.destroy();
  view.lineChart = null;
  const box = $('line-plot');
  box.innerHTML = '';
  box.dataset.points = '0';
  if (!plots) {
    box.textContent = $('residual-plot').textContent = 'No plots: the plotting library is missing.';
    return;
  }
  drawResiduals(view, plots);
  drawAdaptivity(view, plots);
  drawSweep(view, plots);
  drawLine(view, plots, viewer);
}

/** The pressure along the chosen line: the chart, its note and CSV, and the line in the 3D view. */
export function drawLine(view, plots, viewer) {
  const box = $('line-plot');
  const note = $('line-note');
  const solid = view.solid;
  view.lineChart?.destroy();
  view.lineChart = null;
  box.innerHTML = '';
  box.dataset.points = '0';
  if (!solid?.centre || solid.faces.length === 0) {
    box.textContent = view.meshError ?? (solid?.plane ? 'The solution has no contact faces with a pressure.' : 'The case names no plane or sphere obstacle: the pressure line runs in a plane.');
    note.textContent = '';
    view.lineSamples = [];
    viewer.setLine(null);
    return;
  }
  const theta = Number($('line-angle').value) || 0;
  const samples = sampleLine({
    points3: view.mesh.points3, faces: solid.faces, values: view.mesh.pointData.contact_pressure.values,
    frame: solid.frame, centre: solid.centre, thetaDegrees: theta,
  });
  view.lineSamples = samples;
  box.dataset.theta = String(theta);
  if (samples.length === 0) {
    box.textContent = 'The line misses the contact faces.';
  } else if (plots) {
    view.lineChart = plots.linePlot(box, samples, { hertz: view.hertz });
  }
  const h = view.hertz;
  const [t1, c] = [solid.frame.t1, solid.centre];
  note.textContent = `The line through (${c.map((x) => fmt(x)).join(', ')}) at θ = ${fmt(theta)}° from t1 = (${t1.map((x) => fmt(x, 3)).join(', ')}), ` +
    'in the contact plane; the pressure of the contact faces projected onto the plane, interpolated linearly from the vertex values ' +
    '(each the mean of its faces\' values, so below the peak face value).' +
    (h ? ` Dashed red: 3D Hertz for F = |F·n| = ${fmt(h.F)}, R = ${fmt(h.R)}, E* = ${fmt(h.Estar)}: a = ${fmt(h.a)}, p0 = ${fmt(h.p0)}.` : '');
  setCsvLink($('download-line-csv'), lineCsv(samples, h), `job-${view.id}-line-${fmt(theta)}deg.csv`);
  viewer.setLine(linePoints(samples));
}

/** The drawn part of the line as x, y, z triples, a NaN triple where it leaves the contact faces. */
function linePoints(samples) {
  return Float64Array.from(samples.flatMap((x) => (x.value === null ? [NaN, NaN, NaN] : x.point)));
}

/** Colours the 3D view by the chosen field and writes its colour bar, caption and description. */
export function drawSurfaceView(view, viewer, { resetMagnification = false } = {}) {
  const canvas = $('surface-canvas');
  const caption = $('surface-caption');
  // prepare3d leaves view.solid for every mesh it keeps.
  const magnification = figureMagnification(view, { canvas, caption, input: $('surface-magnification') }, resetMagnification);
  if (magnification === null) return;
  const id = $('surface-field').value;
  const field = SURFACE_FIELDS[id];
  const { surface, contact, frame, nContact } = view.solid;
  const coloured = field.compute(view.mesh, surface, { contact, normal: frame?.n });
  if (!coloured) {
    // Not the previous job's colours on this job's surface: a blank view and colour bar.
    viewer.setField(null);
    for (const part of ['min', 'max', 'label']) $(`surface-legend-${part}`).textContent = '';
    $('surface-legend-bar').style.background = 'none';
    caption.textContent = `The solution file has no ${field.label}${frame ? '' : ' (or the case no contact plane)'}.`;
    return;
  }
  const found = shownRange(surface, coloured);
  const range = field.fromZero ? { min: 0, max: Math.max(0, found.max) } : found;
  const scale = colourScale(range, field.signed);
  const units = unitText(field.unit, view.result);
  viewer.setMagnification(magnification);
  viewer.setField({ ...coloured, scale });
  writeColourBar('surface-legend', field.label, units, scale, range);
  const nTriangles = surface.triangles.length / 3;
  Object.assign(canvas.dataset, {
    triangles: String(nTriangles), contactTriangles: String(nContact), field: id,
    min: String(range.min), max: String(range.max), colourMap: scale.map,
  });
  const what = `${nTriangles} boundary triangles (${nContact} contact faces) of ${view.mesh.tetrahedra.length / 4} tetrahedra`;
  canvas.setAttribute('aria-label', `Deformed surface, ${what}, coloured by ${field.label} from ${fmt(range.min, 3)} to ${fmt(range.max, 3)}, ` +
    `displacement magnified ${magnification} times, seen from the contact plane's side`);
  caption.textContent = `${what}, coloured by ${field.label} (${coloured.vertexValues ? 'interpolated from the vertex values' : 'per triangle'}` +
    `${id === 'contact_pressure' ? '; grey: off the contact' : ''}). Displacement magnified ×${magnification}; ` +
    'the black line is the pressure line, in the contact plane. Drag or the arrow keys turn, wheel or + / − zooms, 0 resets.';
}
