// End-to-end test of the page's 3D job view: the shipped hertz_3d (at refinements 1, about a
// second) submitted from the editor to a real fosls-serve, shown in Debian's Chromium; a box
// pressed onto a plane and a ball pressed into a box; then a 2D job, whose view must come back
// as it was.
//
//   FOSLS_SERVE=build/bin/fosls-serve node --test tests/web/page3d.test.mjs
//
// Environment and start-up: tests/web/page_session.mjs. Needs web/build.sh to have run.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { expectPixelsOn } from './page_pixels.mjs';
import { openSession, repo, submitAndWaitForRow } from './page_session.mjs';

const { parseVtu } = await import(join(repo, 'web', 'app', 'vtu.js'));
const { fmt } = await import(join(repo, 'web', 'app', 'format.js'));
const hertzText = readFileSync(join(repo, 'solver', 'examples', 'hertz.json'), 'utf8');

let session;
let page;
let url;
const solid = {};  // the 3D job: id, result, mesh

const expectPixels = (...args) => expectPixelsOn(page, ...args);
const dataset = (selector) => page.locator(selector).evaluate((e) => ({ ...e.dataset }));
const getJson = async (path) => (await fetch(`${url}${path}`)).json();

/**
 * Pixels of the canvas read back in the page: `mode` 'keep' stores them; 'changed' counts the
 * pixels that differ from those stored; 'line' counts the pixels of the pressure line's black
 * (#111111) and those of them that were not black in the stored image.
 */
const canvasPixels = (selector, mode) => page.evaluate(({ selector, mode }) => {
  const canvas = document.querySelector(selector);
  const copy = Object.assign(document.createElement('canvas'), { width: canvas.width, height: canvas.height });
  const ctx = copy.getContext('2d', { willReadFrequently: true });
  ctx.drawImage(canvas, 0, 0);
  const { data } = ctx.getImageData(0, 0, copy.width, copy.height);
  const kept = window.keptPixels;
  if (mode === 'keep') {
    window.keptPixels = data;
    return {};
  }
  const black = (d, i) => Math.abs(d[i] - 17) + Math.abs(d[i + 1] - 17) + Math.abs(d[i + 2] - 17) <= 30;
  let changed = 0, line = 0, fresh = 0;
  for (let i = 0; i < data.length; i += 4) {
    if (Math.abs(data[i] - kept[i]) + Math.abs(data[i + 1] - kept[i + 1]) + Math.abs(data[i + 2] - kept[i + 2]) > 30) changed++;
    if (black(data, i)) {
      line++;
      if (!black(kept, i)) fresh++;
    }
  }
  return { changed, line, fresh };
}, { selector, mode });

/**
 * The boundary of a tetrahedral mesh counted here, apart from the page's module: faces found
 * once, and those of them whose three vertices carry contact_boundary = 1.
 */
function boundaryCounts(mesh) {
  const seen = new Map();
  const t = mesh.tetrahedra;
  for (let c = 0; c < t.length; c += 4) {
    for (const face of [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]) {
      const key = face.map((k) => t[c + k]).sort((a, b) => a - b).join(' ');
      seen.set(key, (seen.get(key) ?? 0) + 1);
    }
  }
  const once = [...seen].filter(([, n]) => n === 1).map(([key]) => key.split(' ').map(Number));
  const flags = mesh.pointData.contact_boundary.values;
  return { triangles: once.length, contact: once.filter((f) => f.every((v) => flags[v] === 1)).length };
}

before(async () => {
  session = await openSession();
  ({ page } = session);
  url = session.server.url;
});

after(() => session?.close());

test('hertz_3d from the example list: key numbers, the coloured surface and the pressure line with Hertz', async () => {
  await page.locator('#example-select option[value="hertz_3d"]').waitFor({ state: 'attached' });
  assert.equal(await page.locator('#example-select optgroup[label="3D"] option[value="hertz_3d"]').count(), 1);
  await page.locator('#example-select').selectOption('hertz_3d');
  await page.getByRole('button', { name: 'Load example' }).click();
  const shipped = JSON.parse(await page.locator('#case-text').inputValue());
  assert.equal(shipped.dimension, 3);
  shipped.mesh.refinements = 1;  // about a second instead of seven
  await page.locator('#case-text').fill(JSON.stringify(shipped, null, 2));
  const row = await submitAndWaitForRow(page, 'hertz_3d');
  await row.locator('.state-succeeded').waitFor({ timeout: 90000 });
  await page.waitForFunction(() => Number(document.querySelector('#surface-canvas')?.dataset.drawn) > 0 &&
    Number(document.querySelector('#line-plot')?.dataset.points) > 0);
  solid.id = Number(await row.getAttribute('data-job-id'));
  solid.result = await getJson(`/v1/jobs/${solid.id}/result`);
  solid.mesh = parseVtu(await (await fetch(`${url}/v1/jobs/${solid.id}/solution.vtu`)).text());
  const r = solid.result;
  assert.equal(r.dimension, 3);

  // The key numbers: the three force components of the result, Hertz's a and p0 for F = |Fz|.
  const numbers = await page.locator('#key-numbers').innerText();
  assert.ok(numbers.includes(`Contact force (Fx, Fy, Fz)\n${r.contact.force.map((f) => fmt(f)).join(', ')}`), numbers);
  const F = Math.abs(r.contact.force[2]);
  const a = Math.cbrt((3 * F) / (4 * (8 / 3)));  // R = 1, E* = 8/3 for μ = λ = 1
  const p0 = (3 * F) / (2 * Math.PI * a * a);
  assert.ok(numbers.includes(`Peak pressure\n${fmt(r.contact.max_pressure)} (Hertz p0 = ${fmt(p0)})`), numbers);
  assert.ok(numbers.includes(`Contact area\n${fmt(r.contact.area)}`), numbers);
  assert.equal(r.contact.zone.symmetry_planes, 0);
  assert.ok(numbers.includes(`Contact radius\n${fmt(r.contact.zone.radius)} (Hertz a = ${fmt(a)})`), numbers);
  assert.ok(numbers.includes(`Contact faces in contact\n${r.contact.faces_in_contact} of ${r.contact.faces}`), numbers);
  assert.ok(numbers.includes(`DOFs\n${r.dofs}`) && numbers.includes(`Tetrahedra\n${r.tetrahedra}`), numbers);
  assert.ok(numbers.includes(`Relative KKT residual\n${fmt(r.relative_kkt_residual, 3)}`), numbers);

  // The surface: the page's triangle counts are the mesh's, and the contact disc is coloured.
  const counts = boundaryCounts(solid.mesh);
  const canvas = await dataset('#surface-canvas');
  assert.equal(Number(canvas.triangles), counts.triangles);
  assert.equal(Number(canvas.contactTriangles), counts.contact);
  assert.ok(Number(canvas.drawn) > 0.3 * counts.triangles && Number(canvas.drawn) < counts.triangles, `${canvas.drawn} facing the viewer`);
  assert.equal(canvas.field, 'contact_pressure');
  assert.equal(Number(canvas.min), 0);
  // The colour bar runs from 0 to the largest vertex pressure (the coloured faces interpolate them).
  assert.equal(Number(canvas.max), Math.max(...solid.mesh.pointData.contact_pressure.values));
  const area = await page.locator('#surface-canvas').evaluate((c) => c.width * c.height);
  await expectPixels('#surface-canvas', null, 0.1 * area, 'the surface');
  await expectPixels('#surface-canvas', 'saturated', 0.005 * area, 'the pressure colours');
  assert.match(await page.locator('#surface-canvas').getAttribute('aria-label'),
    new RegExp(`^Deformed surface, ${counts.triangles} boundary triangles \\(${counts.contact} contact faces\\) of ${r.tetrahedra} tetrahedra, coloured by contact pressure from 0 to `));
  assert.match(await page.locator('#surface-legend-label').innerText(), /^contact pressure, in the stress unit of the case/);

  // The line: its peak is a sample of the vertex pressures, each the mean of its contact faces'
  // values: never above the largest face value (max_pressure) and, since the line runs through
  // the pressure-weighted centre next to the peak vertex, within 5 % of the largest vertex
  // value. (At refinements 1 that vertex mean is about 0.77 of max_pressure: the faces round
  // the pole differ by a quarter, so max_pressure itself is no tighter bound.)
  const line = await dataset('#line-plot');
  const peak = Number(line.peak);
  const vertexPeak = Math.max(...solid.mesh.pointData.contact_pressure.values);
  assert.ok(peak <= r.contact.max_pressure * (1 + 1e-12), `peak ${peak} against max_pressure ${r.contact.max_pressure}`);
  assert.ok(peak >= 0.95 * vertexPeak, `peak ${peak} against the largest vertex value ${vertexPeak}`);
  assert.ok(peak >= 0.6 * r.contact.max_pressure, `peak ${peak} against max_pressure ${r.contact.max_pressure}`);
  assert.equal(line.series, 'pressure|Hertz pressure (3D)');
  await expectPixels('#line-plot', '#1f5fbf', 50, 'the pressure line');
  await expectPixels('#line-plot', '#c0392b', 30, 'the Hertz curve');
  assert.match(await page.locator('#line-note').innerText(), new RegExp(`Dashed red: 3D Hertz .*a = ${fmt(a).replace('.', '\\.')}, p0 = ${fmt(p0).replace('.', '\\.')}\\.$`));
  const history = (r.history ?? []).filter((h) => h.kkt_residual > 0).length;
  assert.equal(await page.locator('#residual-plot').getAttribute('data-points'), String(history));
  if (history === 0) assert.equal(await page.locator('#residual-plot').innerText(), 'No iterations were recorded.');

  // The 2D-only parts are hidden.
  for (const selector of ['#pressure-plot', '#mesh-canvas', '#compare-job', '#download-contact-csv', '#friction-figure']) {
    assert.equal(await page.locator(selector).isVisible(), false, `${selector} hidden for 3D`);
  }
  const shot = await page.evaluate(() => {
    const box = document.querySelector('#job-view').getBoundingClientRect();
    return { x: box.x, y: box.y + window.scrollY, width: box.width, height: box.height };
  });
  await page.screenshot({ path: join(session.screenshots, 'job-view-3d.png'), fullPage: true, clip: shot });
});

test('the line follows its angle: chart, CSV and the line drawn on the surface', async () => {
  const before = await dataset('#line-plot');
  const csvOf = () => page.locator('#download-line-csv').evaluate(async (a) => (await fetch(a.href)).text());
  const firstCsv = await csvOf();
  await canvasPixels('#surface-canvas', 'keep');
  const draws = (await dataset('#surface-canvas')).draws;
  await page.locator('#line-angle').fill('45');
  await page.waitForFunction(() => document.querySelector('#line-plot').dataset.theta === '45');
  const after = await dataset('#line-plot');
  assert.ok(Number(after.points) > 0);
  const csv = await csvOf();
  assert.notEqual(csv, firstCsv);
  const rows = csv.trim().split('\n').map((l) => l.split(','));
  assert.deepEqual(rows[0], ['s', 'x', 'y', 'z', 'pressure', 'hertz_pressure']);
  const pressures = rows.slice(1).map((x) => x[4]).filter((v) => v !== '').map(Number);
  assert.equal(pressures.length, Number(after.points));
  assert.equal(Math.max(...pressures), Number(after.peak));
  // At 45° the direction is (1, 1, 0)/√2 in the plane z = −1.
  const [s, x, y, z] = rows[1].map(Number);
  const centre = [x - s / Math.SQRT2, y - s / Math.SQRT2];
  const [s2, x2, y2, z2] = rows.at(-1).map(Number);
  assert.ok(Math.abs(x2 - (centre[0] + s2 / Math.SQRT2)) < 1e-9 && Math.abs(y2 - (centre[1] + s2 / Math.SQRT2)) < 1e-9 && z === -1 && z2 === -1);
  assert.notEqual(after.peak, before.peak, 'another line, another peak');
  await page.waitForFunction((n) => document.querySelector('#surface-canvas').dataset.draws !== n, draws);
  const { line, fresh } = await canvasPixels('#surface-canvas', 'line');
  assert.ok(line > 100 && fresh > 0.5 * line, `the line on the surface: ${line} pixels, ${fresh} of them new at 45°`);
  assert.match(await page.locator('#line-note').innerText(), /at θ = 45°/);
});

test('the surface turns by drag and keys, zooms, resets, and is coloured by other fields', async () => {
  const canvas = page.locator('#surface-canvas');
  await canvas.scrollIntoViewIfNeeded();
  const start = (await dataset('#surface-canvas')).view;
  await canvasPixels('#surface-canvas', 'keep');
  const box = await canvas.boundingBox();
  const at = [box.x + box.width / 2, box.y + box.height / 2];
  await page.mouse.move(...at);
  await page.mouse.down();
  await page.mouse.move(at[0] + 40, at[1] + 10, { steps: 3 });
  await page.mouse.move(at[0] + 90, at[1] + 20, { steps: 3 });
  await page.mouse.up();
  await page.waitForFunction((v) => document.querySelector('#surface-canvas').dataset.view !== v, start);
  const area = await canvas.evaluate((c) => c.width * c.height);
  const { changed } = await canvasPixels('#surface-canvas', 'changed');
  assert.ok(changed > 0.02 * area, `${changed} of ${area} pixels changed by the turn`);

  await canvas.focus();
  await page.keyboard.press('0');
  await page.waitForFunction((v) => document.querySelector('#surface-canvas').dataset.view === v, start);
  await page.keyboard.press('ArrowLeft');
  await page.waitForFunction((v) => document.querySelector('#surface-canvas').dataset.view !== v, start);
  await page.keyboard.press('+');
  await page.waitForFunction(() => document.querySelector('#surface-canvas').dataset.zoom === '1.25');
  await page.locator('#surface-reset').click();
  await page.waitForFunction((v) => {
    const d = document.querySelector('#surface-canvas').dataset;
    return d.zoom === '1' && d.view === v;
  }, start);

  // |u| and u·n: the range changes with the field, and the colour bar says what it shows.
  await page.locator('#surface-field').selectOption('u_normal');
  await page.waitForFunction(() => document.querySelector('#surface-canvas').dataset.field === 'u_normal');
  const un = await dataset('#surface-canvas');
  assert.ok(Number(un.min) < Number(un.max) && Number(un.min) < 0, `u·n from ${un.min} to ${un.max}: the body moves towards the plane`);
  assert.match(await page.locator('#surface-legend-label').innerText(), /^displacement u·n \(along the plane normal\), in the length unit of the mesh/);
  await page.locator('#surface-field').selectOption('displacement');
  await page.waitForFunction(() => document.querySelector('#surface-canvas').dataset.field === 'displacement');
  const umax = Math.max(...solid.mesh.pointData.u.values.map(Math.abs));
  assert.ok(Number((await dataset('#surface-canvas')).max) >= 0.5 * umax);
  await page.locator('#surface-field').selectOption('contact_pressure');
  await page.locator('#surface-magnification').fill('1');
  await page.locator('#surface-caption', { hasText: 'magnified ×1;' }).waitFor();
  await page.locator('#surface-auto').click();
  await page.locator('#surface-caption', { hasText: 'magnified ×20;' }).waitFor();
});

test('a 3D case that is not the half ball: no Hertz curve, a flat pressure under a pressed box', async () => {
  const box = readFileSync(join(repo, 'tests', 'web', 'fixtures', 'box_3d.json'), 'utf8');
  await page.locator('#case-text').fill(box);
  const row = await submitAndWaitForRow(page, 'box_3d');
  await row.locator('.state-succeeded').waitFor();
  await page.waitForFunction(() => document.querySelector('#surface-canvas')?.dataset.triangles === '12' &&
    Number(document.querySelector('#line-plot')?.dataset.points) > 0);
  const result = await getJson(`/v1/jobs/${await row.getAttribute('data-job-id')}/result`);
  const numbers = await page.locator('#key-numbers').innerText();
  assert.ok(!numbers.includes('Hertz'), numbers);
  assert.equal(await page.locator('#line-plot').getAttribute('data-series'), 'pressure');
  assert.doesNotMatch(await page.locator('#line-note').innerText(), /Hertz/);
  // The whole bottom is pressed evenly: the line crosses the unit square with one pressure.
  const peak = Number(await page.locator('#line-plot').getAttribute('data-peak'));
  assert.ok(Math.abs(peak - result.contact.max_pressure) < 1e-9 * peak, `${peak} against ${result.contact.max_pressure}`);
  assert.equal(await page.locator('#surface-canvas').getAttribute('data-contact-triangles'), '2');
});

test('a ball pressed into a box: the pressure line runs in its tangent plane, through the peak', async () => {
  const ball = readFileSync(join(repo, 'tests', 'web', 'fixtures', 'ball_on_box_3d.json'), 'utf8');
  await page.locator('#case-text').fill(ball);
  const row = await submitAndWaitForRow(page, 'ball_on_box_3d');
  await row.locator('.state-succeeded').waitFor();
  await page.waitForFunction(() => document.querySelector('#line-plot')?.dataset.points !== undefined &&
    Number(document.querySelector('#line-plot')?.dataset.points) > 0);
  const result = await getJson(`/v1/jobs/${await row.getAttribute('data-job-id')}/result`);
  assert.ok(result.contact.force[2] < 0, 'the ball pushes the box down');
  assert.ok(!(await page.locator('#key-numbers').innerText()).includes('Hertz'));
  // The tangent plane at the contact, near the top's centre (1, 1, 1) (the Kuhn mesh is not
  // symmetric, so the pressure centroid is off it by about 0.014): the line runs through a point
  // on the sphere there, t1 nearly horizontal; its peak is a vertex mean, at most the largest
  // face value.
  const note = await page.locator('#line-note').innerText();
  const [, centre, t1] = note.match(/^The line through \(([^)]*)\) at θ = [^ ]+ from t1 = \(([^)]*)\), in the contact plane/) ?? [];
  assert.ok(centre && t1, note);
  const c = centre.split(', ').map(Number);
  assert.ok(Math.hypot(c[0] - 1, c[1] - 1, c[2] - 1) < 0.05, note);
  assert.ok(Math.abs(Math.hypot(c[0] - 1, c[1] - 1, c[2] - 11) - 10) < 1e-3, `on the sphere (to the note's 4 digits): ${note}`);
  assert.ok(Math.abs(Number(t1.split(', ')[2])) < 0.01, note);
  const peak = Number(await page.locator('#line-plot').getAttribute('data-peak'));
  assert.ok(peak > 0 && peak <= result.contact.max_pressure * (1 + 1e-12), `${peak} against ${result.contact.max_pressure}`);
});

test('a 2D job after the 3D one shows the 2D view, and comes back the same after the 3D one again', async () => {
  const variant = JSON.parse(hertzText);
  variant.mesh.refinements = 1;
  variant.name = 'hertz_2d';
  await page.locator('#case-text').fill(JSON.stringify(variant, null, 2));
  const row = await submitAndWaitForRow(page, 'hertz_2d');
  await row.locator('.state-succeeded').waitFor();
  await page.waitForFunction(() => Number(document.querySelector('#pressure-plot')?.dataset.points) > 0 &&
    Number(document.querySelector('#mesh-canvas')?.dataset.triangles) > 0);
  const shown2d = async () => ({
    numbers: await page.locator('#key-numbers').innerText(),
    series: await page.locator('#pressure-plot').getAttribute('data-series'),
    mesh: await page.locator('#mesh-canvas').getAttribute('aria-label'),
    visible: await Promise.all(['#pressure-plot', '#mesh-canvas', '#compare-job', '#download-contact-csv', '#line-plot', '#surface-canvas', '#download-line-csv']
      .map((s) => page.locator(s).isVisible())),
  });
  const first = await shown2d();
  assert.match(first.numbers, /^Contact force \(Fx, Fy\)/);
  assert.ok(!first.numbers.includes('Fz'));
  assert.deepEqual(first.visible, [true, true, true, true, false, false, false]);
  assert.equal(first.series, 'pressure|gap|Hertz pressure (plane strain)');
  await expectPixels('#mesh-canvas', null, 1000, 'the 2D mesh');

  await page.locator(`#job-table [data-action="view"][data-job-id="${solid.id}"]`).click();
  await page.waitForFunction(() => document.querySelector('#job-result').dataset.dimension === '3' &&
    !document.querySelector('#job-result').hidden);
  await page.locator('#key-numbers', { hasText: 'Fz' }).waitFor();
  assert.equal(await page.locator('#surface-canvas').isVisible(), true);

  await page.locator(`#job-table [data-action="view"][data-job-id="${await row.getAttribute('data-job-id')}"]`).click();
  await page.locator('#key-numbers', { hasText: 'Contact force (Fx, Fy)' }).waitFor();
  await page.waitForFunction(() => Number(document.querySelector('#pressure-plot')?.dataset.points) > 0);
  assert.deepEqual(await shown2d(), first);
});

test('a 3D adaptive run shows its steps: tetrahedra, three force components and the N^(−⅓) slope', async () => {
  await page.locator('#example-select').selectOption('hertz_3d');
  await page.getByRole('button', { name: 'Load example' }).click();
  const adaptive = JSON.parse(await page.locator('#case-text').inputValue());
  adaptive.name = 'hertz_3d_adaptive_page';
  adaptive.mesh.refinements = 0;
  adaptive.adaptivity = { steps: 2, theta: 0.5 };
  await page.locator('#case-text').fill(JSON.stringify(adaptive, null, 2));
  const row = await submitAndWaitForRow(page, 'hertz_3d_adaptive_page');
  await row.locator('.state-succeeded').waitFor({ timeout: 90000 });
  await page.locator(`#job-table [data-action="view"][data-job-id="${await row.getAttribute('data-job-id')}"]`).click();
  await page.waitForFunction(() => document.querySelector('#job-result').dataset.dimension === '3' &&
    document.querySelectorAll('#adaptivity-table tbody tr').length > 0);
  const result = await getJson(`/v1/jobs/${await row.getAttribute('data-job-id')}/result`);
  const steps = result.adaptivity.steps;
  assert.equal(await page.locator('#adaptivity-section').isVisible(), true);
  assert.equal(await page.locator('#adaptivity-table tbody tr').count(), steps.length);
  const headings = await page.locator('#adaptivity-table thead th').allInnerTexts();
  assert.deepEqual(headings.slice(2, 8), ['tetrahedra', 'iterations', 'J^½', 'F_x', 'F_y', 'F_z']);
  const last = await page.locator('#adaptivity-table tbody tr').last().locator('td').allInnerTexts();
  assert.equal(last[2], String(steps[steps.length - 1].tetrahedra));
  assert.match(await page.locator('#adaptivity-plot').getAttribute('data-series'), /N\^\(−⅓\)/);
  assert.match(await page.locator('#adaptivity-note').innerText(), /The surface below is the last step's/);
});

test('a 3D sweep plots |F| against the swept value and offers its CSV', async () => {
  await page.locator('#example-select').selectOption('hertz_3d');
  await page.getByRole('button', { name: 'Load example' }).click();
  const swept = JSON.parse(await page.locator('#case-text').inputValue());
  swept.name = 'hertz_3d_sweep_page';
  swept.mesh.refinements = 0;
  swept.sweep = { pointer: '/boundary/top/displacement/2', values: [-0.005, -0.01] };
  await page.locator('#case-text').fill(JSON.stringify(swept, null, 2));
  const row = await submitAndWaitForRow(page, 'hertz_3d_sweep_page');
  await row.locator('.state-succeeded').waitFor({ timeout: 90000 });
  await page.locator(`#job-table [data-action="view"][data-job-id="${await row.getAttribute('data-job-id')}"]`).click();
  await page.waitForFunction(() => document.querySelector('#job-result').dataset.dimension === '3' &&
    Number(document.querySelector('#sweep-plot')?.dataset.points) > 0);
  assert.equal(await page.locator('#sweep-figure').isVisible(), true);
  assert.equal(await page.locator('#sweep-plot').getAttribute('data-points'), '2');
  assert.equal(await page.locator('#adaptivity-section').isVisible(), false);
  assert.equal(await page.locator('#download-sweep-csv').isVisible(), true);
  const csv = await page.evaluate(async () => (await fetch(document.querySelector('#download-sweep-csv').href)).text());
  assert.match(csv, /^\/boundary\/top\/displacement\/2,force_x,force_y,force_z,peak_pressure,contact_radius,/);
  assert.equal(csv.trim().split('\n').length, 3);
});

test('the 3D pages logged no console errors or warnings', () => {
  assert.deepEqual(session.consoleProblems, []);
});
