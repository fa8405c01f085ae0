// Number and status formatting shared by the page's parts.

/** A number with `digits` significant digits, exponential outside [1e-3, 1e5); '—' if none. */
export function fmt(v, digits = 4) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return '—';
  if (v === 0) return '0';
  const a = Math.abs(v);
  return a >= 1e-3 && a < 1e5 ? String(Number(v.toPrecision(digits))) : v.toExponential(digits - 1);
}

export function seconds(v) {
  return typeof v === 'number' ? `${v < 10 ? v.toFixed(2) : v.toFixed(1)} s` : '—';
}

/** Writes a status text; kind 'ok' or 'error' colours it. */
export function setStatus(element, text, kind = '') {
  element.textContent = text;
  element.classList.toggle('ok', kind === 'ok');
  element.classList.toggle('error', kind === 'error');
}

/**
 * "step k of n, " (counted from 1) to go before the iteration of a job that runs several solves
 * (load steps, a sweep, adaptive or accuracy levels), whose iteration count starts again at
 * each; n is left out when not known (accuracy). '' for a single solve, or a service that does
 * not report steps.
 */
export function stepPrefix(progress) {
  if (!progress || typeof progress.step !== 'number' || progress.steps === 1) return '';
  const of = typeof progress.steps === 'number' ? ` of ${progress.steps}` : '';
  return `step ${progress.step + 1}${of}, `;
}
