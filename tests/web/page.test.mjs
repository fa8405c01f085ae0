// End-to-end test of the web page: a real fosls-serve (free loopback port, temporary
// database) and Debian's Chromium driven by playwright-core. Never downloads a browser.
//
//   FOSLS_SERVE=build/bin/fosls-serve node --test tests/web/page.test.mjs
//
// Environment and start-up: tests/web/page_session.mjs (FOSLS_SERVE required; FOSLS_WEB_ROOT,
// FOSLS_SCREENSHOTS, CHROMIUM, FOSLS_REFRESH_SCREENSHOTS=1 to refresh docs/screenshots).
// Needs web/build.sh to have run (npm packages, web/dist).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { expectPixelsOn } from './page_pixels.mjs';
import { checkFrictionAndLoadSteps } from './page_friction.mjs';
import { openSession, repo, submitAndWaitForRow as submitOnPage } from './page_session.mjs';

const hertzText = readFileSync(join(repo, 'solver', 'examples', 'hertz.json'), 'utf8');
const { parseVtu } = await import(join(repo, 'web', 'app', 'vtu.js'));
const { MESH_FIELDS } = await import(join(repo, 'web', 'app', 'mesh_fields.js'));
const { fmt, seconds } = await import(join(repo, 'web', 'app', 'format.js'));

let session;      // server, browser and page (tests/web/page_session.mjs)
let server;       // {url, log}
let page;
let screenshots;  // folder for the screenshots
let consoleProblems;

// The page's canvases read back in the browser (tests/web/page_pixels.mjs), on this test's page.
const expectPixels = (...args) => expectPixelsOn(page, ...args);

async function setEditorText(text) {
  await page.locator('#case-text').fill(text);
}

/// The shipped Hertz case under another name, at `refinements`, changed by `change`, submitted
/// from the editor: its row in the job list.
async function submitHertzVariant(name, refinements, change) {
  const variant = JSON.parse(hertzText);
  variant.name = name;
  variant.mesh.refinements = refinements;
  change(variant);
  await setEditorText(JSON.stringify(variant, null, 2));
  return submitAndWaitForRow(name);
}

const submitAndWaitForRow = (name) => submitOnPage(page, name);

before(async () => {
  session = await openSession();
  ({ server, page, screenshots, consoleProblems } = session);
});

after(() => session?.close());

test('the page loads the shipped examples into the editor', async () => {
  await page.locator('#example-select option[value="hertz"]').waitFor({ state: 'attached' });
  await page.waitForFunction(() => document.querySelector('#case-text').value.length > 0);
  const options = await page.locator('#example-select option').allInnerTexts();
  for (const name of ['hertz', 'hertz_incompressible', 'signorini_square', 'linear_square']) {
    assert.ok(options.includes(name), `example ${name} in ${options}`);
  }
  assert.equal(await page.locator('#example-select').inputValue(), 'hertz');
  assert.equal(await page.locator('#case-text').inputValue(), hertzText);
  assert.equal(await page.locator('#jobs-empty').isVisible(), true);
});

test('submitting the hertz case shows pressure with the Hertz curve, residuals and the mesh', async () => {
  const row = await submitAndWaitForRow('hertz');
  await row.locator('[data-state="succeeded"], .state-succeeded').waitFor();
  await page.locator('#job-result').waitFor({ state: 'visible' });
  await page.waitForFunction(() => Number(document.querySelector('#pressure-plot')?.dataset.points) > 0 &&
    Number(document.querySelector('#residual-plot')?.dataset.points) > 0 &&
    Number(document.querySelector('#mesh-canvas')?.dataset.triangles) > 0);

  const jobId = Number(await row.getAttribute('data-job-id'));
  // Requests of the test itself go from node, so the page's console shows only the page's own.
  const result = await (await fetch(`${server.url}/v1/jobs/${jobId}/result`)).json();
  assert.equal(result.converged, true);
  assert.equal(await page.locator('#pressure-plot').getAttribute('data-points'), String(result.contact.x.length));
  const positiveKkt = result.history.filter((h) => h.kkt_residual > 0).length;
  assert.equal(await page.locator('#residual-plot').getAttribute('data-points'), String(positiveKkt));

  // The curves are drawn: pixels of each series colour on the charts' canvases.
  await expectPixels('#pressure-plot', '#1f5fbf', 100, 'FOSLS pressure line');
  await expectPixels('#pressure-plot', '#c0392b', 50, 'Hertz curve');
  await expectPixels('#residual-plot', '#1f5fbf', 100, 'KKT residual line');
  const canvasArea = await page.evaluate(() => document.querySelector('#mesh-canvas').width * document.querySelector('#mesh-canvas').height);
  await expectPixels('#mesh-canvas', null, 0.1 * canvasArea, 'mesh');

  // The Hertz numbers follow from the result's force: E* = 4μ(λ+μ)/(λ+2μ) = 8/3 for μ = λ = 1.
  const F = Math.abs(result.contact.force[1]);
  const a = Math.sqrt((4 * F * 1) / (Math.PI * (8 / 3)));
  const note = await page.locator('#hertz-note').innerText();
  assert.match(note, new RegExp(`a = ${Number(a.toPrecision(4))}`.replace('.', '\\.')), note);
  const numbers = await page.locator('#key-numbers').innerText();
  assert.match(numbers, /Hertz 2a = /);
  // One contact width everywhere: the page shows the result's contact.zone.width.
  assert.match(numbers, new RegExp(`Contact width\\s+${fmt(result.contact.zone.width).replace('.', '\\.')} \\(Hertz 2a`), numbers);
  assert.match(numbers, new RegExp(`DOFs\\s+${result.dofs}`));
  assert.match(numbers, new RegExp(`Iterations\\s+${result.iterations}`));
  assert.match(await page.locator('#mesh-caption').innerText(), /magnified ×\d+/);
  assert.equal(await page.locator('#sweep-figure').isVisible(), false, 'no sweep, no sweep plot');
  assert.equal(await page.locator('#adaptivity-section').isVisible(), false, 'uniform, no adaptive steps');

  // Downloads point at the API and answer.
  for (const [link, type] of [['#download-result', 'application/json'], ['#download-vtu', 'application/xml']]) {
    const href = await page.locator(link).getAttribute('href');
    const r = await fetch(new URL(href, server.url));
    const status = `${r.status} ${r.headers.get('Content-Type')}`;
    assert.equal(status, `200 ${type}`, href);
  }

  await page.screenshot({ path: join(screenshots, 'job-view.png'), fullPage: true });
});

/** The job's VTU, parsed by the page's own reader. */
async function solutionOf(jobId) {
  return parseVtu(await (await fetch(`${server.url}/v1/jobs/${jobId}/solution.vtu`)).text());
}

const shownJobId = () => page.evaluate(() => Number(/^#job-(\d+)$/.exec(location.hash)?.[1]));

test('the mesh is coloured by each stress component, with its range and unit on the colour bar', async () => {
  const mesh = await solutionOf(await shownJobId());
  const signs = [];
  for (const [id, component] of [['sigma_xx', 0], ['sigma_xy', 1], ['sigma_yx', 2], ['sigma_yy', 3]]) {
    await page.locator('#mesh-field').selectOption(id);
    await page.waitForFunction((f) => document.querySelector('#mesh-canvas').dataset.field === f, id);
    const sigma = mesh.cellData.sigma;
    const values = [];
    for (let c = component; c < sigma.values.length; c += 4) values.push(sigma.values[c]);
    const canvas = page.locator('#mesh-canvas');
    assert.equal(Number(await canvas.getAttribute('data-min')), Math.min(...values), `${id} minimum`);
    assert.equal(Number(await canvas.getAttribute('data-max')), Math.max(...values), `${id} maximum`);
    const label = await page.locator('#legend-label').innerText();
    assert.ok(label.startsWith(`σ_${id.slice(-2)}, in the stress unit of the case (that of μ or E); here μ = 1`), label);
    // A component with both signs: the diverging map on a range symmetric about 0.
    const bothSigns = Math.min(...values) < 0 && Math.max(...values) > 0;
    assert.equal(await canvas.getAttribute('data-colour-map'), bothSigns ? 'coolwarm' : 'viridis', id);
    if (bothSigns) {
      assert.equal(await page.locator('#legend-min').innerText(), `-${await page.locator('#legend-max').innerText()}`);
      assert.match(label, /blue < 0 < red/);
    }
    signs.push(bothSigns);
  }
  assert.ok(signs.some(Boolean), 'some component of the Hertz stress takes both signs');
  // The four components have four different minima here, so a component mix-up would fail above.
  const minima = ['sigma_xx', 'sigma_xy', 'sigma_yx', 'sigma_yy'].map((id) => Math.min(...MESH_FIELDS[id].compute(mesh)));
  assert.equal(new Set(minima).size, 4, `minima ${minima}`);
  await page.locator('#mesh-field').selectOption('displacement');
  await page.locator('#legend-label', { hasText: 'displacement |u|, in the length unit of the mesh' }).waitFor();
  await page.locator('#mesh-field').selectOption('von_mises');
  await page.waitForFunction(() => document.querySelector('#mesh-canvas').dataset.colourMap === 'viridis');
});

test('pressure and gap are plotted along the contact boundary', async () => {
  const result = await (await fetch(`${server.url}/v1/jobs/${await shownJobId()}/result`)).json();
  const plot = page.locator('#pressure-plot');
  assert.equal(await plot.getAttribute('data-series'), 'pressure|gap|Hertz pressure (plane strain)');
  assert.equal(await plot.getAttribute('data-points'), String(result.contact.gap.length));
  await expectPixels('#pressure-plot', '#2e8b57', 100, 'gap line');
  // The CSV link holds the same numbers, one row per contact edge.
  const csv = await page.locator('#download-contact-csv').evaluate(async (a) => (await fetch(a.href)).text());
  const rows = csv.trim().split('\n').map((line) => line.split(','));
  assert.deepEqual(rows[0], ['x', 'y', 's', 'length', 'pressure', 'gap', 'active']);
  assert.equal(rows.length - 1, result.contact.x.length);
  assert.deepEqual(rows.slice(1).map((r) => Number(r[4])), result.contact.pressure);
  assert.deepEqual(rows.slice(1).map((r) => Number(r[5])), result.contact.gap);
  assert.equal(await page.locator('#sweep-csv-item').isVisible(), false, 'no sweep, no sweep CSV');
  // The gap (an edge mean) nearly closes where the edge carries pressure, and opens at the ends.
  const gap = result.contact.gap;
  const gmax = Math.max(...gap);
  assert.ok(gap.every((g, i) => !result.contact.active[i] || Math.abs(g) < 1e-2 * gmax) && gap[0] > 0.5 * gmax);
});

test('the mesh view zooms about the pointer, pans, shows edges and probes values', async () => {
  const jobId = await shownJobId();
  const mesh = await solutionOf(jobId);
  const canvas = page.locator('#mesh-canvas');
  // Without magnification the view is an affine map of the mesh, so distances compare exactly.
  await page.locator('#mesh-magnification').fill('0');
  await canvas.scrollIntoViewIfNeeded();
  const box = await canvas.boundingBox();
  const at = [Math.round(box.x + box.width / 2), Math.round(box.y + box.height * 0.55)];  // wheel events carry whole pixels
  const probeAt = async (x, y) => {
    await page.locator('#mesh-probe').evaluate((e) => delete e.dataset.cell);
    await page.mouse.move(x, y);
    await page.waitForFunction(() => document.querySelector('#mesh-probe').dataset.cell !== undefined);
    const d = await page.locator('#mesh-probe').evaluate((e) => ({ ...e.dataset }));
    return { cell: Number(d.cell), value: Number(d.value), x: Number(d.x), y: Number(d.y), u: [Number(d.ux), Number(d.uy)] };
  };
  const p0 = await probeAt(...at);
  const p1 = await probeAt(at[0] + 100, at[1]);
  const perPixel = (p1.x - p0.x) / 100;
  assert.ok(perPixel > 0 && Math.abs(p1.y - p0.y) < 1e-12, 'x to the right, y unchanged');

  // The probe reports the drawn triangle's value and a point inside that triangle.
  assert.equal(p0.value, mesh.cellData.von_mises.values[p0.cell]);
  const tri = [0, 1, 2].map((k) => mesh.triangles[3 * p0.cell + k]);
  const [[ax, ay], [bx, by], [cx, cy]] = tri.map((v) => [mesh.points[2 * v], mesh.points[2 * v + 1]]);
  const cross = (ux, uy, vx, vy) => ux * vy - uy * vx;
  const signs = [cross(bx - ax, by - ay, p0.x - ax, p0.y - ay), cross(cx - bx, cy - by, p0.x - bx, p0.y - by), cross(ax - cx, ay - cy, p0.x - cx, p0.y - cy)];
  assert.ok(signs.every((v) => v >= -1e-15) || signs.every((v) => v <= 1e-15), `point in triangle ${p0.cell}`);
  assert.match(await page.locator('#mesh-probe').innerText(), /^Probe: x = .*von Mises stress = .*σ = \[.*u = \(/);
  // u at the probed point: the linear interpolation of the triangle's vertex values.
  const twiceArea = cross(bx - ax, by - ay, cx - ax, cy - ay);
  const weights = [signs[1] / twiceArea, signs[2] / twiceArea, signs[0] / twiceArea];
  const uAt = (d) => weights.reduce((sum, w, k) => sum + w * mesh.pointData.u.values[tri[k] * mesh.pointData.u.components + d], 0);
  const probed = p0.u;
  const umax = Math.max(...mesh.pointData.u.values.map(Math.abs));
  assert.ok(Math.abs(probed[0] - uAt(0)) < 1e-9 * umax && Math.abs(probed[1] - uAt(1)) < 1e-9 * umax, `u ${probed} against ${uAt(0)}, ${uAt(1)}`);

  // Zoom about the pointer: the point under it stays, 100 px span 1/zoom of the length.
  await page.mouse.move(...at);
  await page.mouse.wheel(0, -600);
  await page.waitForFunction(() => Number(document.querySelector('#mesh-canvas').dataset.zoom) > 2);
  const zoom = Number(await canvas.getAttribute('data-zoom'));
  const q0 = await probeAt(...at);
  const q1 = await probeAt(at[0] + 100, at[1]);
  assert.ok(Math.abs(q0.x - p0.x) < 1e-12 && Math.abs(q0.y - p0.y) < 1e-12, `fixed point of the zoom: ${JSON.stringify([p0, q0, zoom])}`);
  assert.ok(Math.abs((q1.x - q0.x) / 100 / (perPixel / zoom) - 1) < 1e-3, `zoom ${zoom}: ${(q1.x - q0.x) / 100} per pixel`);

  // Drag to pan by 50 px: the mesh moves with the pointer.
  await page.mouse.move(...at);
  await page.mouse.down();
  await page.mouse.move(at[0] + 25, at[1], { steps: 2 });
  await page.mouse.move(at[0] + 50, at[1], { steps: 2 });
  await page.mouse.up();
  const r0 = await probeAt(at[0] + 50, at[1]);
  assert.ok(Math.abs(r0.x - q0.x) < 1e-12 && Math.abs(r0.y - q0.y) < 1e-12, `panned: ${r0.x} against ${q0.x}`);

  // A click pins the probe and marks it; the keyboard's 0 resets the view.
  await page.mouse.click(...at);
  assert.match(await page.locator('#mesh-probe').innerText(), /^Pinned: /);
  await canvas.focus();
  await page.keyboard.press('0');
  await page.waitForFunction(() => document.querySelector('#mesh-canvas').dataset.zoom === '1');
  await page.keyboard.press('+');
  await page.waitForFunction(() => document.querySelector('#mesh-canvas').dataset.zoom === '1.25');
  await page.getByRole('button', { name: 'Reset view' }).click();
  await page.waitForFunction(() => document.querySelector('#mesh-canvas').dataset.zoom === '1');

  // Mesh edges: dark lines over the colours, so many pixels get darker than without them.
  const darkened = (compare) => page.evaluate((compare) => {
    const canvas = document.querySelector('#mesh-canvas');
    const copy = Object.assign(document.createElement('canvas'), { width: canvas.width, height: canvas.height });
    const ctx = copy.getContext('2d', { willReadFrequently: true });
    ctx.drawImage(canvas, 0, 0);
    const { data } = ctx.getImageData(0, 0, copy.width, copy.height);
    if (!compare) {
      window.meshSnapshot = data;
      return 0;
    }
    let n = 0;
    for (let i = 0; i < data.length; i += 4) {
      const before = window.meshSnapshot[i] + window.meshSnapshot[i + 1] + window.meshSnapshot[i + 2];
      if (before - (data[i] + data[i + 1] + data[i + 2]) > 60) n++;
    }
    return n;
  }, compare);
  await darkened(false);
  await page.locator('#mesh-edges').check();
  await page.waitForFunction(() => document.querySelector('#mesh-canvas').dataset.edges === 'on');
  const area = await canvas.evaluate((c) => c.width * c.height);
  const n = await darkened(true);
  assert.ok(n > 0.02 * area, `${n} of ${area} pixels darker with the edges`);
  await page.screenshot({ path: join(screenshots, 'mesh-probe.png'), clip: { x: box.x - 10, y: box.y - 80, width: box.width + 20, height: box.height + 160 } });
  await page.locator('#mesh-edges').uncheck();
  await page.getByRole('button', { name: 'Auto' }).click();
});

test('an adaptive run shows its steps: the log–log plot, the table and the adapted mesh', async () => {
  await page.locator('#example-select').selectOption('hertz_adaptive');
  await page.getByRole('button', { name: 'Load example' }).click();
  const row = await submitAndWaitForRow('hertz_adaptive');
  await row.locator('.state-succeeded').waitFor();
  const jobId = Number(await row.getAttribute('data-job-id'));
  const result = await (await fetch(`${server.url}/v1/jobs/${jobId}/result`)).json();
  const steps = result.adaptivity.steps;
  assert.ok(steps.length >= 3, `${steps.length} adaptive steps`);
  await page.waitForFunction((n) => document.querySelector('#adaptivity-plot')?.dataset.points === String(n) &&
    document.querySelectorAll('#adaptivity-table tbody tr').length === n &&
    Number(document.querySelector('#mesh-canvas')?.dataset.triangles) > 0, steps.length);

  // The plot: one point per step of J^½ and of the force change, both drawn.
  assert.equal(await page.locator('#adaptivity-plot').getAttribute('data-series'),
    'J^½ (estimator)|N^(−½) (optimal rate)||ΔF| / |F| (force change)');
  await expectPixels('#adaptivity-plot', '#1f5fbf', 50, 'estimator line');
  await expectPixels('#adaptivity-plot', '#2e8b57', 30, 'force change line');

  // The table: one row per step, each number the result's (to the digits shown).
  const headings = await page.locator('#adaptivity-table thead th').allInnerTexts();
  assert.deepEqual(headings, ['step', 'unknowns', 'triangles', 'iterations', 'J^½', 'F_x', 'F_y', '|ΔF| / |F|', 'algebraic error', 'time']);
  const cells = await page.locator('#adaptivity-table tbody tr').evaluateAll((rs) => rs.map((r) => [...r.cells].map((c) => c.textContent)));
  const close = (text, want, digits) => Math.abs(Number(text) - want) <= 0.51 * 10 ** (1 - digits) * Math.abs(want);
  steps.forEach((s, k) => {
    const c = cells[k];
    assert.deepEqual(c.slice(0, 4), [String(s.step), String(s.dofs), String(s.triangles), String(s.iterations)], `step ${k}`);
    assert.ok(close(c[4], s.estimator, 4), `J^½ ${c[4]} against ${s.estimator}`);
    assert.ok(close(c[6], s.force[1], 4), `F_y ${c[6]} against ${s.force[1]}`);
    assert.equal(c[5], fmt(s.force[0]));
    const change = k > 0 ? Math.hypot(s.force[0] - steps[k - 1].force[0], s.force[1] - steps[k - 1].force[1]) / Math.hypot(...s.force) : null;
    if (change === null) assert.equal(c[7], '—');
    else assert.ok(close(c[7], change, 2), `|ΔF|/|F| ${c[7]} against ${change}`);
    assert.equal(c[8], fmt(s.algebraic_error ?? null, 2));
    assert.equal(c[9], seconds(s.time_s));
  });
  assert.ok(steps.at(-1).dofs > steps[0].dofs && steps.at(-1).estimator < steps[0].estimator, 'refined and improved');
  assert.match(await page.locator('#key-numbers').innerText(), new RegExp(`Adaptive steps\\s+${steps.length} \\(stopped: ${result.adaptivity.stop_reason}\\)`));

  // The mesh is the last step's adapted mesh, coloured by the refinement generation of the VTU.
  assert.equal(Number(await page.locator('#mesh-canvas').getAttribute('data-triangles')), steps.at(-1).triangles);
  const mesh = await solutionOf(jobId);
  const generation = [...mesh.cellData.generation.values];
  await page.locator('#mesh-field').selectOption('generation');
  await page.waitForFunction(() => document.querySelector('#mesh-canvas').dataset.field === 'generation');
  const canvas = page.locator('#mesh-canvas');
  assert.equal(Number(await canvas.getAttribute('data-min')), Math.min(...generation));
  assert.equal(Number(await canvas.getAttribute('data-max')), Math.max(...generation));
  assert.ok(Math.max(...generation) > Math.min(...generation), 'graded: the generations differ');
  assert.match(await page.locator('#legend-label').innerText(), /^refinement generation, in bisections from the coarse-mesh triangle/);
  // Why the loop stopped, and that the target is a reduction of J^½, not an accuracy.
  assert.match(await page.locator('#adaptivity-note').innerText(), /It stopped: the \d+ refinement steps were made .*not the relative accuracy of the force/);
  // The adaptive section and the mesh under it, in page coordinates.
  const shot = await page.evaluate(() => {
    const top = document.querySelector('#adaptivity-section').getBoundingClientRect();
    const bottom = document.querySelector('#mesh-caption').getBoundingClientRect();
    return { x: top.x - 10, y: top.y + window.scrollY - 10, width: top.width + 20, height: bottom.bottom - top.y + 20 };
  });
  await page.screenshot({ path: join(screenshots, 'adaptive.png'), fullPage: true, clip: shot });
  await page.locator('#mesh-field').selectOption('von_mises');
});

test('friction with load steps: shear and stick / slip along the boundary, the load path and the step table', async () => {
  await checkFrictionAndLoadSteps({ page, serverUrl: server.url, screenshots, submitAndWaitForRow, setEditorText, expectPixels, fmt });
});

test('a solve stopped by max_iterations gets its own badge, not the success colour', async () => {
  const row = await submitHertzVariant('stopped_hertz', 1, (c) => {
    c.solver = { method: 'pgs', tolerance: 1e-12, max_iterations: 2 };
  });
  const badge = row.locator('.state-not-converged');
  await badge.waitFor();
  assert.equal(await badge.innerText(), 'not converged');
  assert.match(await badge.getAttribute('title'), /max_iterations/);
  const colour = (locator) => locator.evaluate((e) => `${getComputedStyle(e).color} on ${getComputedStyle(e).backgroundColor}`);
  const succeeded = page.locator('#job-table .state-succeeded').first();
  assert.notEqual(await colour(badge), await colour(succeeded));
  await page.locator('#job-summary', { hasText: /^Did not converge/ }).waitFor();
});

test('a converged answer without contact is flagged for review, with its warning', async () => {
  const row = await submitHertzVariant('upside_down', 1, (c) => {
    c.boundary.contact.obstacle.normal = [0, -1];
  });
  await row.locator('.state-succeeded').waitFor();
  await page.locator('#job-summary', { hasText: /^Converged in \d+ iterations, but the answer needs review/ }).waitFor();
  const warning = page.locator('#job-warnings li.review[data-code="no_contact"]');
  await warning.waitFor();
  assert.match(await warning.innerText(), /^Check this answer: no contact/);
  assert.equal(await page.locator('#hertz-note').innerText(), '', 'no Hertz curve without a force');
  const top = await page.locator('#job-summary').boundingBox();
  const list = await page.locator('#job-warnings').boundingBox();
  await page.screenshot({ path: join(screenshots, 'review.png'), fullPage: true,
    clip: { x: list.x - 12, y: top.y - 48, width: list.width + 24, height: list.y + list.height - top.y + 60 } });
});

test('declared units label the numbers and Hertz is offered by geometry, not by name', async () => {
  const row = await submitHertzVariant('a roller in mm', 1, (c) => {
    c.units = { length: 'mm', stress: 'MPa' };
  });
  await row.locator('.state-succeeded').waitFor();
  await page.locator('#hertz-note', { hasText: /Dashed red: plane-strain Hertz/ }).waitFor();
  const jobId = Number(await row.getAttribute('data-job-id'));
  const result = await (await fetch(`${server.url}/v1/jobs/${jobId}/result`)).json();
  const numbers = await page.locator('#key-numbers').innerText();
  assert.ok(numbers.includes(`${fmt(result.contact.force[1])} N/mm`), numbers);
  assert.ok(numbers.includes(`${fmt(result.contact.zone.width)} mm (Hertz 2a`), numbers);
  assert.ok(numbers.includes(`${fmt(result.contact.zone.peak_pressure)} MPa (Hertz p0`), numbers);
  assert.match(await page.locator('#legend-label').innerText(), /in MPa; here μ = |in mm/);
});

test('a sweep shows the force of every point against the swept value', async () => {
  const row = await submitHertzVariant('swept_hertz', 1, (c) => {
    c.boundary.top.displacement = [0, -0.004];
    c.sweep = { pointer: '/boundary/top/displacement/1', values: [-0.004, -0.008, -0.012] };
  });
  await row.locator('.state-succeeded').waitFor();
  await page.waitForFunction(() => document.querySelector('#sweep-plot')?.dataset.points === '3');
  assert.equal(await page.locator('#sweep-figure').isVisible(), true);
  assert.equal(await page.locator('#sweep-plot').getAttribute('data-unconverged'), '0');
  await expectPixels('#sweep-plot', '#1f5fbf', 50, 'sweep curve');
  assert.match(await page.locator('#sweep-note').innerText(), /^3 points of \/boundary\/top\/displacement\/1.*all converged/);
  const csv = await page.locator('#download-sweep-csv').evaluate(async (a) => (await fetch(a.href)).text());
  const lines = csv.trim().split('\n');
  assert.equal(lines[0], '/boundary/top/displacement/1,force_x,force_y,peak_pressure,contact_width,contact_length,converged,stop_reason,iterations');
  const result = await (await fetch(`${server.url}/v1/jobs/${await row.getAttribute('data-job-id')}/result`)).json();
  assert.deepEqual(lines.slice(1).map((l) => Number(l.split(',')[2])), result.sweep.points.map((p) => p.force[1]));
});

test('a second job is drawn over the first: pressure and gap, and the sweep curve', async () => {
  // A stiffer body (μ = λ = 2) under the same sweep: about twice the force at each point.
  const row = await submitHertzVariant('swept_stiffer', 1, (c) => {
    c.material = { mu: 2, lambda: 2 };
    c.boundary.top.displacement = [0, -0.004];
    c.sweep = { pointer: '/boundary/top/displacement/1', values: [-0.004, -0.008] };
  });
  await row.locator('.state-succeeded').waitFor();
  await page.waitForFunction(() => document.querySelector('#sweep-plot')?.dataset.points === '2');

  const other = await (await fetch(`${server.url}/v1/jobs?page_size=50`)).json();
  const sweptId = other.jobs.find((j) => j.name === 'swept_hertz').id;
  const otherResult = await (await fetch(`${server.url}/v1/jobs/${sweptId}/result`)).json();
  await page.locator('#compare-job').selectOption(String(sweptId));
  await page.waitForFunction(() => document.querySelector('#sweep-plot')?.dataset.comparePoints === '3');
  const pressure = page.locator('#pressure-plot');
  // The Hertz curve comes with the geometry (a half disk on a plane), whatever the job's name.
  assert.equal(await pressure.getAttribute('data-series'), `pressure|gap|Hertz pressure (plane strain)|job ${sweptId} pressure|job ${sweptId} gap`);
  assert.equal(await pressure.getAttribute('data-compare-points'), String(otherResult.contact.x.length));
  await expectPixels('#pressure-plot', '#e67e22', 50, 'the compared pressure');
  await expectPixels('#sweep-plot', '#e67e22', 50, 'the compared sweep curve');
  assert.match(await page.locator('#sweep-note').innerText(), new RegExp(`Dashed: job ${sweptId} \\(3 points`));
  await page.screenshot({ path: join(screenshots, 'compare.png'), fullPage: true });

  // The shown job is not offered; "none" removes the overlay.
  const offered = await page.locator('#compare-job option').evaluateAll((os) => os.map((o) => o.value));
  assert.ok(!offered.includes(await row.getAttribute('data-job-id')) && offered.includes(''), `${offered}`);
  await page.locator('#compare-job').selectOption('');
  await page.waitForFunction(() => document.querySelector('#pressure-plot')?.dataset.comparePoints === '0');
  assert.equal(await pressure.getAttribute('data-series'), 'pressure|gap|Hertz pressure (plane strain)');
});

test("a job's case reopens in the editor exactly as it was submitted", async () => {
  const list = await (await fetch(`${server.url}/v1/jobs?page_size=50`)).json();
  const stopped = list.jobs.find((j) => j.name === 'stopped_hertz');
  const submitted = await (await fetch(`${server.url}/v1/jobs/${stopped.id}/case`)).text();
  await setEditorText('{}');
  await page.locator(`#job-table [data-action="view"][data-job-id="${stopped.id}"]`).click();
  await page.locator('#job-heading', { hasText: 'stopped_hertz' }).waitFor();
  await page.getByRole('button', { name: 'Open case in editor' }).click();
  await page.locator('#submit-status', { hasText: `Job ${stopped.id}'s case is in the editor.` }).waitFor();
  assert.equal(await page.locator('#case-text').inputValue(), submitted);
  assert.equal(JSON.parse(submitted).solver.max_iterations, 2);
  assert.equal(await page.evaluate(() => document.activeElement.id), 'case-text');
});

test('an invalid case shows each error next to its field', async () => {
  const bad = hertzText.replace('"mu": 1', '"mu": -1').replace('"method": "mmg"', '"method": "bogus"');
  assert.notEqual(bad, hertzText);
  await setEditorText(bad);
  const jobsBefore = await page.locator('#job-table tbody tr').count();
  await page.getByRole('button', { name: 'Submit case' }).click();
  await page.locator('#case-errors').waitFor({ state: 'visible' });

  const items = await page.locator('#case-error-list li').allInnerTexts();
  const mu = items.find((t) => t.startsWith('/material/mu'));
  const method = items.find((t) => t.startsWith('/solver/method'));
  assert.ok(mu, `an entry for /material/mu in ${JSON.stringify(items)}`);
  assert.ok(method, `an entry for /solver/method in ${JSON.stringify(items)}`);
  const lines = bad.split('\n');
  const muLine = lines.findIndex((l) => l.includes('"mu": -1')) + 1;
  assert.match(mu, new RegExp(`\\(line ${muLine}\\)`));

  // In the editor: the key is marked, the message is written on its line, the gutter flags it.
  const marked = await page.locator('#case-editor .backdrop mark').allInnerTexts();
  assert.ok(marked.includes('"mu"') && marked.includes('"method"'), `marked keys ${marked}`);
  const muNote = await page.locator('#case-editor .backdrop > div').nth(muLine - 1).locator('.note').innerText();
  assert.match(muNote, />|must|positive|0/);
  assert.equal(await page.locator('#case-editor .gutter div').nth(muLine - 1).getAttribute('class'), 'error-line');
  assert.equal(await page.locator('#case-text').getAttribute('aria-invalid'), 'true');

  // The pointer button selects the key in the textarea.
  await page.locator('#case-error-list button', { hasText: '/material/mu' }).click();
  const selected = await page.evaluate(() => {
    const t = document.querySelector('#case-text');
    return t.value.slice(t.selectionStart, t.selectionEnd);
  });
  assert.equal(selected, '"mu"');
  assert.equal(await page.locator('#job-table tbody tr').count(), jobsBefore, 'nothing was queued');
  await page.locator('.side').screenshot({ path: join(screenshots, 'case-errors.png') });

  // Unparsable JSON (400): the parser's line is flagged.
  await setEditorText('{\n  "name": "broken",\n  "mesh": }\n');
  await page.getByRole('button', { name: 'Submit case' }).click();
  await page.locator('#case-error-list li', { hasText: /parse error at line 3/ }).waitFor();
  assert.equal(await page.locator('#case-editor .gutter div').nth(2).getAttribute('class'), 'error-line');
  assert.match(await page.locator('#submit-status').innerText(), /^Not submitted: .*line 3/);

  // Loading an example clears the errors.
  await page.getByRole('button', { name: 'Load example' }).click();
  assert.equal(await page.locator('#case-errors').isVisible(), false);
});

test('a running job can be cancelled and then deleted from the list', async () => {
  // Projected Gauss–Seidel on a fine mesh with an unreachable tolerance runs for minutes (its own
  // time limit keeps it within the service's default --max-job-seconds). Two sweep points: the
  // list and the view say which solve runs (the first, until the cancel).
  const row = await submitHertzVariant('slow_hertz', 5, (c) => {
    c.solver = { method: 'pgs', tolerance: 1e-15, max_iterations: 100000, time_limit_s: 1500 };
    c.sweep = { pointer: '/boundary/top/displacement/1', values: [-0.01, -0.02] };
  });
  // While it runs, the view plots the residuals the polls have seen.
  await row.locator('.state-running').waitFor();
  await page.locator('#job-summary', { hasText: /^Running: step 1 of 2, iteration \d+, KKT residual/ }).waitFor();
  await row.locator('td.progress', { hasText: /^step 1 of 2, it \d+, KKT/ }).waitFor();
  await page.waitForFunction(() => Number(document.querySelector('#live-plot')?.dataset.points) >= 2);
  assert.equal(await page.locator('#live-figure').isVisible(), true);
  await page.screenshot({ path: join(screenshots, 'running.png') });
  const cancel = row.getByRole('button', { name: /^Cancel job/ });
  await cancel.click();
  await row.locator('.state-cancelled').waitFor();
  await page.locator('#job-summary', { hasText: 'Cancelled' }).waitFor();
  assert.equal(await page.locator('#live-figure').isVisible(), false);

  const id = await row.getAttribute('data-job-id');
  await row.getByRole('button', { name: /^Delete job/ }).click();
  await page.locator(`#job-table tbody tr[data-job-id="${id}"]`).waitFor({ state: 'detached' });
  assert.equal((await fetch(`${server.url}/v1/jobs/${id}`)).status, 404);
});

test('the controls are reachable with the keyboard and show focus', async () => {
  await page.locator('body').click({ position: { x: 5, y: 5 } });
  const reached = [];
  for (let k = 0; k < 12; k++) {
    await page.keyboard.press('Tab');
    const info = await page.evaluate(() => {
      const el = document.activeElement;
      const style = getComputedStyle(el);
      return { id: el.id || el.textContent.trim().slice(0, 30), outline: style.outlineStyle, width: style.outlineWidth };
    });
    reached.push(info.id);
    if (info.id === 'submit-case') {
      assert.notEqual(info.outline, 'none', 'focus is visible on the submit button');
      break;
    }
  }
  assert.ok(reached.includes('example-select') && reached.includes('load-example') && reached.includes('submit-case'),
    `tab order ${reached}`);
  // Enter on a focused job name opens that job.
  const view = page.locator('#job-table tbody [data-action="view"]').first();
  await view.focus();
  const name = await view.innerText();
  await page.keyboard.press('Enter');
  await page.locator('#job-heading', { hasText: `· ${name}` }).waitFor();
});

test('the page logged no console errors or warnings', async () => {
  // Chromium reports every HTTP error response as a console error; the 422 and 400 of the
  // invalid cases above are expected, anything else is not.
  const unexpected = consoleProblems.filter(
    (m) => !/Failed to load resource: the server responded with a status of (422|400) .*\/v1\/jobs\)$/.test(m),
  );
  assert.deepEqual(unexpected, []);
});
