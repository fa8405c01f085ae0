// The start-up the browser tests share (tests/web/page.test.mjs, page3d.test.mjs): a real
// fosls-serve on a free loopback port with a temporary database and one worker, and Debian's
// Chromium driven by playwright-core in a fresh profile, with the page's console problems
// collected. Never downloads a browser.
//
// Environment: FOSLS_SERVE (required), FOSLS_WEB_ROOT (default web/), FOSLS_SCREENSHOTS
// (default a new temporary folder), CHROMIUM (default /usr/bin/chromium).
// FOSLS_REFRESH_SCREENSHOTS=1 writes the screenshots to docs/screenshots instead, to refresh
// the docs; an ordinary run leaves the working tree clean.
// Needs web/build.sh to have run (npm packages, web/dist).
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const repo = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
export const webRoot = resolve(process.env.FOSLS_WEB_ROOT ?? join(repo, 'web'));
const serveBinary = process.env.FOSLS_SERVE;
const chromiumPath = process.env.CHROMIUM ?? '/usr/bin/chromium';

/** Where the screenshots go: docs/screenshots when refreshing them, else FOSLS_SCREENSHOTS or a temporary folder. */
function screenshotFolder() {
  return resolve(
    process.env.FOSLS_REFRESH_SCREENSHOTS === '1'
      ? join(repo, 'docs', 'screenshots')
      : (process.env.FOSLS_SCREENSHOTS ?? mkdtempSync(join(tmpdir(), 'fosls-screenshots-'))),
  );
}

function startServer(scratch) {
  return new Promise((resolvePromise, reject) => {
    const child = spawn(
      serveBinary,
      ['--host', '127.0.0.1', '--port', '0', '--db', join(scratch, 'jobs.db'), '--workers', '1',
        '--web-root', webRoot],
      { stdio: ['ignore', 'pipe', 'pipe'] },
    );
    const log = [];
    let stdout = '';
    const timer = setTimeout(() => reject(new Error(`fosls-serve did not start:\n${log.join('')}`)), 15000);
    child.stderr.on('data', (d) => log.push(d.toString()));  // keep draining: a full pipe blocks the server
    child.stdout.on('data', (d) => {
      stdout += d.toString();
      const m = /listening on (http:\/\/\S+)/.exec(stdout);
      if (m) {
        clearTimeout(timer);
        resolvePromise({ process: child, url: m[1], log });
      }
    });
    child.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`fosls-serve exited with ${code}:\n${log.join('')}`));
    });
  });
}

function stopServer(server) {
  if (!server || server.process.exitCode !== null) return Promise.resolve();
  return new Promise((resolvePromise) => {
    const kill = setTimeout(() => server.process.kill('SIGKILL'), 10000);
    server.process.once('exit', () => {
      clearTimeout(kill);
      resolvePromise();
    });
    server.process.kill('SIGTERM');
  });
}

/**
 * Starts the server and the browser and opens the page: {server: {url, log}, page, context,
 * screenshots, consoleProblems (console errors and warnings, uncaught errors, failed
 * requests, as strings), close()}.
 */
export async function openSession() {
  assert.ok(serveBinary && existsSync(serveBinary), `FOSLS_SERVE must name the fosls-serve program (got ${serveBinary})`);
  assert.ok(existsSync(chromiumPath), `${chromiumPath} is missing: apt-get install chromium`);
  assert.ok(existsSync(join(webRoot, 'dist', 'uPlot.esm.js')) && existsSync(join(webRoot, 'dist', 'examples.json')),
    `${webRoot}/dist is incomplete: run web/build.sh`);
  const screenshots = screenshotFolder();
  mkdirSync(screenshots, { recursive: true });
  const scratch = mkdtempSync(join(tmpdir(), 'fosls-web-test-'));
  const session = { screenshots, consoleProblems: [], server: null, context: null };
  session.close = async () => {
    await session.context?.close();  // before the server stops, so no poll meets a closed port
    await stopServer(session.server);
    rmSync(scratch, { recursive: true, force: true });
  };
  session.server = await startServer(scratch);

  // playwright-core lives in web/node_modules (installed by web/build.sh), not beside this file.
  const { chromium } = createRequire(join(webRoot, 'package.json'))('playwright-core');
  session.context = await chromium.launchPersistentContext(join(scratch, 'profile'), {
    executablePath: chromiumPath,
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
    viewport: { width: 1440, height: 900 },
    deviceScaleFactor: 1,
  });
  const page = session.context.pages()[0] ?? (await session.context.newPage());
  session.page = page;
  page.setDefaultTimeout(30000);
  const problems = session.consoleProblems;
  page.on('console', (msg) => {
    if (msg.type() === 'error' || msg.type() === 'warning') problems.push(`${msg.type()}: ${msg.text()} (${msg.location().url})`);
  });
  page.on('pageerror', (error) => problems.push(`uncaught: ${error.message}`));
  page.on('requestfailed', (request) => problems.push(`request failed: ${request.url()} ${request.failure()?.errorText}`));
  await page.goto(session.server.url + '/');
  return session;
}

/** Presses Submit case and waits for the new job's row (the list's first): returns the row. */
export async function submitAndWaitForRow(page, name) {
  const before = await page.locator('#job-table tbody tr').count();
  await page.getByRole('button', { name: 'Submit case' }).click();
  await page.waitForFunction((n) => document.querySelectorAll('#job-table tbody tr').length > n, before);
  const row = page.locator('#job-table tbody tr').first();
  assert.equal(await row.locator('td').nth(1).innerText(), name);
  return row;
}
