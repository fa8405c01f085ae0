// Draws a deformed triangle mesh on a 2D canvas, each triangle filled with the colour of its
// value, fast enough to redraw on every zoom or pan step of a 100k-triangle result: the
// triangles are rasterised into an image by hand; edges and outlines are canvas paths on top.
import { colourAt } from './mesh_view.js';

const BINS = 256;  // more than the eye separates on a continuous colour map

/** Point coordinates moved by magnification × u (the point array u, when there is one). */
export function deformedPoints(mesh, magnification) {
  const n = mesh.points.length / 2;
  const u = mesh.pointData.u;
  const out = new Float64Array(2 * n);
  for (let v = 0; v < n; v++) {
    out[2 * v] = mesh.points[2 * v] + (u ? magnification * u.values[v * u.components] : 0);
    out[2 * v + 1] = mesh.points[2 * v + 1] + (u ? magnification * u.values[v * u.components + 1] : 0);
  }
  return out;
}

/** {xmin, xmax, ymin, ymax} over several x,y coordinate arrays. */
export function bounds(...arrays) {
  let xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
  for (const pts of arrays) {
    for (let k = 0; k < pts.length; k += 2) {
      xmin = Math.min(xmin, pts[k]);
      xmax = Math.max(xmax, pts[k]);
      ymin = Math.min(ymin, pts[k + 1]);
      ymax = Math.max(ymax, pts[k + 1]);
    }
  }
  return { xmin, xmax, ymin, ymax };
}

/**
 * The map from mesh coordinates to canvas pixels that fits `box` into width × height with
 * `pad` pixels around it, y up: X = bx + a·x, Y = by − a·y.
 */
export function fitTransform(box, width, height, pad = 12) {
  const a = Math.min(
    (width - 2 * pad) / Math.max(box.xmax - box.xmin, 1e-300),
    (height - 2 * pad) / Math.max(box.ymax - box.ymin, 1e-300),
  );
  return {
    a,
    bx: (width - a * (box.xmax - box.xmin)) / 2 - a * box.xmin,
    by: height - (height - a * (box.ymax - box.ymin)) / 2 + a * box.ymin,
  };
}

/** {min, max} of the finite values (0, 0 when there is none). */
export function valueRange(values) {
  let min = Infinity, max = -Infinity;
  for (const v of values) {
    if (Number.isFinite(v)) {
      min = Math.min(min, v);
      max = Math.max(max, v);
    }
  }
  return min <= max ? { min, max } : { min: 0, max: 0 };
}

const edgeCache = new WeakMap();

/**
 * Every edge of the mesh once, as vertex pairs [a0, b0, a1, b1, ...], and those on one
 * triangle only (the outline). Cached per mesh: the viewer asks on every redraw.
 */
export function meshEdges(mesh) {
  let edges = edgeCache.get(mesh);
  if (edges) return edges;
  const tri = mesh.triangles;
  const count = new Map();
  for (let c = 0; c < tri.length; c += 3) {
    for (let k = 0; k < 3; k++) {
      const p = tri[c + k];
      const q = tri[c + ((k + 1) % 3)];
      const key = p < q ? p * 4294967296 + q : q * 4294967296 + p;  // exact below 2^53
      count.set(key, (count.get(key) ?? 0) + 1);
    }
  }
  const all = new Uint32Array(2 * count.size);
  const outline = [];
  let i = 0;
  for (const [key, n] of count) {
    const p = Math.floor(key / 4294967296);
    const q = key - p * 4294967296;
    all[i++] = p;
    all[i++] = q;
    if (n === 1) outline.push(p, q);
  }
  edges = { all, outline: Uint32Array.from(outline) };
  edgeCache.set(mesh, edges);
  return edges;
}

function strokeEdges(ctx, pairs, pts, t) {
  ctx.beginPath();
  for (let e = 0; e < pairs.length; e += 2) {
    const p = pairs[e];
    const q = pairs[e + 1];
    ctx.moveTo(t.bx + t.a * pts[2 * p], t.by - t.a * pts[2 * p + 1]);
    ctx.lineTo(t.bx + t.a * pts[2 * q], t.by - t.a * pts[2 * q + 1]);
  }
  ctx.stroke();
}

/** A colour map at BINS levels as 32-bit RGBA pixels (byte order of the canvas), by name. */
const PALETTES = new Map();
function palette(map) {
  if (!PALETTES.has(map)) {
    const bytes = new Uint8ClampedArray(4 * BINS);
    for (let b = 0; b < BINS; b++) bytes.set([...colourAt((b + 0.5) / BINS, map), 255], 4 * b);
    PALETTES.set(map, new Uint32Array(bytes.buffer));
  }
  return PALETTES.get(map);
}

/**
 * Fills the triangles into `pixels` (a Uint32Array over width × height RGBA pixels) with the
 * palette colour of their value: a pixel belongs to the triangle that holds its centre. Done
 * by hand rather than by canvas paths: 108k triangles take tens of milliseconds instead of
 * hundreds, and neighbouring triangles leave no anti-aliased seams between them.
 */
function rasterise(pixels, width, height, mesh, pts, values, scale, colours, t) {
  const tri = mesh.triangles;
  const span = scale.max > scale.min ? scale.max - scale.min : 1;
  const X = (v) => t.bx + t.a * pts[2 * v];
  const Y = (v) => t.by - t.a * pts[2 * v + 1];
  for (let c = 0; c < tri.length / 3; c++) {
    let x0 = X(tri[3 * c]), y0 = Y(tri[3 * c]);
    let x1 = X(tri[3 * c + 1]), y1 = Y(tri[3 * c + 1]);
    const x2 = X(tri[3 * c + 2]), y2 = Y(tri[3 * c + 2]);
    const xmin = Math.max(0, Math.ceil(Math.min(x0, x1, x2) - 0.5));
    const xmax = Math.min(width - 1, Math.floor(Math.max(x0, x1, x2) - 0.5));
    const ymin = Math.max(0, Math.ceil(Math.min(y0, y1, y2) - 0.5));
    const ymax = Math.min(height - 1, Math.floor(Math.max(y0, y1, y2) - 0.5));
    if (xmin > xmax || ymin > ymax) continue;
    let area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if (area === 0) continue;
    if (area < 0) {  // one orientation, so that inside means all three edge functions ≥ 0
      [x0, x1] = [x1, x0];
      [y0, y1] = [y1, y0];
      area = -area;
    }
    const x = (values[c] - scale.min) / span;
    const colour = colours[Number.isFinite(x) ? Math.min(BINS - 1, Math.max(0, Math.floor(x * BINS))) : 0];
    // Edge functions at the centre of pixel (xmin, ymin), and their steps per pixel.
    const px = xmin + 0.5, py = ymin + 0.5;
    let r0 = (x2 - x1) * (py - y1) - (y2 - y1) * (px - x1);
    let r1 = (x0 - x2) * (py - y2) - (y0 - y2) * (px - x2);
    let r2 = (x1 - x0) * (py - y0) - (y1 - y0) * (px - x0);
    const dx0 = -(y2 - y1), dx1 = -(y0 - y2), dx2 = -(y1 - y0);
    const dy0 = x2 - x1, dy1 = x0 - x2, dy2 = x1 - x0;
    for (let yy = ymin; yy <= ymax; yy++) {
      let e0 = r0, e1 = r1, e2 = r2;
      const row = yy * width;
      for (let xx = xmin; xx <= xmax; xx++) {
        if (e0 >= 0 && e1 >= 0 && e2 >= 0) pixels[row + xx] = colour;
        e0 += dx0;
        e1 += dx1;
        e2 += dx2;
      }
      r0 += dy0;
      r1 += dy1;
      r2 += dy2;
    }
  }
}

/**
 * Draws the triangles at `deformed` coordinates through transform `t` (CSS pixels; `ratio`
 * device pixels per CSS pixel), coloured by `values` (one per triangle) over `scale` ({map,
 * min, max}, see colourScale in mesh_view.js); with
 * `edges`, every triangle edge in a thin dark line; with `outline` (the undeformed points),
 * the undeformed boundary dashed.
 */
export function drawMesh(ctx, ratio, mesh, deformed, values, scale, t, { edges = false, outline = null } = {}) {
  const { width, height } = ctx.canvas;
  const image = ctx.createImageData(width, height);
  const device = { a: t.a * ratio, bx: t.bx * ratio, by: t.by * ratio };
  rasterise(new Uint32Array(image.data.buffer), width, height, mesh, deformed, values, scale, palette(scale.map), device);
  ctx.putImageData(image, 0, 0);
  const { all, outline: boundary } = meshEdges(mesh);
  ctx.lineJoin = 'round';
  if (edges) {
    ctx.strokeStyle = 'rgba(15, 15, 15, 0.55)';
    ctx.lineWidth = 0.5;
    strokeEdges(ctx, all, deformed, t);
  }
  if (outline) {
    ctx.strokeStyle = 'rgba(90, 90, 90, 0.9)';
    ctx.lineWidth = 1;
    ctx.setLineDash([4, 3]);
    strokeEdges(ctx, boundary, outline, t);
    ctx.setLineDash([]);
  }
}

/**
 * The triangle that contains the point (x, y) of the deformed mesh, with its barycentric
 * coordinates: {cell, weights: [l0, l1, l2]}, or null outside the mesh. A linear scan with
 * a bounding-box test first: a few milliseconds for 100k triangles, once per probe.
 */
export function locatePoint(mesh, deformed, x, y) {
  const tri = mesh.triangles;
  for (let c = 0; c < tri.length / 3; c++) {
    const p = tri[3 * c], q = tri[3 * c + 1], s = tri[3 * c + 2];
    const x0 = deformed[2 * p], y0 = deformed[2 * p + 1];
    const x1 = deformed[2 * q], y1 = deformed[2 * q + 1];
    const x2 = deformed[2 * s], y2 = deformed[2 * s + 1];
    if (x < Math.min(x0, x1, x2) || x > Math.max(x0, x1, x2) || y < Math.min(y0, y1, y2) || y > Math.max(y0, y1, y2)) continue;
    const det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if (det === 0) continue;
    const l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / det;
    const l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / det;
    const l0 = 1 - l1 - l2;
    const eps = -1e-12;
    if (l0 >= eps && l1 >= eps && l2 >= eps) return { cell: c, weights: [l0, l1, l2] };
  }
  return null;
}
