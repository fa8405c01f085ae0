// Unit tests of the page's pure modules (no browser): JSON pointer locations, the Hertz
// formulas, the VTU reader, the mesh view's colour map, magnification, fields, edges, fit
// and point location, and the friction / load-step data shaping.
//   node --test tests/web/modules.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

import { locateJson, rangeForPointer, lineOfOffset, splitPointer } from '../../web/app/json_locations.js';
import { contactModulus, hertzContact, hertzForResult, hertzPressure, lameParameters } from '../../web/app/hertz.js';
import { parseVtu } from '../../web/app/vtu.js';
import { autoMagnification, colourAt, colourScale, maxDisplacement } from '../../web/app/mesh_view.js';
import { MESH_FIELDS, probeSummary } from '../../web/app/mesh_fields.js';
import { contactCsv, sweepCsv } from '../../web/app/csv_export.js';
import { adaptiveRows, stepColumns } from '../../web/app/adaptive_steps.js';
import { stepPrefix } from '../../web/app/format.js';
import { accuracyNumber } from '../../web/app/accuracy.js';
import {
  changesText, commonCoefficient, forceAxes, frictionNumbers, frictionText, loadStepColumns, loadStepRows, stateRuns, stickZoneText,
} from '../../web/app/friction.js';
import { bounds, deformedPoints, fitTransform, locatePoint, meshEdges, valueRange } from '../../web/app/mesh_drawing.js';

const repo = join(dirname(fileURLToPath(import.meta.url)), '..', '..');
const hertzText = readFileSync(join(repo, 'solver', 'examples', 'hertz.json'), 'utf8');

const lineOf = (text, pointer) => {
  const { locations } = locateJson(text);
  const range = rangeForPointer(text, locations, pointer);
  return range && { line: lineOfOffset(text, range.start) + 1, exact: range.exact, key: text.slice(range.start, range.end) };
};

test('pointers resolve to the line of their key in a shipped case', () => {
  const lines = hertzText.split('\n');
  const lineWith = (needle) => lines.findIndex((l) => l.includes(needle)) + 1;
  assert.deepEqual(lineOf(hertzText, '/material/mu'), { line: lineWith('"material"'), exact: true, key: '"mu"' });
  assert.deepEqual(lineOf(hertzText, '/mesh/refinements'), { line: lineWith('"refinements"'), exact: true, key: '"refinements"' });
  assert.deepEqual(lineOf(hertzText, '/boundary/contact/obstacle/normal'), { line: lineWith('"normal"'), exact: true, key: '"normal"' });
  // An array element: its value.
  const pressed = String(JSON.parse(hertzText).boundary.top.displacement[1]);
  assert.deepEqual(lineOf(hertzText, '/boundary/top/displacement/1'), { line: lineWith('"displacement"'), exact: true, key: pressed });
});

test('a missing field is shown on its nearest existing parent', () => {
  const r = lineOf(hertzText, '/solver/smoother');
  assert.equal(r.exact, false);
  assert.equal(r.key, '"solver"');
  const root = lineOf(hertzText, '/nothing/here');
  assert.equal(root.exact, false);
  assert.equal(root.line, 1);
});

test('escaped pointer tokens (~0, ~1) find keys with "~" and "/"', () => {
  const text = '{\n "boundary": {\n  "a/b": {"type": "x"},\n  "c~d": 1\n }\n}';
  assert.deepEqual(splitPointer('/boundary/a~1b'), ['boundary', 'a/b']);
  assert.equal(lineOf(text, '/boundary/a~1b/type').line, 3);
  assert.equal(lineOf(text, '/boundary/c~0d').line, 4);
});

test('a syntax error keeps the locations found before it', () => {
  const text = '{\n "name": "x",\n "mesh": {"size": 0.1,, }\n}';
  const { locations, error } = locateJson(text);
  assert.ok(error);
  assert.equal(lineOfOffset(text, error.offset) + 1, 3);
  assert.ok(locations.has('/name'));
  assert.ok(locations.has('/mesh/size'));
});

test('Hertz: E* from Lamé parameters, E and nu, and the incompressible limit', () => {
  assert.equal(contactModulus({ mu: 1, lambda: Infinity }), 4);
  assert.ok(Math.abs(contactModulus({ mu: 1, lambda: 1 }) - 8 / 3) < 1e-15);
  // E = 2.6, nu = 0.3: E* = E/(1 − nu²).
  const lame = lameParameters({ E: 2.6, nu: 0.3 });
  assert.ok(Math.abs(contactModulus(lame) - 2.6 / (1 - 0.09)) < 1e-12);
  assert.equal(lameParameters({ mu: 2, lambda: 'inf' }).lambda, Infinity);
  assert.equal(lameParameters({ E: 3, nu: 0.5 }).lambda, Infinity);
  assert.equal(lameParameters({ mu: -1, lambda: 1 }), null);
});

test('Hertz: a, p0 and the pressure integrate to the force', () => {
  const F = 0.3, R = 1, lame = { mu: 1, lambda: 1 };
  const h = hertzContact(F, R, lame);
  assert.ok(Math.abs(h.a - Math.sqrt((4 * F * R) / (Math.PI * (8 / 3)))) < 1e-15);
  assert.ok(Math.abs(h.p0 - (2 * F) / (Math.PI * h.a)) < 1e-15);
  // ∫ p dx over [−a, a] = π a p0 / 2 = F (midpoint rule, 20000 cells).
  const n = 20000;
  let integral = 0;
  for (let k = 0; k < n; k++) integral += hertzPressure(-h.a + ((k + 0.5) * 2 * h.a) / n, h) * ((2 * h.a) / n);
  assert.ok(Math.abs(integral - F) < 1e-5 * F, `∫p = ${integral}`);
  assert.equal(hertzPressure(1.01 * h.a, h), 0);
});

test('Hertz is offered by geometry: an arc against a plane, whatever the name', () => {
  const result = {
    name: 'a roller',
    material: { mu: 1, lambda: 1 },
    contact: { force: [0, 0.25], shape: { type: 'arc', center: [0, 2], radius: 2 }, plane_normal: [0, 1] },
  };
  const h = hertzForResult(result);
  assert.equal(h.R, 2);
  assert.ok(Math.abs(h.Estar - 8 / 3) < 1e-12);
  assert.ok(Math.abs(h.a - Math.sqrt((4 * 0.25 * 2) / (Math.PI * (8 / 3)))) < 1e-12);
  // The normal force along the plane's normal, not |F_y|, on a tilted plane.
  const tilted = { ...result, contact: { ...result.contact, force: [0.6, 0.8], plane_normal: [0.6, 0.8] } };
  assert.ok(Math.abs(hertzForResult(tilted).F - 1) < 1e-12);
  assert.equal(hertzForResult({ ...result, contact: { ...result.contact, shape: { type: 'line' } } }), null);
  assert.equal(hertzForResult({ ...result, contact: { ...result.contact, plane_normal: null } }), null, 'a circle or gap obstacle');
  assert.equal(hertzForResult({ ...result, contact: { ...result.contact, force: [0, 0] } }), null, 'no contact');
  assert.equal(hertzForResult({ ...result, material: { mu: 1, lambda: 'inf' } }).Estar, 4);
});

const twoTriangles = `<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
<UnstructuredGrid>
<Piece NumberOfPoints="4" NumberOfCells="2">
<Points>
<DataArray type="Float64" NumberOfComponents="3" format="ascii">
0 0 0
1 0 0
1 1 0
0 1 0
</DataArray>
</Points>
<Cells>
<DataArray type="Int32" Name="connectivity" format="ascii">
0 1 2
0 2 3
</DataArray>
<DataArray type="Int32" Name="offsets" format="ascii">
3
6
</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">
5
5
</DataArray>
</Cells>
<PointData Vectors="u">
<DataArray type="Float64" Name="u" NumberOfComponents="3" format="ascii">
0 0 0
0.001 0 0
0.001 -0.002 0
0 -0.002 0
</DataArray>
</PointData>
<CellData Scalars="von_mises">
<DataArray type="Float64" Name="sigma" NumberOfComponents="4" format="ascii">
1 0.25 0.5 -1
2 -3 4 2
</DataArray>
<DataArray type="Float64" Name="von_mises" format="ascii">
0.5
1.5e-3
</DataArray>
</CellData>
</Piece>
</UnstructuredGrid>
</VTKFile>
`;

test('the VTU reader returns points, triangles, point and cell data', () => {
  const mesh = parseVtu(twoTriangles);
  assert.deepEqual([...mesh.points], [0, 0, 1, 0, 1, 1, 0, 1]);
  assert.deepEqual([...mesh.triangles], [0, 1, 2, 0, 2, 3]);
  assert.equal(mesh.pointData.u.components, 3);
  assert.deepEqual([...mesh.cellData.von_mises.values], [0.5, 1.5e-3]);
  assert.equal(mesh.cellData.sigma.values.length, 8);
  assert.ok(Math.abs(maxDisplacement(mesh) - Math.hypot(0.001, 0.002)) < 1e-15);
});

/** The same two triangles with every array in VTK's inline binary format (base64 of a UInt32 byte count and the values). */
function binaryTwoTriangles() {
  const types = { Float64: Float64Array, Int32: Int32Array, UInt8: Uint8Array };
  return twoTriangles.replace(/<DataArray type="(\w+)"([^>]*) format="ascii">\n([\s\S]*?)<\/DataArray>/g, (all, type, attrs, text) => {
    const values = new types[type](text.trim().split(/\s+/).map(Number));
    const bytes = Buffer.concat([Buffer.from(new Uint32Array([values.byteLength]).buffer), Buffer.from(values.buffer)]);
    return `<DataArray type="${type}"${attrs} format="binary">\n${bytes.toString('base64')}\n</DataArray>`;
  });
}

test('the VTU reader reads inline binary arrays as their ASCII values', () => {
  const binary = binaryTwoTriangles();
  assert.ok(binary.includes('format="binary"') && !binary.includes('format="ascii"'));
  assert.deepEqual(parseVtu(binary), parseVtu(twoTriangles));
});

test('the VTU reader says what is wrong with a broken file', () => {
  assert.throws(() => parseVtu('<html></html>'), /no <Piece>/);
  assert.throws(() => parseVtu(twoTriangles.replace('0 2 3', '0 2 7')), /names point 7/);
  assert.throws(() => parseVtu(twoTriangles.replace('0.5\n1.5e-3\n', '0.5\n')), /von_mises/);
  assert.throws(() => parseVtu(twoTriangles.replace('Name="u" NumberOfComponents="3" format="ascii"', 'Name="u" NumberOfComponents="3" format="appended"')), /neither ASCII nor inline binary/);
  assert.throws(() => parseVtu(binaryTwoTriangles().replace(/(Name="u"[^>]*>\n)(\S{8})/, '$1AAAAAAAA')), /header announces 0 bytes|expected 4 × 3/);
});

test('magnification makes the largest displacement about 8 % of the diagonal, never below 1', () => {
  const mesh = parseVtu(twoTriangles);
  // diagonal √2, |u|max = √5 · 1e-3: target 0.08·√2/(√5·1e-3) ≈ 50.6 → 50.
  assert.equal(autoMagnification(mesh), 50);
  const big = parseVtu(twoTriangles.replaceAll('0.001', '0.5'));
  assert.equal(autoMagnification(big), 1);
});

test('the colour map runs from dark purple to yellow and clamps', () => {
  assert.deepEqual(colourAt(0), [68, 1, 84]);
  assert.deepEqual(colourAt(1), [253, 231, 37]);
  assert.deepEqual(colourAt(-3), colourAt(0));
  assert.deepEqual(colourAt(NaN), colourAt(0));
  // The diverging map: blue, grey-white at the middle (0 on a symmetric range), red.
  assert.deepEqual(colourAt(0, 'coolwarm'), [59, 76, 192]);
  assert.deepEqual(colourAt(0.5, 'coolwarm'), [221, 221, 221]);
  assert.deepEqual(colourAt(1, 'coolwarm'), [180, 4, 38]);
});

test('signed fields with both signs get the diverging map, symmetric about 0', () => {
  assert.deepEqual(colourScale({ min: -0.1, max: 0.02 }, true), { map: 'coolwarm', min: -0.1, max: 0.1 });
  assert.deepEqual(colourScale({ min: -0.01, max: 0.3 }, true), { map: 'coolwarm', min: -0.3, max: 0.3 });
  assert.deepEqual(colourScale({ min: 0.01, max: 0.3 }, true), { map: 'viridis', min: 0.01, max: 0.3 });
  assert.deepEqual(colourScale({ min: -0.1, max: 0.02 }, false), { map: 'viridis', min: -0.1, max: 0.02 });
});

test('the mesh fields: each σ component, u per triangle, and their units', () => {
  const mesh = parseVtu(twoTriangles);
  const values = (id) => [...MESH_FIELDS[id].compute(mesh)];
  assert.deepEqual(values('sigma_xx'), [1, 2]);
  assert.deepEqual(values('sigma_xy'), [0.25, -3]);
  assert.deepEqual(values('sigma_yx'), [0.5, 4]);
  assert.deepEqual(values('sigma_yy'), [-1, 2]);
  assert.deepEqual(values('von_mises'), [0.5, 1.5e-3]);
  // u_y per triangle: the mean over its vertices (0, 0, −0.002 and 0, −0.002, −0.002).
  const uy = values('u_y');
  assert.ok(Math.abs(uy[0] + 0.002 / 3) < 1e-18 && Math.abs(uy[1] + 0.004 / 3) < 1e-18, `${uy}`);
  assert.equal(MESH_FIELDS.functional.compute(mesh), null, 'no functional array: null, not zeros');
  for (const id of ['von_mises', 'sigma_xx', 'sigma_xy', 'sigma_yx', 'sigma_yy']) assert.equal(MESH_FIELDS[id].unit, 'S');
  for (const id of ['displacement', 'u_x', 'u_y']) assert.equal(MESH_FIELDS[id].unit, 'L');
  assert.deepEqual(valueRange([3, NaN, -2, 1]), { min: -2, max: 3 });
  assert.deepEqual(valueRange([]), { min: 0, max: 0 });
});

test('mesh edges: every edge once, the outline on one triangle only', () => {
  const mesh = parseVtu(twoTriangles);
  const { all, outline } = meshEdges(mesh);
  assert.equal(all.length / 2, 5);  // the square's four sides and its diagonal
  assert.equal(outline.length / 2, 4);
  const pairs = [];
  for (let e = 0; e < outline.length; e += 2) pairs.push([outline[e], outline[e + 1]].sort().join('-'));
  assert.deepEqual(pairs.sort(), ['0-1', '0-3', '1-2', '2-3']);
});

test('the fit puts the mesh in the middle of the canvas, y up, and points are located', () => {
  const mesh = parseVtu(twoTriangles);
  const t = fitTransform(bounds(mesh.points), 200, 100, 10);
  assert.equal(t.a, 80);  // the height limits: (100 − 20) / 1
  assert.deepEqual([t.bx + t.a * 0.5, t.by - t.a * 0.5], [100, 50]);
  assert.ok(t.by - t.a * 1 < t.by - t.a * 0, 'y = 1 is above y = 0');
  const hit = locatePoint(mesh, mesh.points, 0.25, 0.75);  // above the diagonal: triangle 1
  assert.equal(hit.cell, 1);
  assert.ok(Math.abs(hit.weights.reduce((a, b) => a + b) - 1) < 1e-15);
  assert.equal(locatePoint(mesh, mesh.points, 0.75, 0.25).cell, 0);
  assert.equal(locatePoint(mesh, mesh.points, 1.5, 0.5), null);
  // Deformed by 100 × u, the point (1.05, 0.5) lies inside (x moved right by 0.1 at x = 1).
  const moved = deformedPoints(mesh, 100);
  assert.deepEqual([moved[2], moved[5]], [1.1, 1 - 0.2]);
  assert.equal(locatePoint(mesh, moved, 1.05, 0.5)?.cell, 0);
});

test('a probe adds σ of the triangle and u interpolated at the point', () => {
  const mesh = parseVtu(twoTriangles);
  // Triangle 1 = points 0, 2, 3; its centroid: u = mean of (0, 0), (0.001, −0.002), (0, −0.002).
  const r = probeSummary(mesh, { cell: 1, weights: [1 / 3, 1 / 3, 1 / 3] }, String);
  assert.ok(Math.abs(r.u[0] - 0.001 / 3) < 1e-18 && Math.abs(r.u[1] + 0.004 / 3) < 1e-18, `${r.u}`);
  assert.match(r.text, /^σ = \[2, -3; 4, 2\] · u = \(/);
  // At a vertex the interpolation is the vertex's value.
  assert.deepEqual(probeSummary(mesh, { cell: 1, weights: [0, 1, 0] }, String).u, [0.001, -0.002]);
});

test('CSV of the contact boundary and of a sweep', () => {
  const contact = { x: [-0.1, 0.1], y: [0, 0], s: [0.9, 1.1], length: [0.2, 0.2], pressure: [0.5, 0], gap: [0, 0.01], active: [true, false] };
  assert.equal(contactCsv(contact), 'x,y,s,length,pressure,gap,active\n-0.1,0,0.9,0.2,0.5,0,1\n0.1,0,1.1,0.2,0,0.01,0\n');
  assert.equal(contactCsv({ x: [] }), 'x,y,s,length,pressure,gap,active\n');
  const sweep = { pointer: '/a/b', points: [{ value: 1, force: [0, 2.5], peak_pressure: 3, contact_width: 0.35, contact_length: 0.4, converged: false, stop_reason: 'max_iterations', iterations: 200 }] };
  assert.equal(sweepCsv(sweep), '/a/b,force_x,force_y,peak_pressure,contact_width,contact_length,converged,stop_reason,iterations\n1,0,2.5,3,0.35,0.4,0,"max_iterations",200\n');
  const solid = { pointer: '/b', points: [{ value: 2, force: [0, 1, 2.5], peak_pressure: 3, contact_radius: 0.1, converged: true, stop_reason: 'converged', iterations: 12 }] };
  assert.equal(sweepCsv(solid, 3), '/b,force_x,force_y,force_z,peak_pressure,contact_radius,converged,stop_reason,iterations\n2,0,1,2.5,3,0.1,1,"converged",12\n');
});

test('adaptive steps: the force change is relative to the later step, none on the first', () => {
  const steps = [
    { step: 0, dofs: 100, triangles: 40, iterations: 9, estimator: 0.02, force: [0, 1], algebraic_error: null, time_s: 0.1 },
    { step: 1, dofs: 180, triangles: 70, iterations: 8, estimator: 0.015, force: [0.3, 1.4], algebraic_error: 2e-9, time_s: 0.2 },
  ];
  const rows = adaptiveRows(steps);
  assert.equal(rows.length, 2);
  assert.equal(rows[0].forceChange, null);
  assert.ok(Math.abs(rows[1].forceChange - 0.5 / Math.hypot(0.3, 1.4)) < 1e-15);
  const columns = stepColumns(2);
  const cells = columns.map(([, text]) => text(rows[1]));
  assert.deepEqual(cells, ['1', '180', '70', '8', '0.015', '0.3', '1.4', '0.35', '2.0e-9', '0.20 s']);
  assert.equal(columns[7][1](rows[0]), '—');
  assert.deepEqual(adaptiveRows(undefined), []);
  // 3D: tetrahedra and three force components, the change over all three.
  const solid = adaptiveRows([
    { step: 0, dofs: 2452, tetrahedra: 384, iterations: 12, estimator: 0.01, force: [0, 0, 1], time_s: 1 },
    { step: 1, dofs: 2701, tetrahedra: 420, iterations: 9, estimator: 0.008, force: [0, 0.3, 1.4], time_s: 2 },
  ]);
  assert.ok(Math.abs(solid[1].forceChange - 0.5 / Math.hypot(0.3, 1.4)) < 1e-15);
  const columns3 = stepColumns(3);
  assert.deepEqual(columns3.map(([title]) => title).slice(2, 8), ['tetrahedra', 'iterations', 'J^½', 'F_x', 'F_y', 'F_z']);
  assert.deepEqual(columns3.map(([, text]) => text(solid[1])).slice(0, 8), ['1', '2701', '420', '9', '0.008', '0', '0.3', '1.4']);
});

test('state runs tile the boundary: boundaries halfway between midpoints, ends half a spacing out', () => {
  const xs = [0, 1, 2, 4, 6];
  const runs = stateRuns(xs, ['open', 'slip', 'stick', 'stick', 'open']);
  assert.deepEqual(runs, [
    { state: 'open', from: -0.5, to: 0.5, edges: 1 },
    { state: 'slip', from: 0.5, to: 1.5, edges: 1 },
    { state: 'stick', from: 1.5, to: 5, edges: 2 },
    { state: 'open', from: 5, to: 7, edges: 1 },
  ]);
  assert.deepEqual(stateRuns([3], ['stick']), [{ state: 'stick', from: 3, to: 3, edges: 1 }]);
  assert.deepEqual(stateRuns([], []), []);
});

test('friction in words: the law, the bound from the case for Tresca, the updates and the stick zone', () => {
  const coulomb = { groups: { contact: { law: 'coulomb', coefficient: 0.3 } }, updates: 10, last_change: 4.443e-7 };
  assert.equal(frictionText(coulomb), 'Coulomb 𝔣 = 0.3; 10 updates of the slip bounds, the last changing them by 4.4e-7');
  const tresca = { groups: { left: { law: 'tresca', coefficient: null }, right: { law: 'coulomb', coefficient: 0.5 } }, updates: 0 };
  const caseDoc = { boundary: { left: { friction: { bound: '0.01 * (1 + x)' } } } };
  assert.equal(frictionText(tresca, caseDoc), 'left: Tresca s = 0.01 * (1 + x), right: Coulomb 𝔣 = 0.5');
  assert.equal(frictionText(tresca), 'left: Tresca (bound s as in the case), right: Coulomb 𝔣 = 0.5');
  // The slip bound 𝔣p is drawn only when one coefficient holds on every frictional edge.
  assert.equal(commonCoefficient(coulomb), 0.3);
  assert.equal(commonCoefficient(tresca), null);
  assert.equal(commonCoefficient(undefined), null);
  assert.equal(stickZoneText({ edges: 10, length: 0.14928, s_start: 0.46743, s_end: 0.61671 }, ' mm'), '0.1493 mm over 10 edges, s = 0.4674 … 0.6167 mm');
  assert.equal(stickZoneText({ edges: 0, length: 0, s_start: null, s_end: null }), 'none: every edge in contact slips');
});

test('load steps: forces split along the plane obstacle, one row per step, the table cells', () => {
  const step = (k, changes, force, states, stick) => ({
    step: k, changes, iterations: 10 + k, converged: k !== 2,
    contact: { force, state: states, stick_zone: { edges: stick ? 1 : 0, length: stick } },
  });
  const loadSteps = { count: 3, steps: [
    step(0, {}, [0, 2], ['open', 'stick', 'stick'], 0.2),
    step(1, { '/boundary/top/displacement/0': 0.001 }, [-0.3, 2], ['open', 'slip', 'stick'], 0.1),
    step(2, { '/boundary/top/displacement/0': 0.002, '/x': 'y' }, [-0.6, 2], ['slip', 'slip', 'open'], 0),
  ] };
  // A horizontal plane with ν = (0, 1): F_t = F_x, F_n = F_y.
  const flat = forceAxes([0, 1]);
  const rows = loadStepRows(loadSteps, flat);
  assert.deepEqual(rows.map((r) => [r.step, r.tangential, r.normal, r.ratio]), [[0, 0, 2, 0], [1, -0.3, 2, 0.15], [2, -0.6, 2, 0.3]]);
  assert.deepEqual(rows[1].counts, { open: 1, stick: 1, slip: 1 });
  // A plane tilted by 90° (ν = (1, 0)): the normal force is F_x and t = (0, −1).
  const tilted = loadStepRows(loadSteps, forceAxes([1, 0]));
  assert.deepEqual(tilted.map((r) => [r.tangential, r.normal]), [[-2, 0], [-2, -0.3], [-2, -0.6]]);
  assert.equal(tilted[0].ratio, null, 'no ratio without a positive normal force');
  // No plane obstacle: F_x and F_y, named so.
  const xy = forceAxes(null);
  assert.equal(loadStepRows(loadSteps, xy)[2].normal, 2);
  const columns = loadStepColumns(flat);
  assert.deepEqual(columns.map(([title]) => title),
    ['step', 'changes', 'iterations', 'converged', 'F_t', 'F_n', '|F_t| / F_n', 'stick zone', 'stick / slip / open edges']);
  assert.deepEqual(loadStepColumns(xy).slice(4, 7).map(([title]) => title), ['F_x', 'F_y', '|F_x| / F_y']);
  assert.deepEqual(columns.map(([, text]) => text(rows[2])),
    ['2', '/boundary/top/displacement/0 = 0.002, /x = "y"', '12', 'no', '-0.6', '2', '0.3', '0', '0 / 2 / 1']);
  assert.equal(changesText({}), '— (the case as given)');
  assert.deepEqual(loadStepRows(undefined, flat), []);
});

test('the key numbers a frictional, load-stepped result adds', () => {
  const result = {
    units: { declared: true, length: 'mm', stress: 'MPa' },
    friction: { groups: { contact: { law: 'coulomb', coefficient: 0.3 } }, updates: 1, last_change: 1 },
    contact: { shear: [0, -0.1], stick_zone: { edges: 1, length: 0.5, s_start: 1, s_end: 1.5 } },
    load_steps: { count: 2, steps: [{ converged: true }, { converged: false }] },
  };
  const numbers = frictionNumbers(result);
  assert.deepEqual(numbers.map(([term, value]) => [term, value]), [
    ['Friction', 'Coulomb 𝔣 = 0.3; 1 update of the slip bounds, the last changing them by 1'],
    ['Stick zone', '0.5 mm over 1 edge, s = 1 … 1.5 mm'],
    ['Load steps', '2 (1 not converged)'],
  ]);
  assert.deepEqual(frictionNumbers({ contact: { x: [0] } }), [], 'frictionless: nothing added');
});

test('a job of several solves says which one runs, counted from 1, out of how many if known', () => {
  assert.equal(stepPrefix({ iteration: 3, step: 1, steps: 3 }), 'step 2 of 3, ');
  assert.equal(stepPrefix({ iteration: 3, step: 2, steps: null }), 'step 3, ');  // accuracy
  assert.equal(stepPrefix({ iteration: 3, step: 0, steps: 1 }), '');  // a single solve
  assert.equal(stepPrefix({ iteration: 3 }), '');  // a service from before steps
  assert.equal(stepPrefix(null), '');
});

test('a run to a requested force accuracy says whether it got there, and with which estimate', () => {
  const steps = [{ refinements: 2 }, { refinements: 3 }, { refinements: 4 }];
  const [reached, why] = accuracyNumber({ force: 1e-3, reached: true, stop_reason: 'reached', estimate: 6.5e-4, steps, stop_message: 'the estimated …' });
  assert.equal(reached, 'reached: estimated 0.065 % of 0.1 % asked (refinements 2–4)');
  assert.equal(why, 'the estimated …');
  const [missed] = accuracyNumber({ force: 1e-5, reached: false, stop_reason: 'max_dofs', estimate: 2e-4, steps });
  assert.equal(missed, 'NOT reached (max_dofs): estimated 0.02 % of 0.001 % asked (refinements 2–4)');
  const [zero] = accuracyNumber({ force: 1e-3, reached: false, stop_reason: 'no_force', estimate: null, steps: [{ refinements: 2 }] });
  assert.equal(zero, 'NOT reached (no_force): estimated — of 0.1 % asked (refinements 2)');
  assert.equal(accuracyNumber(undefined), null);
});
