// Painting the 3D view on a canvas 2D context: the visible surface triangles far to near, each
// flat-shaded in its field colour, a large one cut into smaller ones coloured by its vertex
// values interpolated (so a vertex field such as the contact pressure varies within a face, as
// the values it interpolates do), and a polyline over everything.
import { paintOrder, shade } from './surface_camera.js';
import { colourAt } from './mesh_view.js';
import { normalOf } from './tet_surface.js';

const NEUTRAL = [200, 200, 200];  // NaN values: off the contact for the pressure
const PIECE_PIXELS = 12;          // a triangle is cut so that its pieces' edges are about this long
const MAX_CUTS = 6;

/** Fills the screen triangle (x, y pairs) in `colour`, its edges too: that hides the seams between neighbours. */
function fillTriangle(ctx, colour, ax, ay, bx, by, cx, cy) {
  ctx.fillStyle = colour;
  ctx.strokeStyle = colour;
  ctx.beginPath();
  ctx.moveTo(ax, ay);
  ctx.lineTo(bx, by);
  ctx.lineTo(cx, cy);
  ctx.closePath();
  ctx.fill();
  ctx.stroke();
}

/**
 * Triangle a b c cut into n² pieces (n from its longest screen edge), each filled with the
 * colour `colourOf(value)` of its centroid's value, the vertex values va, vb, vc interpolated
 * linearly. Pieces of one triangle lie in its plane, so painting them in a row keeps the
 * painter's order.
 */
function paintPieces(ctx, corners, vertexValues, colourOf) {
  const [[ax, ay], [bx, by], [cx, cy]] = corners;
  const n = Math.min(MAX_CUTS, Math.max(1, Math.ceil(Math.max(Math.hypot(bx - ax, by - ay), Math.hypot(cx - bx, cy - by), Math.hypot(ax - cx, ay - cy)) / PIECE_PIXELS)));
  const [va, vb, vc] = vertexValues;
  // The point i/n of the way to b and j/n of the way to c, and its value.
  const at = (i, j) => [ax + (i / n) * (bx - ax) + (j / n) * (cx - ax), ay + (i / n) * (by - ay) + (j / n) * (cy - ay), va + (i / n) * (vb - va) + (j / n) * (vc - va)];
  for (let i = 0; i < n; i++) {
    for (let j = 0; i + j < n; j++) {
      const pieces = [[at(i, j), at(i + 1, j), at(i, j + 1)]];
      if (i + j < n - 1) pieces.push([at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]);
      for (const [p, q, r] of pieces) fillTriangle(ctx, colourOf((p[2] + q[2] + r[2]) / 3), p[0], p[1], q[0], q[1], r[0], r[1]);
    }
  }
}

/**
 * Paints the triangles of `triangles` that face the viewer (screen: X, Y, depth triples of the
 * points; deformed: their x, y, z, for the shading) in `field` ({values per triangle,
 * vertexValues or none, scale {map, min, max}}). Returns the painted triangles, far to near.
 */
export function paintSurface(ctx, { triangles: t, screen, deformed, camera, field }) {
  const { values, vertexValues, scale } = field;
  const span = scale.max - scale.min;
  const base = (v) => colourAt(span > 0 ? (v - scale.min) / span : 0.5, scale.map);
  const order = paintOrder(t, screen);
  ctx.lineWidth = 0.6;
  ctx.lineJoin = 'round';
  for (const f of order) {
    const light = shade(normalOf(deformed, t[3 * f], t[3 * f + 1], t[3 * f + 2]), camera);
    const colourOf = (v) => `rgb(${(Number.isFinite(v) ? base(v) : NEUTRAL).map((c) => Math.round(c * light)).join(',')})`;
    const vertices = [t[3 * f], t[3 * f + 1], t[3 * f + 2]];
    const corners = vertices.map((a) => [screen[3 * a], screen[3 * a + 1]]);
    if (vertexValues && Number.isFinite(values[f])) paintPieces(ctx, corners, vertices.map((a) => vertexValues[a]), colourOf);
    else fillTriangle(ctx, colourOf(values[f]), ...corners.flat());
  }
  return order;
}

/** A polyline of screen points (X, Y, depth triples; a NaN breaks it), white under black so it shows on any colour. */
export function paintPolyline(ctx, screen) {
  for (const [colour, lineWidth] of [['#ffffff', 4], ['#111111', 2]]) {
    ctx.strokeStyle = colour;
    ctx.lineWidth = lineWidth;
    ctx.beginPath();
    let pen = false;
    for (let i = 0; i < screen.length; i += 3) {
      if (!Number.isFinite(screen[i])) {
        pen = false;
        continue;
      }
      if (pen) ctx.lineTo(screen[i], screen[i + 1]);
      else ctx.moveTo(screen[i], screen[i + 1]);
      pen = true;
    }
    ctx.stroke();
  }
}
