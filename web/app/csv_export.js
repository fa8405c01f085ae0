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

/** One row per sweep point, in the order solved (3D: three force components and the zone's radius). */
export function sweepCsv(sweep, dimension = 2) {
  const zone = dimension === 3 ? ['contact_radius'] : ['contact_width', 'contact_length'];
  const forces = ['force_x', 'force_y', 'force_z'].slice(0, dimension);
  const rows = (sweep?.points ?? []).map((p) => [
    p.value, ...forces.map((_, k) => p.force?.[k]), p.peak_pressure, ...zone.map((z) => p[z]), p.converged ? 1 : 0, p.stop_reason, p.iterations,
  ]);
  return csv([sweep?.pointer ?? 'value', ...forces, 'peak_pressure', ...zone, 'converged', 'stop_reason', 'iterations'], rows);
}

/**
 * The samples of a 3D result's pressure line (contact_line.js): s, the point x, y, z, the
 * pressure (empty off the contact faces) and, with `hertz` ({a, p0}), 3D Hertz at r = |s|.
 */
export function lineCsv(samples, hertz = null) {
  const rows = samples.map((x) => [x.s, ...x.point, x.value, ...(hertz ? [hertzPressure(x.s, hertz)] : [])]);
  return csv(['s', 'x', 'y', 'z', 'pressure', ...(hertz ? ['hertz_pressure'] : [])], rows);
}
