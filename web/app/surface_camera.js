// The 3D view's camera and projection, without a canvas: an orthographic camera given by an
// orthonormal frame (right, up, towards the viewer) that orbits the surface's centre, the
// projection of points to the screen, and the painter's order of the visible triangles.

const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const unit = (a) => {
  const l = Math.hypot(...a);
  return a.map((c) => c / l);
};
const combine = (a, ca, b, cb) => a.map((x, k) => ca * x + cb * b[k]);

/** The default tilt (radians) away from looking straight along the plane normal. */
export const DEFAULT_TILT = (35 * Math.PI) / 180;

/**
 * The camera that looks at the contact surface from the obstacle's side: along the plane's
 * normal n (from the plane into the body), tilted by DEFAULT_TILT about the plane's first
 * tangent t1 so that the body's side shows too. Without a plane: an oblique view from −z.
 */
export function defaultCamera(frame) {
  const n = frame?.n ?? [0, 0, 1];
  const t1 = frame?.t1 ?? [1, 0, 0];
  const towards = n.map((c) => -c);       // the viewer stands on the plane's side of the body
  const up = cross(towards, t1);          // so that right × up = towards
  return pitch({ right: t1, up, towards }, -DEFAULT_TILT);
}

/** The camera turned about its up axis by `angle` (radians): the view orbits left or right. */
export function yaw(camera, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return orthonormal({
    right: combine(camera.right, c, camera.towards, s),
    up: camera.up,
    towards: combine(camera.towards, c, camera.right, -s),
  });
}

/** The camera turned about its right axis by `angle` (radians): the view orbits up or down. */
export function pitch(camera, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return orthonormal({
    right: camera.right,
    up: combine(camera.up, c, camera.towards, -s),
    towards: combine(camera.towards, c, camera.up, s),
  });
}

/** Gram–Schmidt on (towards, up), right = up × towards: keeps many small turns from drifting. */
function orthonormal({ up, towards }) {
  const w = unit(towards);
  const v = unit(combine(up, 1, w, -dot(up, w)));
  return { right: cross(v, w), up: v, towards: w };
}

/** The centre of the points' bounding box and the radius of the ball about it that holds them. */
export function boundingBall(points) {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < points.length; i += 3) {
    for (let d = 0; d < 3; d++) {
      lo[d] = Math.min(lo[d], points[i + d]);
      hi[d] = Math.max(hi[d], points[i + d]);
    }
  }
  const centre = lo.map((l, d) => (l + hi[d]) / 2);
  let radius = 0;
  for (let i = 0; i < points.length; i += 3) {
    radius = Math.max(radius, Math.hypot(points[i] - centre[0], points[i + 1] - centre[1], points[i + 2] - centre[2]));
  }
  return { centre, radius };
}

/**
 * Screen coordinates of the points (x, y, z triples): [X, Y, depth] triples in CSS pixels,
 * the ball about `centre` of `radius` fitting the width × height canvas at zoom 1, Y down,
 * depth growing towards the viewer. The fit does not depend on the camera, so a turn keeps
 * the size.
 */
export function project(points, camera, { centre, radius }, width, height, zoom = 1) {
  const scale = (zoom * 0.46 * Math.min(width, height)) / (radius || 1);
  const out = new Float64Array(points.length);
  for (let i = 0; i < points.length; i += 3) {
    const p = [points[i] - centre[0], points[i + 1] - centre[1], points[i + 2] - centre[2]];
    out[i] = width / 2 + scale * dot(p, camera.right);
    out[i + 1] = height / 2 - scale * dot(p, camera.up);
    out[i + 2] = scale * dot(p, camera.towards);
  }
  return out;
}

/**
 * The triangles that face the viewer, farthest first (painter's algorithm: each is painted
 * over those behind it). A triangle faces the viewer when its screen corners turn
 * counter-clockwise as seen (outward normal towards the camera); on a closed surface the
 * others are hidden behind the front. Sorting by the mean depth is exact for a convex surface
 * and close enough for a slightly deformed one.
 */
export function paintOrder(triangles, screen) {
  const visible = [];
  const depth = new Float64Array(triangles.length / 3);
  for (let f = 0; f < triangles.length / 3; f++) {
    const [a, b, c] = [triangles[3 * f], triangles[3 * f + 1], triangles[3 * f + 2]];
    const turn = (screen[3 * b] - screen[3 * a]) * (screen[3 * c + 1] - screen[3 * a + 1]) -
      (screen[3 * b + 1] - screen[3 * a + 1]) * (screen[3 * c] - screen[3 * a]);
    if (turn >= 0) continue;  // Y points down: a counter-clockwise turn on screen is negative
    visible.push(f);
    depth[f] = screen[3 * a + 2] + screen[3 * b + 2] + screen[3 * c + 2];
  }
  return Uint32Array.from(visible).sort((f, g) => depth[f] - depth[g]);
}

/**
 * The brightness of a triangle whose outward normal is `normal` (any length) under a light
 * from over the viewer's shoulder: between 0.45 (edge-on) and 1 (facing the light), so
 * colours stay readable and the shape still shows.
 */
export function shade(normal, camera) {
  const light = unit(combine(combine(camera.towards, 1, camera.up, 0.35), 1, camera.right, -0.25));
  const cos = dot(unit(normal), light);
  return 0.45 + 0.55 * Math.max(0, cos);
}
