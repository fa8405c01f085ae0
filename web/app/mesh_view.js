// Draws the deformed mesh of a solution on a canvas, each triangle filled with the colour of
// a cell value (von Mises stress by default), the undeformed outline in grey behind it.

// Viridis at nine evenly spaced points: perceptually uniform and readable in grey scale.
const VIRIDIS = [
  [68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141],
  [39, 173, 129], [92, 200, 99], [170, 220, 50], [253, 231, 37],
];

/** The colour (as [r, g, b]) of t in [0, 1] on the colour map. */
export function colourAt(t) {
  const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * (VIRIDIS.length - 1);
  const i = Math.min(VIRIDIS.length - 2, Math.floor(x));
  const f = x - i;
  return VIRIDIS[i].map((c, k) => Math.round(c + f * (VIRIDIS[i + 1][k] - c)));
}

/** CSS gradient of the colour map, left = minimum, for the legend. */
export function colourGradientCss() {
  const stops = VIRIDIS.map((c, i) => `rgb(${c.join(',')}) ${(100 * i) / (VIRIDIS.length - 1)}%`);
  return `linear-gradient(to right, ${stops.join(', ')})`;
}

/** Fields the mesh can be coloured by: id → {label, compute(mesh) → per-cell values}. */
export const MESH_FIELDS = {
  von_mises: {
    label: 'von Mises stress',
    compute: (mesh) => mesh.cellData.von_mises?.values ?? null,
  },
  displacement: {
    label: 'displacement |u|',
    compute: (mesh) => {
      const u = mesh.pointData.u;
      if (!u) return null;
      const n = mesh.triangles.length / 3;
      const out = new Float64Array(n);
      for (let c = 0; c < n; c++) {
        let sum = 0;
        for (let k = 0; k < 3; k++) {
          const v = mesh.triangles[3 * c + k];
          sum += Math.hypot(u.values[v * u.components], u.values[v * u.components + 1]);
        }
        out[c] = sum / 3;
      }
      return out;
    },
  },
  functional: {
    label: 'FOSLS functional (error indicator)',
    compute: (mesh) => mesh.cellData.functional?.values ?? null,
  },
};

/** Largest displacement length of the mesh (0 without a u field). */
export function maxDisplacement(mesh) {
  const u = mesh.pointData.u;
  if (!u) return 0;
  let m = 0;
  for (let v = 0; v < mesh.points.length / 2; v++) {
    m = Math.max(m, Math.hypot(u.values[v * u.components], u.values[v * u.components + 1]));
  }
  return m;
}

/**
 * A round magnification (1, 2, 5 × 10^k, never below 1) that makes the largest displacement
 * about 8 % of the mesh's diagonal, so that small elastic deformations become visible.
 */
export function autoMagnification(mesh) {
  const umax = maxDisplacement(mesh);
  if (!(umax > 0)) return 1;
  let xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
  for (let v = 0; v < mesh.points.length; v += 2) {
    xmin = Math.min(xmin, mesh.points[v]);
    xmax = Math.max(xmax, mesh.points[v]);
    ymin = Math.min(ymin, mesh.points[v + 1]);
    ymax = Math.max(ymax, mesh.points[v + 1]);
  }
  const target = (0.08 * Math.hypot(xmax - xmin, ymax - ymin)) / umax;
  if (target <= 1) return 1;
  const decade = 10 ** Math.floor(Math.log10(target));
  const mantissa = [5, 2, 1].find((m) => m * decade <= target);
  return mantissa * decade;
}

/** Edges (vertex pairs) that belong to one triangle only: the outline of the mesh. */
function boundaryEdges(triangles) {
  const count = new Map();
  for (let c = 0; c < triangles.length; c += 3) {
    for (let k = 0; k < 3; k++) {
      const a = triangles[c + k];
      const b = triangles[c + ((k + 1) % 3)];
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      count.set(key, (count.get(key) ?? 0) + 1);
    }
  }
  return [...count].filter(([, n]) => n === 1).map(([key]) => key.split(',').map(Number));
}

/**
 * Draws `mesh` deformed by `magnification` × u, coloured by `values` (one per cell).
 * Returns {min, max} of the values drawn. The canvas keeps its CSS size; its backing store
 * follows the device pixel ratio so lines stay sharp.
 */
export function drawMesh(canvas, mesh, values, magnification) {
  const ratio = window.devicePixelRatio || 1;
  const cssWidth = canvas.clientWidth;
  const cssHeight = canvas.clientHeight;
  canvas.width = Math.round(cssWidth * ratio);
  canvas.height = Math.round(cssHeight * ratio);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, cssWidth, cssHeight);

  const nPoints = mesh.points.length / 2;
  const u = mesh.pointData.u;
  const deformed = new Float64Array(2 * nPoints);
  for (let v = 0; v < nPoints; v++) {
    const ux = u ? u.values[v * u.components] : 0;
    const uy = u ? u.values[v * u.components + 1] : 0;
    deformed[2 * v] = mesh.points[2 * v] + magnification * ux;
    deformed[2 * v + 1] = mesh.points[2 * v + 1] + magnification * uy;
  }
  let xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
  for (const pts of [mesh.points, deformed]) {
    for (let k = 0; k < pts.length; k += 2) {
      xmin = Math.min(xmin, pts[k]);
      xmax = Math.max(xmax, pts[k]);
      ymin = Math.min(ymin, pts[k + 1]);
      ymax = Math.max(ymax, pts[k + 1]);
    }
  }
  const pad = 12;
  const scale = Math.min(
    (cssWidth - 2 * pad) / Math.max(xmax - xmin, 1e-300),
    (cssHeight - 2 * pad) / Math.max(ymax - ymin, 1e-300),
  );
  const ox = (cssWidth - scale * (xmax - xmin)) / 2;
  const oy = (cssHeight - scale * (ymax - ymin)) / 2;
  const sx = (x) => ox + scale * (x - xmin);
  const sy = (y) => cssHeight - oy - scale * (y - ymin);  // y up

  let min = Infinity, max = -Infinity;
  for (const v of values) {
    if (Number.isFinite(v)) {
      min = Math.min(min, v);
      max = Math.max(max, v);
    }
  }
  const span = max > min ? max - min : 1;

  ctx.lineJoin = 'round';
  ctx.lineWidth = 0.6;  // the same colour as the fill hides anti-aliasing seams between cells
  const tri = mesh.triangles;
  for (let c = 0; c < tri.length / 3; c++) {
    const [r, g, b] = colourAt((values[c] - min) / span);
    const style = `rgb(${r},${g},${b})`;
    ctx.fillStyle = style;
    ctx.strokeStyle = style;
    ctx.beginPath();
    for (let k = 0; k < 3; k++) {
      const v = tri[3 * c + k];
      const X = sx(deformed[2 * v]);
      const Y = sy(deformed[2 * v + 1]);
      if (k === 0) ctx.moveTo(X, Y);
      else ctx.lineTo(X, Y);
    }
    ctx.closePath();
    ctx.fill();
    ctx.stroke();
  }

  if (magnification !== 0) {
    ctx.strokeStyle = 'rgba(90, 90, 90, 0.9)';
    ctx.lineWidth = 1;
    ctx.setLineDash([4, 3]);
    ctx.beginPath();
    for (const [a, b] of boundaryEdges(tri)) {
      ctx.moveTo(sx(mesh.points[2 * a]), sy(mesh.points[2 * a + 1]));
      ctx.lineTo(sx(mesh.points[2 * b]), sy(mesh.points[2 * b + 1]));
    }
    ctx.stroke();
    ctx.setLineDash([]);
  }
  return { min, max };
}
