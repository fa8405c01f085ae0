// The page: wires the case editor, the job list and the job view to the service's API.
import * as api from './api.js';
import { CaseEditor } from './case_editor.js';
import { caseFromResult, hertzForCase } from './hertz.js';
import { parseVtu } from './vtu.js';
import { MESH_FIELDS, autoMagnification, colourGradientCss, drawMesh } from './mesh_view.js';

const $ = (id) => document.getElementById(id);

// The plots need uPlot from web/dist (web/build.sh). Loaded apart so that without it the
// editor and the job list still work and the page says what is missing.
let plots = null;
const plotsReady = import('./plots.js')
  .then((module) => {
    plots = module;
  })
  .catch(() => {
    setStatus($('service-status'), 'The plotting library is missing on the server: run web/build.sh.', 'error');
  });

const POLL_ACTIVE_MS = 1000;   // while a job is queued or running
const POLL_IDLE_MS = 5000;     // to notice jobs submitted elsewhere (curl, another tab)
const CASE_KEY_PREFIX = 'fosls-case:';
const MAX_STORED_CASES = 100;

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

// ---- small helpers ----------------------------------------------------------------------

function fmt(v, digits = 4) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return '—';
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-3 && a < 1e5 ? String(Number(v.toPrecision(digits))) : v.toExponential(digits - 1);
}

function seconds(v) {
  return typeof v === 'number' ? `${v < 10 ? v.toFixed(2) : v.toFixed(1)} s` : '—';
}

function setStatus(element, text, kind = '') {
  element.textContent = text;
  element.classList.toggle('ok', kind === 'ok');
  element.classList.toggle('error', kind === 'error');
}

// The service keeps the case but does not return it with the job, so the browser remembers
// the cases it submitted (keyed by id and creation time: ids restart with a new database).
function caseKey(job) {
  return `${CASE_KEY_PREFIX}${job.id}:${job.created_at}`;
}

function rememberCase(job, text) {
  try {
    localStorage.setItem(caseKey(job), text);
    const keys = Object.keys(localStorage).filter((k) => k.startsWith(CASE_KEY_PREFIX));
    if (keys.length > MAX_STORED_CASES) {
      const id = (k) => Number(k.slice(CASE_KEY_PREFIX.length).split(':')[0]);
      keys.sort((a, b) => id(a) - id(b));
      for (const k of keys.slice(0, keys.length - MAX_STORED_CASES)) localStorage.removeItem(k);
    }
  } catch {
    // Storage full or disabled: only the Hertz overlay needs the case.
  }
}

function recalledCase(job) {
  try {
    const text = localStorage.getItem(caseKey(job));
    return text ? JSON.parse(text) : null;
  } catch {
    return null;
  }
}

function forgetCase(job) {
  try {
    localStorage.removeItem(caseKey(job));
  } catch {
    // nothing stored
  }
}

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
  for (const ex of examples) {
    const option = document.createElement('option');
    option.value = ex.name;
    option.textContent = ex.name;
    select.append(option);
  }
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
      rememberCase(job, text);
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

const isActive = (job) => job.state === 'queued' || job.state === 'running';

function progressText(job) {
  if (!job.progress) return job.state === 'queued' ? 'waiting' : '';
  return `it ${job.progress.iteration}, KKT ${fmt(job.progress.kkt_residual, 2)}`;
}

// A solve stopped by max_iterations "succeeded" but its answer is the last iterate, not a
// converged solution: its badge must not look like a success (docs/web.md).
function stateBadge(job) {
  const badge = document.createElement('span');
  const unconverged = job.converged === false && job.state === 'succeeded';
  badge.className = `state state-${unconverged ? 'not-converged' : job.state}`;
  badge.textContent = job.cancel_requested && isActive(job) ? 'cancelling' : unconverged ? 'not converged' : job.state;
  if (job.converged === false) badge.title = `the solve stopped without converging (${job.stop_reason ?? 'reason unknown'})`;
  return badge;
}

function actionButton(label, action, job, describedBy) {
  const b = document.createElement('button');
  b.type = 'button';
  b.textContent = label;
  b.dataset.action = action;
  b.dataset.jobId = String(job.id);
  b.setAttribute('aria-label', `${label} job ${job.id} (${job.name})`);
  if (describedBy) b.setAttribute('aria-describedby', describedBy);
  return b;
}

function renderJobs() {
  const tbody = document.querySelector('#job-table tbody');
  // Rebuilding rows would drop keyboard focus: remember which control had it.
  const active = document.activeElement;
  const focusKey = active?.dataset?.action ? { action: active.dataset.action, id: active.dataset.jobId } : null;

  tbody.innerHTML = '';
  for (const job of state.jobs) {
    const tr = document.createElement('tr');
    tr.dataset.jobId = String(job.id);
    tr.dataset.state = job.state;
    if (job.id === state.selectedId) tr.className = 'selected';
    const idCell = document.createElement('td');
    idCell.textContent = String(job.id);
    const nameCell = document.createElement('td');
    const view = actionButton(job.name, 'view', job);
    view.className = 'link';
    view.setAttribute('aria-label', `Show job ${job.id} (${job.name})`);
    if (job.id === state.selectedId) view.setAttribute('aria-current', 'true');
    nameCell.append(view);
    const stateCell = document.createElement('td');
    stateCell.append(stateBadge(job));
    const progressCell = document.createElement('td');
    progressCell.className = 'progress';
    progressCell.textContent = progressText(job);
    const actions = document.createElement('td');
    actions.className = 'actions';
    if (isActive(job)) actions.append(actionButton('Cancel', 'cancel', job));
    else actions.append(actionButton('Delete', 'delete', job));
    tr.append(idCell, nameCell, stateCell, progressCell, actions);
    tbody.append(tr);
  }
  $('jobs-empty').hidden = state.jobs.length > 0;

  if (focusKey) {
    const same = tbody.querySelector(`[data-action="${focusKey.action}"][data-job-id="${focusKey.id}"]`);
    const fallback = tbody.querySelector(`[data-action="view"][data-job-id="${focusKey.id}"]`);
    (same ?? fallback)?.focus();
  }
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
  const job = state.jobs.find((j) => j.id === id);
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
      if (job) forgetCase(job);
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
}

function destroyCharts() {
  for (const chart of state.view?.charts ?? []) chart.destroy();
  if (state.view) state.view.charts = [];
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
// polls make a coarse residual history until the full one arrives with the result.
function updateLiveChart(job) {
  const view = state.view;
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
        ? `Running: iteration ${job.progress.iteration}, KKT residual ${fmt(job.progress.kkt_residual, 3)}.`
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
      summary.textContent = 'Cancelled: there is no result.';
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
    const [resultResponse, vtuResponse] = await Promise.all([api.getResult(job.id), api.getSolution(job.id), plotsReady]);
    if (state.view !== view) return;  // another job was chosen meanwhile
    if (!resultResponse.ok) {
      $('job-summary').textContent = `The result cannot be loaded: ${api.problemMessage(resultResponse)}`;
      $('job-summary').className = 'error';
      return;
    }
    view.result = resultResponse.body;
    view.caseJson = recalledCase(job);
    view.mesh = null;
    view.meshError = null;
    if (vtuResponse.ok) {
      try {
        view.mesh = parseVtu(vtuResponse.body);
      } catch (e) {
        view.meshError = `The solution file cannot be read: ${e.message}`;
      }
    } else {
      view.meshError = `No solution file: ${api.problemMessage(vtuResponse)}`;
    }
    renderResult(job, view);
  } catch {
    $('job-summary').textContent = 'Cannot reach the service to load the result.';
  }
}

function contactWidth(contact) {
  const xs = (contact?.x ?? []).filter((_, i) => contact.active?.[i]);
  return xs.length ? Math.max(...xs) - Math.min(...xs) : 0;
}

function addNumber(dl, term, value, title) {
  const dt = document.createElement('dt');
  dt.textContent = term;
  const dd = document.createElement('dd');
  dd.textContent = value;
  const group = document.createElement('div');  // HTML allows a div around each dt/dd pair
  if (title) group.title = title;
  group.append(dt, dd);
  dl.append(group);
}

function renderResult(job, view) {
  const r = view.result;
  const contact = r.contact ?? { x: [], s: [], pressure: [], active: [], force: [0, 0] };
  view.hertz = hertzForCase(view.caseJson ?? caseFromResult(r), r);

  const summary = $('job-summary');
  summary.className = r.converged ? 'ok' : 'error';
  summary.textContent = r.converged
    ? `Converged in ${r.iterations} iterations (${r.method ?? 'solver'}).`
    : `Did not converge: ${(r.message ?? `stopped after ${r.iterations} iterations`).replace(/\.$/, '')}.`;

  const dl = $('key-numbers');
  dl.innerHTML = '';
  const force = contact.force ?? [NaN, NaN];
  addNumber(dl, 'Contact force (Fx, Fy)', `${fmt(force[0])}, ${fmt(force[1])}`, 'per unit thickness');
  const hasContact = (contact.x?.length ?? 0) > 0;
  const width = contactWidth(contact);
  addNumber(
    dl,
    'Contact width',
    !hasContact ? '— (no contact boundary)' : view.hertz ? `${fmt(width)} (Hertz 2a = ${fmt(2 * view.hertz.a)})` : fmt(width),
    'x extent of the midpoints of the active contact edges',
  );
  const pmax = hasContact ? Math.max(...contact.pressure) : NaN;
  addNumber(dl, 'Peak pressure', view.hertz ? `${fmt(pmax)} (Hertz p0 = ${fmt(view.hertz.p0)})` : fmt(pmax));
  addNumber(dl, 'Iterations', `${r.iterations}${r.converged ? '' : ' (not converged)'}`);
  addNumber(dl, 'Final KKT residual', fmt(r.final_kkt_residual, 3));
  addNumber(dl, 'Levels', String(r.levels));
  addNumber(dl, 'DOFs', String(r.dofs), r.dofs_total ? `${r.dofs_total} including constrained` : undefined);
  addNumber(dl, 'Active contact edges', `${contact.active?.filter(Boolean).length ?? 0} of ${contact.active?.length ?? 0}`);
  addNumber(dl, 'Time', `${seconds(r.timing?.total_s)} (solve ${seconds(r.timing?.solve_s)})`,
    `mesh ${seconds(r.timing?.mesh_s)}, assembly ${seconds(r.timing?.assembly_s)}`);

  const warnings = $('job-warnings');
  warnings.innerHTML = '';
  for (const w of r.warnings ?? []) {
    const li = document.createElement('li');
    li.textContent = w;
    warnings.append(li);
  }

  $('download-result').href = api.resultUrl(job.id);
  $('download-result').download = `job-${job.id}-result.json`;
  $('download-vtu').href = api.solutionUrl(job.id);
  $('download-vtu').download = `job-${job.id}.vtu`;

  $('job-result').hidden = false;  // charts measure their container: show it first
  drawCharts(view);
  drawMeshView(view, { resetMagnification: true });
}

function drawCharts(view) {
  destroyCharts();
  const contact = view.result.contact ?? { x: [], s: [], pressure: [] };
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
  if (!contact.x?.length) {
    pressureBox.textContent = 'This case has no contact boundary.';
    pressureBox.dataset.points = '0';
    note.textContent = '';
  } else {
    view.charts.push(plots.pressurePlot(pressureBox, contact, view.hertz, abscissa));
    const name = String(view.result.name ?? '');
    if (view.hertz) {
      note.textContent = `Dashed: plane-strain Hertz pressure for F = |Fy| = ${fmt(view.hertz.F)}, ` +
        `R = ${fmt(view.hertz.R)}, E* = ${fmt(view.hertz.Estar)}: a = ${fmt(view.hertz.a)}, p0 = ${fmt(view.hertz.p0)}` +
        (abscissa === 'x' ? '.' : ' (shown against x only).');
    } else if (name.toLowerCase().includes('hertz') && !view.caseJson) {
      note.textContent = 'The Hertz curve needs the case (material, radius); this browser did not submit it.';
    } else {
      note.textContent = '';
    }
  }
  drawSweep(view);
  const history = view.result.history ?? [];
  if (history.length) view.charts.push(plots.residualPlot(residualBox, history));
  else {
    residualBox.textContent = 'No iterations were recorded.';
    residualBox.dataset.points = '0';
  }
}

// A case with a sweep: the force of every point against the swept value (docs/web.md).
function drawSweep(view) {
  const sweep = view.result.sweep;
  $('sweep-figure').hidden = !sweep;
  const box = $('sweep-plot');
  box.innerHTML = '';
  if (!sweep) return;
  view.charts.push(plots.sweepPlot(box, sweep));
  const bad = sweep.points.filter((p) => !p.converged).length;
  $('sweep-note').textContent = `${sweep.points.length} points of ${sweep.pointer}, each started from the previous solution` +
    (bad ? `; ${bad} did not converge (red).` : '; all converged.');
}

function drawMeshView(view, { resetMagnification = false } = {}) {
  const canvas = $('mesh-canvas');
  const caption = $('mesh-caption');
  const input = $('mesh-magnification');
  if (!view.mesh) {
    canvas.hidden = true;
    caption.textContent = view.meshError ?? 'No solution file.';
    return;
  }
  canvas.hidden = false;
  if (resetMagnification) input.value = String(autoMagnification(view.mesh));
  const magnification = Math.max(0, Number(input.value) || 0);
  const fieldId = $('mesh-field').value;
  const field = MESH_FIELDS[fieldId];
  const values = field.compute(view.mesh);
  if (!values) {
    caption.textContent = `The solution file has no ${field.label}.`;
    return;
  }
  const { min, max } = drawMesh(canvas, view.mesh, values, magnification);
  $('legend-min').textContent = fmt(min, 3);
  $('legend-max').textContent = fmt(max, 3);
  const nTriangles = view.mesh.triangles.length / 3;
  canvas.dataset.triangles = String(nTriangles);
  canvas.setAttribute('aria-label',
    `Deformed mesh of ${nTriangles} triangles coloured by ${field.label} from ${fmt(min, 3)} to ${fmt(max, 3)}, displacement magnified ${magnification} times`);
  caption.textContent = `${nTriangles} triangles, coloured by ${field.label} (per triangle). ` +
    `Displacement magnified ×${magnification}; dashed: the undeformed outline.`;
}

// ---- start ------------------------------------------------------------------------------

function init() {
  for (const [id, field] of Object.entries(MESH_FIELDS)) {
    const option = document.createElement('option');
    option.value = id;
    option.textContent = field.label;
    $('mesh-field').append(option);
  }
  $('legend-bar').style.background = colourGradientCss();
  $('submit-case').addEventListener('click', submitCase);
  $('case-text').addEventListener('keydown', (e) => {
    if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) {
      e.preventDefault();
      submitCase();
    }
  });
  document.querySelector('#job-table tbody').addEventListener('click', onJobAction);
  $('pressure-abscissa').addEventListener('change', () => state.view?.result && drawCharts(state.view));
  $('mesh-field').addEventListener('change', () => state.view?.mesh && drawMeshView(state.view));
  $('mesh-magnification').addEventListener('input', () => state.view?.mesh && drawMeshView(state.view));
  $('mesh-auto').addEventListener('click', () => state.view?.mesh && drawMeshView(state.view, { resetMagnification: true }));
  let resizeFrame = 0;
  new ResizeObserver(() => {
    cancelAnimationFrame(resizeFrame);
    resizeFrame = requestAnimationFrame(() => state.view?.mesh && drawMeshView(state.view));
  }).observe($('mesh-canvas'));

  const fromHash = /^#job-(\d+)$/.exec(location.hash);
  if (fromHash) state.selectedId = Number(fromHash[1]);
  loadExamples();
  refreshJobs();
}

init();
