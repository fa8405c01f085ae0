// Unit tests of the page's 3D modules (no browser, no binaries): the 3D VTU reader on the
// committed box fixture (ASCII and binary, written by fosls-contact from fixtures/box_3d.json),
// the boundary surface of a tetrahedral mesh and its contact faces, the pressure line in the
// contact plane, 3D Hertz, the camera and painter's order, the surface's fields and the
// line's CSV.
//   node --test tests/web/modules3d.test.mjs
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { dirname, join } from 'node:path';

import { parseVtu } from '../../web/app/vtu.js';
import { boundarySurface, contactFaces, normalOf } from '../../web/app/tet_surface.js';
import { planeFrame, pressureCentre, projectToPlane, sampleLine, sphereTangentPlane } from '../../web/app/contact_line.js';
import { contactPlanes, contactSpheres, hertzForResult3d, hertzSphereContact, halfBallRadius } from '../../web/app/hertz.js';

const here = dirname(fileURLToPath(import.meta.url));
const repo = join(here, '..', '..');
const fixture = (name) => readFileSync(join(here, 'fixtures', name), 'utf8');
const boxAscii = fixture('box_3d_ascii.vtu');
const boxBinary = fixture('box_3d.vtu');

test('the VTU reader returns tetrahedra and 3D points for a 3D file, ASCII or binary', () => {
  const mesh = parseVtu(boxAscii);
  assert.equal(mesh.dimension, 3);
  assert.equal(mesh.points, undefined, 'no 2D points: a 3D mesh is never drawn as 2D');
  assert.deepEqual([...mesh.points3.slice(0, 6)], [0, 0, 0, 1, 0, 0]);
  assert.equal(mesh.points3.length, 8 * 3);
  assert.deepEqual([...mesh.tetrahedra.slice(0, 8)], [0, 1, 3, 7, 0, 1, 5, 7]);
  assert.equal(mesh.tetrahedra.length, 6 * 4);
  assert.equal(mesh.pointData.u.components, 3);
  assert.deepEqual([...mesh.pointData.contact_boundary.values], [1, 1, 1, 1, 0, 0, 0, 0]);
  assert.equal(mesh.cellData.sigma.components, 9);

  // The binary file of the same solve: the same mesh, its values to the digits ASCII keeps
  // (12 significant) or Float32's (the stresses).
  const binary = parseVtu(boxBinary);
  assert.deepEqual(binary.points3, mesh.points3);
  assert.deepEqual(binary.tetrahedra, mesh.tetrahedra);
  const close = (a, b, rel) => a.every((v, i) => Math.abs(v - b[i]) <= rel * Math.max(...b.map(Math.abs)));
  assert.ok(close(binary.pointData.u.values, mesh.pointData.u.values, 1e-11));
  assert.ok(close(binary.pointData.contact_pressure.values, mesh.pointData.contact_pressure.values, 1e-11));
  assert.ok(close(binary.cellData.sigma.values, mesh.cellData.sigma.values, 1e-6));
});

test('the VTU reader refuses mixed and unknown cells, saying which', () => {
  const types = (text, f) => text.replace(/(Name="types" format="ascii">\n)([\s\S]*?)(<\/DataArray>)/, (all, a, body, b) => a + f(body) + b);
  assert.throws(() => parseVtu(types(boxAscii, (t) => t.replace(/10\n$/, '5\n'))), /cell 5 is not a tetrahedron as cell 0 is/);
  assert.throws(() => parseVtu(types(boxAscii, (t) => t.replaceAll('10', '12'))), /cell 0 has VTK type 12: only triangles \(5\) and tetrahedra \(10\)/);
  assert.throws(() => parseVtu(boxAscii.replace('0 1 3 7', '0 1 3 9')), /cell 0 names point 9, beyond 8/);
});

/**
 * The box [0, L]³ in cubes of six Kuhn tetrahedra (the builtin box's split). `flip` swaps two
 * vertices of every other tetrahedron, so the input orientation is mixed.
 */
function kuhnBox(cells, lengths, flip = true) {
  const [nx, ny, nz] = cells;
  const id = (i, j, k) => (k * (ny + 1) + j) * (nx + 1) + i;
  const points3 = [];
  for (let k = 0; k <= nz; k++) for (let j = 0; j <= ny; j++) for (let i = 0; i <= nx; i++) {
    points3.push((lengths[0] * i) / nx, (lengths[1] * j) / ny, (lengths[2] * k) / nz);
  }
  const kuhn = [[0, 1, 3, 7], [0, 1, 5, 7], [0, 2, 3, 7], [0, 2, 6, 7], [0, 4, 5, 7], [0, 4, 6, 7]];
  const tetrahedra = [];
  for (let k = 0; k < nz; k++) for (let j = 0; j < ny; j++) for (let i = 0; i < nx; i++) {
    const corner = (c) => id(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
    for (const tet of kuhn) {
      const v = tet.map(corner);
      if (flip && tetrahedra.length % 8 === 4) [v[1], v[2]] = [v[2], v[1]];
      tetrahedra.push(...v);
    }
  }
  const flags = [];
  for (let v = 0; v < points3.length / 3; v++) flags.push(points3[3 * v + 2] === 0 ? 1 : 0);
  return {
    dimension: 3, points3: Float64Array.from(points3), tetrahedra: Uint32Array.from(tetrahedra),
    pointData: { contact_boundary: { components: 1, values: Float64Array.from(flags) } }, cellData: {},
  };
}

test('the boundary surface of a box: its triangles, turned outwards (Σ area n·x = 3 volume)', () => {
  const fixtureMesh = parseVtu(boxAscii);
  const one = boundarySurface(fixtureMesh);
  assert.equal(one.triangles.length / 3, 12, 'the unit cube of six tetrahedra: 2 triangles per side');
  assert.equal(contactFaces(fixtureMesh, one).reduce((a, b) => a + b, 0), 2, 'its bottom is the contact group');

  const cells = [2, 3, 4];
  const lengths = [2, 1, 3];
  const mesh = kuhnBox(cells, lengths);
  const surface = boundarySurface(mesh);
  const [nx, ny, nz] = cells;
  assert.equal(surface.triangles.length / 3, 4 * (nx * ny + ny * nz + nx * nz));
  // Divergence theorem for x: ∫ x·n dA = 3 V; x·n is linear on a flat triangle, so its centroid
  // value times the area is exact. A face turned inwards would subtract instead of add.
  let flux = 0;
  const p = mesh.points3;
  const t = surface.triangles;
  for (let f = 0; f < t.length / 3; f++) {
    const n = normalOf(p, t[3 * f], t[3 * f + 1], t[3 * f + 2]);  // 2 × area × unit normal
    const centroid = [0, 1, 2].map((d) => (p[3 * t[3 * f] + d] + p[3 * t[3 * f + 1] + d] + p[3 * t[3 * f + 2] + d]) / 3);
    flux += (n[0] * centroid[0] + n[1] * centroid[1] + n[2] * centroid[2]) / 2;
  }
  assert.ok(Math.abs(flux - 3 * lengths[0] * lengths[1] * lengths[2]) < 1e-12, `flux ${flux}`);
  assert.equal(contactFaces(mesh, surface).reduce((a, b) => a + b, 0), 2 * nx * ny, 'the bottom triangles');
  // Every face's tetrahedron is named and lies inside.
  assert.equal(surface.cells.length, t.length / 3);
  assert.ok(surface.cells.every((c) => c < mesh.tetrahedra.length / 4));
});

test('the plane frame starts at global x projected, or y when x is the normal', () => {
  const flat = planeFrame([0, 0, 2]);
  assert.deepEqual([flat.n, flat.t1, flat.t2], [[0, 0, 1], [1, 0, 0], [0, 1, 0]]);
  const wall = planeFrame([-3, 0, 0]);
  assert.deepEqual(wall.t1, [0, 1, 0]);
  const tilted = planeFrame([0, 1, 1]);
  assert.deepEqual(tilted.t1, [1, 0, 0]);
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  assert.ok(Math.abs(dot(tilted.t2, tilted.n)) < 1e-15 && Math.abs(dot(tilted.t2, tilted.t1)) < 1e-15);
  assert.equal(planeFrame([0, 0, 0]), null);
  assert.deepEqual(projectToPlane([1, 2, 5], [0, 0, -1], [0, 0, 1]), [1, 2, -1]);
});

/** The bottom (contact) triangles of a box as vertex triples, and the frame of the plane z = 0. */
function bottomOfBox(cells) {
  const mesh = kuhnBox(cells, [1, 1, 1]);
  const surface = boundarySurface(mesh);
  const contact = contactFaces(mesh, surface);
  const faces = [];
  for (let f = 0; f < contact.length; f++) if (contact[f]) faces.push([...surface.triangles.slice(3 * f, 3 * f + 3)]);
  return { mesh, faces, frame: planeFrame([0, 0, 1]) };
}

test('the line reproduces a field linear on the contact faces, and gives nothing off them', () => {
  const { mesh, faces, frame } = bottomOfBox([4, 3, 1]);
  const p = mesh.points3;
  const linear = (x, y) => 1 + 2 * x - 3 * y;
  const values = Float64Array.from({ length: p.length / 3 }, (_, v) => linear(p[3 * v], p[3 * v + 1]));
  const centre = [0.4, 0.5, 0];
  const samples = sampleLine({ points3: p, faces, values, frame, centre, thetaDegrees: 30, count: 51 });
  assert.ok(samples.length >= 51);
  for (const { s, value, point } of samples) {
    assert.ok(value !== null, `s = ${s} lies on the bottom`);
    assert.ok(Math.abs(value - linear(point[0], point[1])) < 1e-12, `s = ${s}: ${value} against ${linear(point[0], point[1])}`);
    assert.ok(Math.abs(point[0] - (centre[0] + s * Math.cos(Math.PI / 6))) < 1e-12 && point[2] === 0);
  }
  // The samples span the chord of the unit square: from its side x = 0 to its side x = 1.
  assert.ok(Math.abs(samples[0].s - -0.4 / Math.cos(Math.PI / 6)) < 1e-9, `${samples[0].s}`);
  assert.ok(Math.abs(samples.at(-1).s - 0.6 / Math.cos(Math.PI / 6)) < 1e-9, `${samples.at(-1).s}`);
  assert.deepEqual(samples.map((x) => x.s), [...samples.map((x) => x.s)].sort((a, b) => a - b));
  // A line that misses the contact faces: no samples.
  assert.deepEqual(sampleLine({ points3: p, faces, values, frame, centre: [3, 3, 0], thetaDegrees: 0 }), []);
  // Off a contact face between two crossed ones: null, not drawn.
  const some = faces.filter((f) => f.every((v) => p[3 * v] <= 0.25 + 1e-12 || p[3 * v] >= 0.75 - 1e-12));
  const gapped = sampleLine({ points3: p, faces: some, values, frame, centre: [0, 0.5, 0], thetaDegrees: 0, count: 41 });
  assert.ok(gapped.some((x) => x.value === null && x.s > 0.3 && x.s < 0.7));
  assert.ok(gapped.filter((x) => x.value === null).every((x) => x.s > 0.25 && x.s < 0.75));
});

test('the line is centred on the pressure-weighted centroid of the contact vertices, on the plane', () => {
  const points3 = [0, 0, 1, 2, 0, 1, 0, 4, 1, 9, 9, 9];
  const flags = [1, 1, 1, 0];
  const plane = { point: [0, 0, -1], normal: [0, 0, 5] };
  assert.deepEqual(pressureCentre(points3, flags, [1, 1, 2, 100], plane), [0.5, 2, -1]);
  assert.deepEqual(pressureCentre(points3, flags, [0, 0, 0, 0], plane), [2 / 3, 4 / 3, -1], 'no pressure: the plain centroid');
  assert.deepEqual(pressureCentre(points3, [0, 0, 0, 0], [0, 0, 0, 0], plane), [0, 0, -1], 'no contact vertex: the plane point');
});

test('3D Hertz for hertz_3d: E* = 8/3, a = 0.1 and p0 = 3F/(2πa²) at F = 0.0035556', () => {
  const F = 0.0035556;
  const h = hertzSphereContact(F, 1, { mu: 1, lambda: 1 });
  assert.ok(Math.abs(h.Estar - 8 / 3) < 1e-15);
  assert.ok(Math.abs(h.a - 0.1) < 1e-6, `a = ${h.a}`);
  assert.ok(Math.abs(h.p0 - (3 * F) / (2 * Math.PI * h.a ** 2)) < 1e-15);
  assert.ok(Math.abs(h.p0 - 0.169766) < 1e-5, `p0 = ${h.p0}`);
  // λ = ∞: ν = 1/2, E = 3μ, E* = 4μ.
  assert.equal(hertzSphereContact(F, 1, { mu: 1, lambda: Infinity }).Estar, 4);

  const caseDoc = JSON.parse(readFileSync(join(repo, 'solver', 'examples', '3d', 'hertz_3d.json'), 'utf8'));
  const result = { material: { mu: 1, lambda: 1 }, contact: { force: [1e-5, 1e-5, F] } };
  const fromResult = hertzForResult3d(result, caseDoc);
  assert.equal(fromResult.F, F);
  assert.equal(fromResult.R, 1);
  assert.ok(Math.abs(fromResult.a - 0.1) < 1e-6);
  // The normal force on a tilted plane; the radius the case gives, 1 when it gives none.
  const tilted = structuredClone(caseDoc);
  tilted.boundary.contact.normal = [0, 3, 4];
  tilted.mesh.builtin.radius = 2;
  const onTilted = hertzForResult3d({ ...result, contact: { force: [0, 1, 2] } }, tilted);
  assert.ok(Math.abs(onTilted.F - 2.2) < 1e-15 && onTilted.R === 2);
  assert.equal(halfBallRadius({ mesh: { builtin: 'half_ball' } }), 1);
  assert.equal(hertzForResult3d(result, { ...caseDoc, mesh: { builtin: 'box' } }), null, 'not a ball: no Hertz');
  assert.equal(hertzForResult3d({ ...result, material: { mu: 1, lambda: 'inf' } }, caseDoc).Estar, 4);
  assert.equal(hertzForResult3d({ ...result, contact: { force: [0, 0, 0] } }, caseDoc), null, 'no force: no Hertz');
  // A quarter ball (two symmetry planes against the zone) carries a quarter of the force.
  const quarter = hertzForResult3d({ ...result, contact: { force: [0, 0, F / 4], zone: { symmetry_planes: 2 } } }, caseDoc);
  assert.ok(Math.abs(quarter.F - F) < 1e-15 && Math.abs(quarter.a - 0.1) < 1e-6);
});

test('the default camera looks at the contact face from the plane, and a turn keeps the frame and the size', async () => {
  const { defaultCamera, pitch, project, paintOrder, yaw, boundingBall } = await import('../../web/app/surface_camera.js');
  const frame = planeFrame([0, 0, 1]);
  const camera = defaultCamera(frame);
  // From the plane's side (below the body): the viewer looks up, obliquely.
  assert.ok(camera.towards[2] < -0.7 && camera.towards[2] > -0.95, `towards ${camera.towards}`);
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const turned = pitch(yaw(camera, 0.7), -0.3);
  for (const c of [camera, turned]) {
    assert.ok(Math.abs(dot(c.right, c.up)) < 1e-12 && Math.abs(dot(c.up, c.towards)) < 1e-12 && Math.abs(dot(c.right, c.towards)) < 1e-12);
    const r = c.right, u = c.up;
    const cross = [r[1] * u[2] - r[2] * u[1], r[2] * u[0] - r[0] * u[2], r[0] * u[1] - r[1] * u[0]];
    assert.ok(cross.every((x, k) => Math.abs(x - c.towards[k]) < 1e-12), 'right × up = towards');
  }
  // The bottom of the box faces the default camera, its top does not; a turn keeps the size.
  const mesh = kuhnBox([2, 2, 2], [1, 1, 1]);
  const surface = boundarySurface(mesh);
  const ball = boundingBall(mesh.points3);
  const screen = project(mesh.points3, camera, ball, 400, 300);
  const visible = [...paintOrder(surface.triangles, screen)];
  const t = surface.triangles;
  const zOf = (f) => [0, 1, 2].map((k) => mesh.points3[3 * t[3 * f + k] + 2]);
  assert.ok(visible.some((f) => zOf(f).every((z) => z === 0)), 'the bottom is seen');
  assert.ok(!visible.some((f) => zOf(f).every((z) => z === 1)), 'the top is hidden');
  assert.ok(visible.length < t.length / 3 && visible.length > 0);
  // The distance of two vertices in screen coordinates (with depth): an orthographic turn keeps it.
  const extent = (s) => Math.hypot(s[0] - s[3 * 7], s[1] - s[3 * 7 + 1], s[2] - s[3 * 7 + 2]);
  assert.ok(extent(screen) > 10 && Math.abs(extent(screen) - extent(project(mesh.points3, turned, ball, 400, 300))) < 1e-9, 'lengths are kept by a turn');
  // Painter's order: each drawn triangle is no nearer than the next.
  const depth = (f) => [0, 1, 2].reduce((sum, k) => sum + screen[3 * t[3 * f + k] + 2], 0);
  assert.ok(visible.every((f, i) => i === 0 || depth(visible[i - 1]) <= depth(f)));
});

test('the 3D fields: pressure on the contact faces only, u·n along the plane normal, the magnification rule', async () => {
  const { SURFACE_FIELDS } = await import('../../web/app/surface_fields.js');
  const { autoMagnification, maxDisplacement } = await import('../../web/app/mesh_view.js');
  const mesh = parseVtu(boxAscii);
  const surface = boundarySurface(mesh);
  const contact = contactFaces(mesh, surface);
  const pressure = SURFACE_FIELDS.contact_pressure.compute(mesh, surface, { contact, normal: [0, 0, 1] }).values;
  const p = mesh.pointData.contact_pressure.values[0];
  pressure.forEach((v, f) => assert.ok(contact[f] ? Math.abs(v - p) < 1e-15 : Number.isNaN(v), `face ${f}: ${v}`));
  const un = SURFACE_FIELDS.u_normal.compute(mesh, surface, { contact, normal: [0, 0, 1] }).values;
  // The top (z = 1) moved by −0.01 along z, the bottom stays on the plane.
  surface.triangles.forEach((v, i) => {
    if (i % 3) return;
    const f = i / 3;
    const z = [0, 1, 2].map((k) => mesh.points3[3 * surface.triangles[i + k] + 2]);
    if (z.every((x) => x === 1)) assert.ok(Math.abs(un[f] + 0.01) < 1e-12);
    if (z.every((x) => x === 0)) assert.ok(Math.abs(un[f]) < 1e-12);
  });
  assert.equal(SURFACE_FIELDS.u_normal.compute(mesh, surface, { contact, normal: undefined }), null, 'no plane, no u·n');
  const vm = SURFACE_FIELDS.von_mises.compute(mesh, surface, { contact }).values;
  assert.ok(vm.every((v, f) => v === mesh.cellData.von_mises.values[surface.cells[f]]));
  // |u|max = 0.01 (the top), diagonal √3: 0.08·√3/0.01 = 13.9 → 10.
  assert.ok(Math.abs(maxDisplacement(mesh) - 0.01) < 1e-15);
  assert.equal(autoMagnification(mesh), 10);
});

test("the line's CSV: one row per sample, the pressure empty off the contact, Hertz at |s|", async () => {
  const { lineCsv } = await import('../../web/app/csv_export.js');
  const samples = [{ s: -0.5, value: null, point: [-0.5, 0, -1] }, { s: 0, value: 2, point: [0, 0, -1] }];
  assert.equal(lineCsv(samples), 's,x,y,z,pressure\n-0.5,-0.5,0,-1,\n0,0,0,-1,2\n');
  assert.equal(lineCsv(samples, { a: 1, p0: 3 }), 's,x,y,z,pressure,hertz_pressure\n-0.5,-0.5,0,-1,,' + `${3 * Math.sqrt(0.75)}\n0,0,0,-1,2,3\n`);
});

test('the contact planes of a 3D case: point and normal, or an obstacle of type plane; not a sphere or gap', () => {
  const caseDoc = {
    boundary: {
      top: { type: 'dirichlet', displacement: [0, 0, 0] },
      a: { type: 'contact', point: [0, 0, -1], normal: [0, 0, 1] },
      b: { type: 'contact', obstacle: { type: 'plane', point: [0, 0, 2], normal: [0, 0, -1], displacement: [0, 0, -0.5] } },
      c: { type: 'contact', obstacle: { type: 'sphere', center: [0, 0, 3], radius: 1 } },
      d: { type: 'contact', obstacle: { type: 'gap', g: '1 - z' } },
    },
  };
  assert.deepEqual(contactPlanes(caseDoc), [
    { group: 'a', point: [0, 0, -1], normal: [0, 0, 1] },
    { group: 'b', point: [0, 0, 1.5], normal: [0, 0, -1] },
  ]);
});

test('a sphere obstacle gives the line its tangent plane at the contact, the normal into the body', () => {
  const sphere = contactSpheres({
    boundary: { top: { type: 'contact', obstacle: { type: 'sphere', center: [1, 1, 12], radius: 10, displacement: [0, 0, -1] } } },
  })[0];
  assert.deepEqual(sphere, { group: 'top', center: [1, 1, 11], radius: 10 });
  // Contact vertices around (1, 1, 1), the pressure symmetric about it; one vertex off contact.
  const points3 = Float64Array.from([0.9, 1, 1, 1.1, 1, 1, 1, 0.9, 1, 1, 1.1, 1, 5, 5, 5]);
  const flags = Float64Array.from([1, 1, 1, 1, 0]);
  const pressure = Float64Array.from([2, 2, 3, 3, 100]);
  const plane = sphereTangentPlane(points3, flags, pressure, sphere);
  assert.deepEqual(plane.normal, [0, 0, -1]);
  for (let k = 0; k < 3; k++) assert.ok(Math.abs(plane.point[k] - [1, 1, 1][k]) < 1e-12, plane.point);
  assert.equal(sphereTangentPlane(points3, Float64Array.from([0, 0, 0, 0, 0]), pressure, sphere), null);
});
