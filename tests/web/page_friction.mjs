// The end-to-end check of friction and load steps, run by tests/web/page.test.mjs on its page
// and service: the shipped cattaneo_mindlin case (Coulomb friction) submitted from the editor
// with load steps, and what the job view draws and writes for it, against the result.
import assert from 'node:assert/strict';
import { join } from 'node:path';

// The Cattaneo–Mindlin loading of docs/case-format.md ("Load steps"): press, then shift in
// three steps. Used when the shipped example has no load steps of its own.
const PRESS_THEN_SHIFT = [
  { '/boundary/top/displacement/0': 0.001 },
  { '/boundary/top/displacement/0': 0.002 },
  { '/boundary/top/displacement/0': 0.004 },
];

/** The shipped example from the editor, coarser (a second at 2 refinements), with load steps. */
function frictionCase(text) {
  const variant = JSON.parse(text);
  variant.mesh.refinements = Math.min(2, variant.mesh.refinements ?? 2);
  if (!variant.load_steps) {
    variant.boundary.top.displacement = [0, variant.boundary.top.displacement[1]];
    variant.load_steps = PRESS_THEN_SHIFT;
  }
  return JSON.stringify(variant, null, 2);
}

/** "state:edges" runs of the edge states ordered by x, as the plot reports them. */
function stateSequence(contact) {
  const order = contact.x.map((_, i) => i).sort((i, j) => contact.x[i] - contact.x[j]);
  const runs = [];
  for (const i of order) {
    const last = runs.at(-1);
    if (last?.state === contact.state[i]) last.edges++;
    else runs.push({ state: contact.state[i], edges: 1 });
  }
  return runs.map((r) => `${r.state}:${r.edges}`).join('|');
}

/** Table cells of #load-step-table, row by row. */
const tableCells = (page) => page.locator('#load-step-table tbody tr').evaluateAll((rs) => rs.map((r) => [...r.cells].map((c) => c.textContent)));

export async function checkFrictionAndLoadSteps({ page, serverUrl, screenshots, submitAndWaitForRow, setEditorText, expectPixels, fmt }) {
  await page.locator('#example-select').selectOption('cattaneo_mindlin');
  await page.getByRole('button', { name: 'Load example' }).click();
  await setEditorText(frictionCase(await page.locator('#case-text').inputValue()));
  const row = await submitAndWaitForRow('cattaneo_mindlin');
  await row.locator('.state-succeeded').waitFor();
  const jobId = Number(await row.getAttribute('data-job-id'));
  const result = await (await fetch(`${serverUrl}/v1/jobs/${jobId}/result`)).json();
  const { contact, friction } = result;
  const steps = result.load_steps.steps;
  assert.ok(friction && contact.shear.length === contact.x.length && steps.length >= 2, 'a frictional, load-stepped result');
  await page.waitForFunction(({ edges, n }) => document.querySelector('#friction-plot')?.dataset.points === String(edges) &&
    document.querySelector('#load-force-plot')?.dataset.points === String(n) &&
    document.querySelectorAll('#load-step-table tbody tr').length === n, { edges: contact.x.length, n: steps.length });

  // Shear with the pressure over the stick / slip / open band, edge states in order along x.
  const plot = page.locator('#friction-plot');
  assert.equal(await plot.getAttribute('data-series'), 'pressure p|shear σ_nt|+𝔣p (slip bound)|−𝔣p (slip bound)');
  assert.equal(await plot.getAttribute('data-states'), stateSequence(contact));
  await expectPixels('#friction-plot', '#6c3483', 50, 'shear line');
  await expectPixels('#friction-plot', '#16a085', 30, 'stick band');
  if (contact.state.includes('slip')) await expectPixels('#friction-plot', '#e74c3c', 10, 'slip band');
  const numbers = await page.locator('#key-numbers').innerText();
  assert.match(numbers, new RegExp(`Friction\\s+Coulomb 𝔣 = ${friction.groups.contact.coefficient}; ${friction.updates} updates of the slip bounds`), numbers);
  const zone = contact.stick_zone;
  assert.ok(numbers.includes(`Stick zone\n${fmt(zone.length)} over ${zone.edges} edges, s = ${fmt(zone.s_start)} … ${fmt(zone.s_end)}`), numbers);
  assert.match(numbers, new RegExp(`Load steps\\s+${steps.length} \\(all converged\\)`));

  // The load path: one point per step and Coulomb's limit, F_t = F_x and F_n = F_y on this plane.
  assert.deepEqual(contact.plane_normal, [0, 1]);
  assert.equal(await page.locator('#load-force-plot').getAttribute('data-series'),
    'F_t of each step|+𝔣 F_n (Coulomb limit)|−𝔣 F_n (Coulomb limit)');
  await expectPixels('#load-force-plot', '#1f5fbf', 30, 'load path');
  await expectPixels('#load-force-plot', '#c0392b', 30, 'Coulomb limit');

  // The table: the result's numbers step by step, the last step chosen first.
  assert.deepEqual(await page.locator('#load-step-table thead th').allInnerTexts(),
    ['step', 'changes', 'iterations', 'converged', 'F_t', 'F_n', '|F_t| / F_n', 'stick zone', 'stick / slip / open edges']);
  const cells = await tableCells(page);
  steps.forEach((s, k) => {
    const f = s.contact.force;
    assert.deepEqual([cells[k][0], cells[k][2], cells[k][3], cells[k][4], cells[k][5], cells[k][7]],
      [String(s.step), String(s.iterations), s.converged ? 'yes' : 'no', fmt(f[0]), fmt(f[1]), fmt(s.contact.stick_zone.length)], `step ${k}`);
  });
  assert.match(cells[1][1], /^\/boundary\/top\/displacement\/0 = /);
  const current = () => page.locator('#load-step-table tbody tr[aria-current="true"] td').first().innerText();
  assert.equal(await current(), String(steps.at(-1).step));
  assert.equal(await page.locator('#load-step-plot').getAttribute('data-step'), String(steps.at(-1).step));

  // Choosing step 0 draws its tractions (its own states) and marks its row.
  await page.locator('#load-step-select').selectOption('0');
  await page.waitForFunction(() => document.querySelector('#load-step-plot')?.dataset.step === '0');
  assert.equal(await page.locator('#load-step-plot').getAttribute('data-states'), stateSequence(steps[0].contact));
  assert.equal(await current(), '0');
  await expectPixels('#load-step-plot', '#6c3483', 50, "step 0's shear line");

  const shot = await page.evaluate(() => {
    const area = document.querySelector('#job-result').getBoundingClientRect();
    const top = document.querySelector('#friction-figure').getBoundingClientRect();
    const bottom = document.querySelector('#load-step-table').getBoundingClientRect();
    return { x: area.x - 10, y: top.y + window.scrollY - 10, width: area.width + 20, height: bottom.bottom - top.y + 20 };
  });
  await page.screenshot({ path: join(screenshots, 'friction.png'), fullPage: true, clip: shot });
}
