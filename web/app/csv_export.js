// The job's tables as CSV for a spreadsheet: the contact boundary (one row per contact edge,
// the result's contact arrays), a sweep's points and a 3D result's pressure line. Column names follow docs/result-format.md.

import { hertzPressure } from './hertz.js';

function csv(header, rows) {
  const cell = (v) => (v === null || v === undefined ? '' : typeof v === 'number' ? String(v) : JSON.stringify(String(v)));
  return [header.join(','), ...rows.map((r) => r.map(cell).join(','))].join('\n') + '\n';
}

/** One row per contact edge: x, y, s, length, pressure, gap, active (1 or 0). */
export function contactCsv(contact) {
  const columns = ['x', 'y', 's', 'length', 'pressure', 'gap'];
  const n = contact?.x?.length ?? 0;
  const rows = [];
  for (let i = 0; i < n; i++) rows.push([...columns.map((c) => contact[c]?.[i]), contact.active?.[i] ? 1 : 0]);
  return csv([...columns, 'active'], rows);
}

/** One row per sweep point, in the order solved. */
export function sweepCsv(sweep) {
  const rows = (sweep?.points ?? []).map((p) => [
    p.value, p.force?.[0], p.force?.[1], p.peak_pressure, p.contact_width, p.contact_length, p.converged ? 1 : 0, p.stop_reason, p.iterations,
  ]);
  return csv([sweep?.pointer ?? 'value', 'force_x', 'force_y', 'peak_pressure', 'contact_width', 'contact_length', 'converged', 'stop_reason', 'iterations'], rows);
}

/**
 * The samples of a 3D result's pressure line (contact_line.js): s, the point x, y, z, the
 * pressure (empty off the contact faces) and, with `hertz` ({a, p0}), 3D Hertz at r = |s|.
 */
export function lineCsv(samples, hertz = null) {
  const rows = samples.map((x) => [x.s, ...x.point, x.value, ...(hertz ? [hertzPressure(x.s, hertz)] : [])]);
  return csv(['s', 'x', 'y', 'z', 'pressure', ...(hertz ? ['hertz_pressure'] : [])], rows);
}
