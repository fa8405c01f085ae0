// The mesh view's colour maps and its displacement magnification rule. The drawing
// is in mesh_drawing.js, the interaction (zoom, pan, probe) in mesh_viewer.js.

// Two colour maps at nine evenly spaced points. Viridis (sequential: perceptually uniform and
// readable in grey scale) for magnitudes; Moreland's cool-warm (diverging: blue, grey-white at
// the middle, red) for signed fields on a range symmetric about 0, so that the sign of a stress
// component shows at a glance.
const MAPS = {
  viridis: [
    [68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141],
    [39, 173, 129], [92, 200, 99], [170, 220, 50], [253, 231, 37],
  ],
  coolwarm: [
    [59, 76, 192], [98, 130, 234], [141, 176, 254], [184, 208, 249], [221, 221, 221],
    [245, 196, 173], [244, 154, 123], [222, 96, 77], [180, 4, 38],
  ],
};

/** The colour (as [r, g, b]) of t in [0, 1] on colour map `map` (viridis or coolwarm). */
export function colourAt(t, map = 'viridis') {
  const stops = MAPS[map];
  const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * (stops.length - 1);
  const i = Math.min(stops.length - 2, Math.floor(x));
  const f = x - i;
  return stops[i].map((c, k) => Math.round(c + f * (stops[i + 1][k] - c)));
}

/** CSS gradient of a colour map, left = minimum, for the legend. */
export function colourGradientCss(map = 'viridis') {
  const stops = MAPS[map];
  const css = stops.map((c, i) => `rgb(${c.join(',')}) ${(100 * i) / (stops.length - 1)}%`);
  return `linear-gradient(to right, ${css.join(', ')})`;
}

/**
 * How a field is coloured: a signed field whose values have both signs on the diverging map
 * over [−m, m], m the largest |value|; anything else on viridis over its range.
 */
export function colourScale(range, signed) {
  if (signed && range.min < 0 && range.max > 0) {
    const m = Math.max(-range.min, range.max);
    return { map: 'coolwarm', min: -m, max: m };
  }
  return { map: 'viridis', min: range.min, max: range.max };
}

/** Largest displacement length of the mesh, 2D or 3D (0 without a u field). */
export function maxDisplacement(mesh) {
  const u = mesh.pointData.u;
  if (!u) return 0;
  const solid = mesh.dimension === 3;
  let m = 0;
  for (let v = 0; v < u.values.length / u.components; v++) {
    const [x, y, z] = [0, 1, 2].map((d) => u.values[v * u.components + d]);
    m = Math.max(m, solid ? Math.hypot(x, y, z) : Math.hypot(x, y));
  }
  return m;
}

/** The diagonal of the box around the mesh's points (x, y pairs in 2D, triples in 3D). */
function diagonal(mesh) {
  const [points, dims] = mesh.dimension === 3 ? [mesh.points3, 3] : [mesh.points, 2];
  const lo = Array(dims).fill(Infinity);
  const hi = Array(dims).fill(-Infinity);
  for (let v = 0; v < points.length; v += dims) {
    for (let d = 0; d < dims; d++) {
      lo[d] = Math.min(lo[d], points[v + d]);
      hi[d] = Math.max(hi[d], points[v + d]);
    }
  }
  return Math.hypot(...hi.map((h, d) => h - lo[d]));
}

/**
 * A round magnification (1, 2, 5 × 10^k, never below 1) that makes the largest displacement
 * about 8 % of the mesh's diagonal, so that small elastic deformations become visible. The
 * same rule for 2D and 3D meshes.
 */
export function autoMagnification(mesh) {
  const umax = maxDisplacement(mesh);
  if (!(umax > 0)) return 1;
  const target = (0.08 * diagonal(mesh)) / umax;
  if (target <= 1) return 1;
  const decade = 10 ** Math.floor(Math.log10(target));
  const mantissa = [5, 2, 1].find((m) => m * decade <= target);
  return mantissa * decade;
}
