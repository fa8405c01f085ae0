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
