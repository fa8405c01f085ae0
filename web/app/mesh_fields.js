// What the deformed mesh can be coloured by: one value per triangle, taken from the VTU's
// arrays (docs/result-format.md, "VTU file"), with the unit each carries. Results are in the
// units of the case, so a unit is named by what it is in the case (the stress unit of μ or E,
// the length unit of the mesh), not by a symbol the case never states.

/** Unit ids of docs/result-format.md → how the colour bar names them. */
export const UNITS = {
  S: 'the stress unit of the case (that of μ or E)',
  L: 'the length unit of the mesh',
  scaled: 'scaled units (stresses divided by μ)',
  bisections: 'bisections from the coarse-mesh triangle (a uniform refinement counts as two)',
};

/**
 * The unit names of a result: those the case declared (`result.units`: "mm", "MPa", "N/mm"),
 * or the words of UNITS when it declared none.
 */
export function resultUnits(result) {
  const u = result?.units;
  if (u?.declared) return { declared: true, L: u.length, S: u.stress, F: u.force_per_thickness };
  return { declared: false, L: UNITS.L, S: UNITS.S, F: 'per unit thickness' };
}

const cellArray = (name) => (mesh) => mesh.cellData[name]?.values ?? null;

/** Component k of a cell array with several components (σ is stored row by row). */
const cellComponent = (name, k) => (mesh) => {
  const a = mesh.cellData[name];
  if (!a || a.components <= k) return null;
  const n = a.values.length / a.components;
  const out = new Float64Array(n);
  for (let c = 0; c < n; c++) out[c] = a.values[c * a.components + k];
  return out;
};

/** The mean over each triangle's vertices of f(ux, uy) of the point array u. */
const displacementPerCell = (f) => (mesh) => {
  const u = mesh.pointData.u;
  if (!u) return null;
  const n = mesh.triangles.length / 3;
  const out = new Float64Array(n);
  for (let c = 0; c < n; c++) {
    let sum = 0;
    for (let k = 0; k < 3; k++) {
      const v = mesh.triangles[3 * c + k];
      sum += f(u.values[v * u.components], u.values[v * u.components + 1]);
    }
    out[c] = sum / 3;
  }
  return out;
};

/**
 * Fields the mesh can be coloured by: id → {label, unit, signed (a component whose sign
 * matters: a diverging colour map when it takes both signs), compute(mesh) → per-cell values}.
 */
export const MESH_FIELDS = {
  von_mises: { label: 'von Mises stress', unit: 'S', compute: cellArray('von_mises') },
  sigma_xx: { label: 'σ_xx', unit: 'S', signed: true, compute: cellComponent('sigma', 0) },
  sigma_xy: { label: 'σ_xy', unit: 'S', signed: true, compute: cellComponent('sigma', 1) },
  sigma_yx: { label: 'σ_yx', unit: 'S', signed: true, compute: cellComponent('sigma', 2) },
  sigma_yy: { label: 'σ_yy', unit: 'S', signed: true, compute: cellComponent('sigma', 3) },
  displacement: { label: 'displacement |u|', unit: 'L', compute: displacementPerCell(Math.hypot) },
  u_x: { label: 'displacement u_x', unit: 'L', signed: true, compute: displacementPerCell((x) => x) },
  u_y: { label: 'displacement u_y', unit: 'L', signed: true, compute: displacementPerCell((x, y) => y) },
  functional: { label: 'FOSLS functional (error indicator)', unit: 'scaled', compute: cellArray('functional') },
  generation: { label: 'refinement generation', unit: 'bisections', compute: cellArray('generation') },
};

/**
 * What a probe reports besides the coloured field: σ of the triangle (row by row) and u at the
 * point, interpolated linearly from the triangle's vertices (u is P1). `hit` is {cell,
 * weights} (barycentric); returns {text, u: [ux, uy] or null}.
 */
export function probeSummary(mesh, hit, format) {
  const parts = [];
  const sigma = mesh.cellData.sigma;
  if (sigma && sigma.components >= 4) {
    const s = (k) => format(sigma.values[hit.cell * sigma.components + k]);
    parts.push(`σ = [${s(0)}, ${s(1)}; ${s(2)}, ${s(3)}]`);
  }
  const u = mesh.pointData.u;
  let at = null;
  if (u) {
    at = [0, 1].map((d) => hit.weights.reduce((sum, w, k) => sum + w * u.values[mesh.triangles[3 * hit.cell + k] * u.components + d], 0));
    parts.push(`u = (${format(at[0])}, ${format(at[1])})`);
  }
  return { text: parts.join(' · '), u: at };
}
