// The page: wires the case editor, the job list and the job view to the service's API.
import * as api from './api.js';
import { CaseEditor } from './case_editor.js';
import { hertzForResult, hertzForResult3d } from './hertz.js';
import { hasTresca } from './friction.js';
import { parseVtu } from './vtu.js';
import { fmt, setStatus, stepPrefix } from './format.js';
import { MESH_FIELDS } from './mesh_fields.js';
import { MeshViewer } from './mesh_viewer.js';
import { drawCharts, drawMeshView, renderSummary } from './job_result.js';
import { CompareSelect } from './compare_select.js';
import { SurfaceViewer } from './surface_viewer.js';
import { SURFACE_FIELDS } from './surface_fields.js';
import { drawCharts3d, drawLine, drawSurfaceView, prepare3d, renderSummary3d } from './job_view3d.js';
import { isActive, renderJobTable } from './job_table.js';

const $ = (id) => document.getElementById(id);

// The plots need uPlot from web/dist (web/build.sh). Loaded apart so that without it the
// editor and the job list still work and the page says what is missing.
let plots = null;
const plotsReady = Promise.all([import('./plots.js'), import('./friction_plots.js')])
  .then(([charts, frictionCharts]) => {
    plots = { ...charts, ...frictionCharts };
  })
  .catch(() => {
    setStatus($('service-status'), 'The plotting library is missing on the server: run web/build.sh.', 'error');
  });

const POLL_ACTIVE_MS = 1000;   // while a job is queued or running
const POLL_IDLE_MS = 5000;     // to notice jobs submitted elsewhere (curl, another tab)

const state = {
  jobs: [],
  jobsSignature: '',
  selectedId: null,
  view: null,  // {id, state, result, mesh, charts: []} of the job shown
  pollTimer: 0,
  unreachable: false,  // the last poll failed: its message is in #service-status
};

const editor = new CaseEditor({
  textarea: $('case-text'),
  backdrop: document.querySelector('#case-editor .backdrop'),
  gutter: document.querySelector('#case-editor .gutter'),
  errorList: $('case-error-list'),
  errorBox: $('case-errors'),
});

// ---- case editor ------------------------------------------------------------------------

async function loadExamples() {
  const select = $('example-select');
  let examples = [];
  try {
    const response = await fetch('dist/examples.json');
    if (response.ok) examples = await response.json();
  } catch {
    // handled below
  }
  if (!Array.isArray(examples) || examples.length === 0) {
    setStatus($('submit-status'), 'The shipped examples are missing (run web/build.sh).', 'error');
    return;
  }
  // The 3D cases (web/scripts/make_examples.mjs marks them) in a group of their own after the 2D ones.
  const solidGroup = document.createElement('optgroup');
  solidGroup.label = '3D';
  for (const ex of examples) {
    const option = document.createElement('option');
    option.value = ex.name;
    option.textContent = ex.name;
    (ex.dimension === 3 ? solidGroup : select).append(option);
  }
  if (solidGroup.children.length) select.append(solidGroup);
  const byName = new Map(examples.map((ex) => [ex.name, ex.text]));
  const load = () => {
    editor.text = byName.get(select.value) ?? '';
    editor.clearProblems();
    setStatus($('submit-status'), '');
  };
  $('load-example').addEventListener('click', load);
  select.value = byName.has('hertz') ? 'hertz' : examples[0].name;
  if (!editor.text.trim()) load();
}

async function submitCase() {
  const button = $('submit-case');
  const status = $('submit-status');
  const text = editor.text;
  button.disabled = true;
  setStatus(status, 'Submitting…');
  try {
    const response = await api.submitCase(text);
    if (response.status === 202 || response.status === 200) {
      const job = response.body;
      editor.clearProblems();
      setStatus(status, `Job ${job.id} queued.`, 'ok');
      await refreshJobs();
      selectJob(job.id, { focus: false });
    } else if (response.status === 422 && Array.isArray(response.body?.errors)) {
      editor.showProblems(response.body.errors);
      const n = response.body.errors.length;
      setStatus(status, `Not submitted: ${n} ${n === 1 ? 'problem' : 'problems'} in the case (listed above).`, 'error');
    } else if (response.status === 400) {
      // nlohmann's parse errors say "at line L, column C".
      const detail = api.problemMessage(response);
      const where = /line (\d+), column (\d+)/.exec(detail);
      if (where) editor.showSyntaxError(Number(where[1]), Number(where[2]), detail);
      else editor.clearProblems();
      setStatus(status, `Not submitted: ${detail}`, 'error');
    } else {
      setStatus(status, `Not submitted (${response.status}): ${api.problemMessage(response)}`, 'error');
    }
  } catch {
    setStatus(status, 'Cannot reach the service.', 'error');
  } finally {
    button.disabled = false;
  }
}

// ---- job list ---------------------------------------------------------------------------

function renderJobs() {
  renderJobTable(document.querySelector('#job-table tbody'), state.jobs, state.selectedId);
  $('jobs-empty').hidden = state.jobs.length > 0;
  // The job compared with was deleted: draw without it.
  if (compareSelect.update(state.jobs, state.selectedId) && state.view?.compare) compareWith(null);
}

// One poll at a time: a refresh asked for while one is in flight runs once after it (its
// answer may predate the change the caller made), and only the last poll arms the timer.
let pollInFlight = null;
let pollQueued = null;

function refreshJobs() {
  if (!pollInFlight) {
    pollInFlight = pollJobs().finally(() => {
      pollInFlight = null;
    });
    return pollInFlight;
  }
  pollQueued ??= pollInFlight.then(() => {
    pollQueued = null;
    return refreshJobs();
  });
  return pollQueued;
}

async function pollJobs() {
  try {
    const response = await api.listJobs();
    if (response.ok) {
      $('jobs-error').hidden = true;
      state.jobs = response.body.jobs ?? [];
      const signature = JSON.stringify(state.jobs);
      if (signature !== state.jobsSignature) {
        state.jobsSignature = signature;
        renderJobs();
      }
      const selected = state.jobs.find((j) => j.id === state.selectedId);
      if (selected) showJob(selected);
      if (state.unreachable) setStatus($('service-status'), '');
      state.unreachable = false;
    } else {
      $('jobs-error').hidden = false;
      $('jobs-error').textContent = `Cannot list jobs: ${api.problemMessage(response)}`;
    }
  } catch {
    state.unreachable = true;
    setStatus($('service-status'), 'The service does not answer; retrying…', 'error');
  }
  const delay = state.jobs.some(isActive) ? POLL_ACTIVE_MS : POLL_IDLE_MS;
  clearTimeout(state.pollTimer);
  state.pollTimer = setTimeout(refreshJobs, delay);
}

async function onJobAction(event) {
  const button = event.target.closest('button[data-action]');
  if (!button) return;
  const id = Number(button.dataset.jobId);
  if (button.dataset.action === 'view') {
    selectJob(id, { focus: true });
    return;
  }
  button.disabled = true;
  try {
    const response = button.dataset.action === 'cancel' ? await api.cancelJob(id) : await api.deleteJob(id);
    if (!response.ok) {
      setStatus($('service-status'), `Job ${id}: ${api.problemMessage(response)}`, 'error');
    } else if (button.dataset.action === 'delete') {
      if (state.selectedId === id) selectJob(null);
      // Keep the keyboard in the list: focus the next row's name (or the previous one).
      const row = button.closest('tr');
      const neighbour = row?.nextElementSibling ?? row?.previousElementSibling;
      const target = neighbour?.querySelector('[data-action="view"]');
      if (target) target.focus();
      else $('case-text').focus();
    }
  } catch {
    setStatus($('service-status'), 'Cannot reach the service.', 'error');
  }
  await refreshJobs();
}

// ---- job view ---------------------------------------------------------------------------

function selectJob(id, { focus = false } = {}) {
  state.selectedId = id;
  history.replaceState(null, '', id === null ? location.pathname : `#job-${id}`);
  renderJobs();
  const job = state.jobs.find((j) => j.id === id);
  if (job) showJob(job);
  else clearView();
  if (focus) $('job-view').focus();
}

function clearView() {
  destroyCharts();
  state.view = null;
  $('job-heading').textContent = 'No job selected';
  $('job-summary').textContent = 'Submit a case, or choose a job in the list.';
  $('job-error').hidden = true;
  $('job-result').hidden = true;
  $('open-case').hidden = true;
}

function destroyCharts() {
  for (const chart of state.view?.charts ?? []) chart.destroy();
  state.view?.lineChart?.destroy();
  if (state.view) Object.assign(state.view, { charts: [], lineChart: null });
  destroyLiveChart();
}

function destroyLiveChart() {
  state.view?.liveChart?.destroy();
  if (state.view) state.view.liveChart = null;
  $('live-figure').hidden = true;
  $('live-plot').innerHTML = '';
  $('live-plot').dataset.points = '0';
}

// While a job runs the service reports only its latest iteration; the samples seen by the
// polls make a coarse residual history until the full one arrives with the result. A job of
// several solves counts iterations from 0 in each: the chart follows the one running.
function updateLiveChart(job) {
  const view = state.view;
  const step = job.progress?.step ?? 0;
  if (view.samplesStep !== step) Object.assign(view, { samples: [], samplesStep: step, liveDrawn: 0 });
  const samples = (view.samples ??= []);
  const last = samples[samples.length - 1];
  if (job.progress && (!last || job.progress.iteration > last.iteration)) {
    samples.push({ iteration: job.progress.iteration, kkt_residual: job.progress.kkt_residual });
  }
  if (!plots || samples.length === 0 || (view.liveChart && view.liveDrawn === samples.length)) return;
  $('live-figure').hidden = false;
  view.liveChart?.destroy();
  $('live-plot').innerHTML = '';
  view.liveChart = plots.residualPlot($('live-plot'), samples, { correction: false });
  view.liveDrawn = samples.length;
}

function showJob(job) {
  const previous = state.view;
  const same = previous && previous.id === job.id && previous.createdAt === job.created_at;
  if (same && previous.state === job.state && job.state !== 'running' && job.state !== 'queued') return;
  if (!same) {
    destroyCharts();
    state.view = { id: job.id, createdAt: job.created_at, state: job.state, charts: [] };
    $('job-result').hidden = true;
    $('open-case').hidden = false;
    compareSelect.update(state.jobs, job.id);
    compareSelect.clear();
  }
  state.view.state = job.state;
  if (job.state !== 'running') destroyLiveChart();
  $('job-heading').textContent = `Job ${job.id} · ${job.name}`;
  const summary = $('job-summary');
  summary.className = '';
  $('job-error').hidden = true;
  switch (job.state) {
    case 'queued':
      summary.textContent = 'Queued: waiting for a worker.';
      break;
    case 'running':
      summary.textContent = job.progress
        ? `Running: ${stepPrefix(job.progress)}iteration ${job.progress.iteration}, KKT residual ${fmt(job.progress.kkt_residual, 3)}.`
        : 'Running: setting up (mesh, assembly).';
      updateLiveChart(job);
      break;
    case 'failed':
      summary.textContent = 'Failed.';
      summary.className = 'error';
      $('job-error').textContent = job.error ?? 'no reason given';
      $('job-error').hidden = false;
      // Failed for not converging (--fail-unconverged): the last iterate is kept; show it.
      if (job.converged === false) loadResult(job);
      break;
    case 'cancelled':
      // A job with load steps keeps the steps solved before the cancel (converged false).
      if (job.converged === false) {
        summary.textContent = 'Cancelled: the load steps solved before the cancel are kept. Loading them…';
        loadResult(job);
      } else {
        summary.textContent = 'Cancelled: there is no result.';
      }
      break;
    case 'succeeded':
      summary.textContent = 'Succeeded. Loading the result…';
      loadResult(job);
      break;
    default:
      summary.textContent = job.state;
  }
}

async function loadResult(job) {
  const view = state.view;
  try {
    const [resultResponse, vtuResponse] =
      await Promise.all([api.getResult(job.id), api.getSolution(job.id), plotsReady]);
    if (state.view !== view) return;  // another job was chosen meanwhile
    if (!resultResponse.ok) {
      $('job-summary').textContent = `The result cannot be loaded: ${api.problemMessage(resultResponse)}`;
      $('job-summary').className = 'error';
      return;
    }
    view.result = resultResponse.body;
    const solid = view.result?.dimension === 3;
    $('job-result').dataset.dimension = solid ? '3' : '2';
    if (solid) {
      await showResult3d(job, view, vtuResponse);
      return;
    }
    // Offered by the contact boundary's shape: an arc against a plane (docs/web.md).
    view.hertz = hertzForResult(view.result);
    view.mesh = null;
    view.meshError = null;
    // A Tresca bound is in the case only (a number or an expression): the friction summary names it.
    if (hasTresca(view.result)) {
      const caseResponse = await api.getCase(job.id);
      if (state.view !== view) return;
      view.caseDoc = caseResponse.ok ? caseResponse.body : null;
    }
    if (vtuResponse.ok) {
      try {
        view.mesh = parseVtu(vtuResponse.body);
        if (view.mesh.dimension === 3) throw new Error('it holds tetrahedra, and the result is 2D');
      } catch (e) {
        view.mesh = null;
        view.meshError = `The solution file cannot be read: ${e.message}`;
      }
    } else {
      view.meshError = `No solution file: ${api.problemMessage(vtuResponse)}`;
    }
    renderSummary(job, view);
    $('job-result').hidden = false;  // charts measure their container: show it first
    drawCharts(view, plots);
    if (view.mesh) viewer.setMesh(view.mesh);
    drawMeshView(view, viewer, { resetMagnification: true });
  } catch {
    $('job-summary').textContent = 'Cannot reach the service to load the result.';
  }
}

// A 3D result (docs/web.md, "3D jobs"): its case gives the contact plane and the half ball's
// radius; the VTU the surface. Problems with either end in the figure's caption, never a throw.
async function showResult3d(job, view, vtuResponse) {
  const caseResponse = await api.getCase(job.id);
  if (state.view !== view) return;
  view.caseDoc = caseResponse.ok ? caseResponse.body : null;
  view.hertz = hertzForResult3d(view.result, view.caseDoc);
  Object.assign(view, { mesh: null, meshError: null, solid: null });
  if (vtuResponse.ok) {
    try {
      view.mesh = parseVtu(vtuResponse.body);
      prepare3d(view);
    } catch (e) {
      Object.assign(view, { mesh: null, solid: null, meshError: `The solution file cannot be read: ${e.message}` });
    }
  } else {
    view.meshError = `No solution file: ${api.problemMessage(vtuResponse)}`;
  }
  renderSummary3d(job, view);
  $('job-result').hidden = false;  // charts measure their container: show it first
  if (view.solid) {
    const { surface, frame, contact } = view.solid;
    surfaceViewer.setSurface({ mesh: view.mesh, surface, frame, contact });
  }
  drawSurfaceView(view, surfaceViewer, { resetMagnification: true });
  drawCharts3d(view, plots, surfaceViewer);
}

// A second job's result over the shown one's curves (docs/web.md, "Compare with"; 2D only).
async function compareWith(job) {
  const view = state.view;
  if (!view?.result || view.result.dimension === 3) return;
  view.compare = null;
  if (job) {
    const response = await api.getResult(job.id);
    if (state.view !== view) return;
    if (response.ok) view.compare = { label: `job ${job.id}`, result: response.body };
    else setStatus($('service-status'), `Job ${job.id}: ${api.problemMessage(response)}`, 'error');
  }
  drawCharts(view, plots);
}

// The case as the service stored it, byte for byte, back in the editor to change and resubmit.
async function openCase() {
  const id = state.view?.id;
  if (id === undefined) return;
  const response = await api.getCase(id, { accept: 'text' });
  if (!response.ok) {
    setStatus($('submit-status'), `Job ${id}'s case: ${api.problemMessage(response)}`, 'error');
    return;
  }
  editor.text = response.body;
  editor.clearProblems();
  setStatus($('submit-status'), `Job ${id}'s case is in the editor.`, 'ok');
  $('case-text').focus();
}

// ---- start ------------------------------------------------------------------------------

const viewer = new MeshViewer({ canvas: $('mesh-canvas'), probe: $('mesh-probe'), format: (v) => fmt(v, 5) });
const compareSelect = new CompareSelect($('compare-job'), compareWith);
const surfaceViewer = new SurfaceViewer({ canvas: $('surface-canvas') });

/** The 3D view's controls: colour, magnification, reset, and the line's angle. */
function listen3d() {
  for (const [id, field] of Object.entries(SURFACE_FIELDS)) $('surface-field').append(new Option(field.label, id));
  const redraw = (options) => state.view?.solid && drawSurfaceView(state.view, surfaceViewer, options);
  $('surface-field').addEventListener('change', () => redraw());
  $('surface-magnification').addEventListener('input', () => redraw());
  $('surface-auto').addEventListener('click', () => redraw({ resetMagnification: true }));
  $('surface-reset').addEventListener('click', () => surfaceViewer.resetView());
  $('line-angle').addEventListener('input', () => state.view?.solid && drawLine(state.view, plots, surfaceViewer));
  new ResizeObserver(() => surfaceViewer.redraw()).observe($('surface-canvas'));
}

function init() {
  for (const [id, field] of Object.entries(MESH_FIELDS)) $('mesh-field').append(new Option(field.label, id));
  $('submit-case').addEventListener('click', submitCase);
  $('case-text').addEventListener('keydown', (e) => {
    if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) {
      e.preventDefault();
      submitCase();
    }
  });
  document.querySelector('#job-table tbody').addEventListener('click', onJobAction);
  $('open-case').addEventListener('click', openCase);
  const redrawMesh = (options) => state.view?.mesh && drawMeshView(state.view, viewer, options);
  $('pressure-abscissa').addEventListener('change', () => state.view?.result && drawCharts(state.view, plots));
  $('load-step-select').addEventListener('change', (e) => {
    if (!state.view?.result) return;
    state.view.loadStep = Number(e.target.value);
    drawCharts(state.view, plots);
  });
  $('mesh-field').addEventListener('change', () => redrawMesh());
  $('mesh-magnification').addEventListener('input', () => redrawMesh());
  $('mesh-auto').addEventListener('click', () => redrawMesh({ resetMagnification: true }));
  $('mesh-edges').addEventListener('change', (e) => viewer.setEdges(e.target.checked));
  $('mesh-reset').addEventListener('click', () => viewer.resetView());
  new ResizeObserver(() => viewer.redraw()).observe($('mesh-canvas'));
  listen3d();

  const fromHash = /^#job-(\d+)$/.exec(location.hash);
  if (fromHash) state.selectedId = Number(fromHash[1]);
  loadExamples();
  refreshJobs();
}

init();
