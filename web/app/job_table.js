// The job list's table: one row per job with its state badge, progress and the Cancel or
// Delete button; the job's name opens it.
import { fmt, stepPrefix } from './format.js';

export const isActive = (job) => job.state === 'queued' || job.state === 'running';

function progressText(job) {
  if (!job.progress) return job.state === 'queued' ? 'waiting' : '';
  return `${stepPrefix(job.progress)}it ${job.progress.iteration}, KKT ${fmt(job.progress.kkt_residual, 2)}`;
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

/** Rebuilds the rows of `tbody` for `jobs`, marking `selectedId`; keeps keyboard focus. */
export function renderJobTable(tbody, jobs, selectedId) {
  // Rebuilding rows would drop keyboard focus: remember which control had it.
  const active = document.activeElement;
  const focusKey = active?.dataset?.action ? { action: active.dataset.action, id: active.dataset.jobId } : null;

  tbody.innerHTML = '';
  for (const job of jobs) {
    const tr = document.createElement('tr');
    tr.dataset.jobId = String(job.id);
    tr.dataset.state = job.state;
    if (job.id === selectedId) tr.className = 'selected';
    const idCell = document.createElement('td');
    idCell.textContent = String(job.id);
    const nameCell = document.createElement('td');
    const view = actionButton(job.name, 'view', job);
    view.className = 'link';
    view.setAttribute('aria-label', `Show job ${job.id} (${job.name})`);
    if (job.id === selectedId) view.setAttribute('aria-current', 'true');
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

  if (focusKey) {
    const same = tbody.querySelector(`[data-action="${focusKey.action}"][data-job-id="${focusKey.id}"]`);
    const fallback = tbody.querySelector(`[data-action="view"][data-job-id="${focusKey.id}"]`);
    (same ?? fallback)?.focus();
  }
}
