// Times the web page on a job of a running fosls-serve (not a test: timings are not asserted,
// docs/web.md "Large results" records them). Opens #job-ID in Debian's Chromium and prints:
// time until the job view is drawn (result, case and VTU fetched, VTU parsed, mesh drawn), the
// mesh redraw time while zooming, with edges, and the time of one probe.
//
//   node tests/web/measure_page.mjs http://127.0.0.1:8080 JOB_ID
import { createRequire } from 'node:module';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const [url, jobId] = process.argv.slice(2);
if (!url || !jobId) {
  console.error('usage: node tests/web/measure_page.mjs SERVER_URL JOB_ID');
  process.exit(2);
}
const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
const { chromium } = createRequire(join(repo, 'web', 'package.json'))('playwright-core');
const profile = mkdtempSync(join(tmpdir(), 'fosls-measure-'));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run'],
  viewport: { width: 1440, height: 900 },
  deviceScaleFactor: 1,
});
const page = context.pages()[0] ?? (await context.newPage());
page.setDefaultTimeout(300000);

const started = Date.now();
await page.goto(`${url}/#job-${jobId}`);
await page.waitForFunction(() => Number(document.querySelector('#mesh-canvas')?.dataset.triangles) > 0 &&
  document.querySelector('#mesh-canvas').dataset.drawMs !== undefined);
const shown = Date.now() - started;
const canvas = page.locator('#mesh-canvas');
const triangles = await canvas.getAttribute('data-triangles');
const firstDraw = Number(await canvas.getAttribute('data-draw-ms'));

// One redraw per wheel step, each awaited: the drawing time of the view as it zooms in.
await canvas.scrollIntoViewIfNeeded();
const box = await canvas.boundingBox();
await page.mouse.move(box.x + box.width / 2, box.y + box.height * 0.9);
const zoomDraws = [];
for (let k = 0; k < 5; k++) {
  const before = await canvas.getAttribute('data-zoom');
  await page.mouse.wheel(0, -200);
  await page.waitForFunction((z) => document.querySelector('#mesh-canvas').dataset.zoom !== z, before);
  zoomDraws.push(Number(await canvas.getAttribute('data-draw-ms')));
}
await page.getByRole('button', { name: 'Reset view' }).click();
await page.waitForFunction(() => document.querySelector('#mesh-canvas').dataset.zoom === '1');
await page.locator('#mesh-edges').check();
await page.waitForFunction(() => document.querySelector('#mesh-canvas').dataset.edges === 'on');
const edgesDraw = Number(await canvas.getAttribute('data-draw-ms'));
const probeMs = await page.evaluate(({ x, y }) => {
  const canvas = document.querySelector('#mesh-canvas');
  const r = canvas.getBoundingClientRect();
  const t0 = performance.now();
  canvas.dispatchEvent(new PointerEvent('pointermove', { clientX: r.left + x, clientY: r.top + y, bubbles: true }));
  return performance.now() - t0;
}, { x: box.width / 2, y: box.height * 0.5 });

const median = (a) => [...a].sort((p, q) => p - q)[Math.floor(a.length / 2)];
console.log(`| triangles | job view shown | first draw | redraw while zooming (median of 5) | draw with edges | one probe |`);
console.log(`|---:|---:|---:|---:|---:|---:|`);
console.log(`| ${triangles} | ${shown} ms | ${firstDraw} ms | ${median(zoomDraws)} ms | ${edgesDraw} ms | ${probeMs.toFixed(1)} ms |`);
await context.close();
rmSync(profile, { recursive: true, force: true });
