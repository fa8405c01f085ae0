// Pixels of the page's canvases, read in the browser: how the end-to-end tests see that a
// chart or the mesh was drawn in a given colour (tests/web/page.test.mjs and the checks it
// imports).
import assert from 'node:assert/strict';

/** Counts pixels of `canvasSelector` (first match, or the largest canvas inside it) within
 *  `tolerance` of the colour `hex`, or (hex = null) pixels that are not transparent/white, or
 *  (hex = 'saturated') pixels of a colour rather than a grey (channels more than 60 apart). */
export async function countPixels(page, selector, hex, tolerance = 40) {
  return page.evaluate(
    ({ selector, hex, tolerance }) => {
      const root = document.querySelector(selector);
      const canvases = root.tagName === 'CANVAS' ? [root] : [...root.querySelectorAll('canvas')];
      const canvas = canvases.sort((a, b) => b.width * b.height - a.width * a.height)[0];
      // Read a copy made for reading, so the page's own canvas is not switched to software.
      const copy = document.createElement('canvas');
      copy.width = canvas.width;
      copy.height = canvas.height;
      const ctx = copy.getContext('2d', { willReadFrequently: true });
      ctx.drawImage(canvas, 0, 0);
      const { data } = ctx.getImageData(0, 0, copy.width, copy.height);
      const want = hex?.startsWith('#') && [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16));
      let n = 0;
      for (let i = 0; i < data.length; i += 4) {
        if (data[i + 3] < 128) continue;
        if (hex === 'saturated') {
          if (Math.max(data[i], data[i + 1], data[i + 2]) - Math.min(data[i], data[i + 1], data[i + 2]) > 60) n++;
        } else if (want) {
          if (Math.abs(data[i] - want[0]) + Math.abs(data[i + 1] - want[1]) + Math.abs(data[i + 2] - want[2]) <= tolerance) n++;
        } else if (data[i] + data[i + 1] + data[i + 2] < 3 * 235) {
          n++;
        }
      }
      return n;
    },
    { selector, hex, tolerance },
  );
}

/** Waits (up to 10 s) until countPixels(page, selector, hex) exceeds `min`; returns the count. */
export async function expectPixelsOn(page, selector, hex, min, what) {
  let n = 0;
  for (const deadline = Date.now() + 10000; Date.now() < deadline; await new Promise((r) => setTimeout(r, 100))) {
    n = await countPixels(page, selector, hex);
    if (n > min) return n;
  }
  assert.fail(`${what}: ${n} pixels of ${hex ?? 'non-background'} on ${selector}, expected more than ${min}`);
}
