// The interactive 3D view of a tetrahedral result's deformed boundary surface on a 2D canvas:
// flat-shaded triangles painted far to near (surface_camera.js), coloured per triangle by a
// field (surface_fields.js; NaN in a neutral grey), with the pressure line drawn over them.
// Orbit by drag or the arrow keys, zoom by wheel or + / −, 0 or resetView() for the default
// camera. A canvas 2D rather than WebGL: headless Chromium without a GPU draws it the same,
// and a few thousand triangles take milliseconds.
import { boundingBall, defaultCamera, paintOrder, pitch, project, shade, yaw } from './surface_camera.js';
import { colourAt } from './mesh_view.js';
import { normalOf } from './tet_surface.js';
import { CanvasView } from './canvas_view.js';

const ZOOM_MIN = 0.3;
const ZOOM_MAX = 50;
const TURN_PER_PIXEL = 0.008;      // radians of orbit per pixel dragged
const KEY_TURN = Math.PI / 18;     // 10° per arrow key
const NEUTRAL = [200, 200, 200];   // NaN values: off the contact for the pressure

export class SurfaceViewer extends CanvasView {
  constructor({ canvas }) {
    super(canvas);
    this.surface_ = null;  // {mesh, surface, frame}
    this.field_ = null;    // {values (per triangle), scale {map, min, max}}
    this.line_ = null;     // Float64Array of x, y, z triples, NaN between runs
    this.zoom_ = 1;
    this.camera_ = defaultCamera(null);
    this.listen_();
  }

  /** A new surface ({mesh, surface, frame}: the plane's frame orients the default camera). */
  setSurface(surface) {
    this.surface_ = surface;
    this.deformed_ = null;
    this.line_ = null;
    this.resetView();
  }

  setField(field) {
    this.field_ = field;
    this.redraw();
  }

  /** The pressure line's points (x, y, z triples; a NaN triple breaks the line), or null. */
  setLine(points) {
    this.line_ = points;
    this.redraw();
  }


  resetView() {
    this.camera_ = defaultCamera(this.surface_?.frame);
    this.zoom_ = 1;
    this.redraw();
  }

  /** Orbits the camera: `right` and `down` in radians (a drag to the right turns the body right). */
  turn(right, down) {
    this.camera_ = pitch(yaw(this.camera_, -right), -down);
    this.redraw();
  }

  zoomBy(factor) {
    this.zoom_ = Math.min(ZOOM_MAX, Math.max(ZOOM_MIN, this.zoom_ * factor));
    this.redraw();
  }


  /** The deformed points x + m·u and the ball that holds them, kept until m or the mesh change. */
  geometry_() {
    if (this.deformed_) return;
    const { points3, pointData } = this.surface_.mesh;
    const u = pointData.u;
    const m = this.magnification_;
    this.deformed_ = Float64Array.from(points3, (x, i) => (u ? x + m * u.values[Math.floor(i / 3) * u.components + (i % 3)] : x));
    this.ball_ = boundingBall(this.deformed_);
  }

  draw_() {
    const canvas = this.canvas_;
    // Not laid out (the view is hidden): the ResizeObserver redraws when it is shown.
    if (!this.surface_ || !this.field_ || canvas.clientWidth === 0 || canvas.clientHeight === 0) return;
    this.geometry_();
    const started = performance.now();
    const ratio = window.devicePixelRatio || 1;
    const [width, height] = [canvas.clientWidth, canvas.clientHeight];
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    const ctx = canvas.getContext('2d');
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, width, height);
    const screen = project(this.deformed_, this.camera_, this.ball_, width, height, this.zoom_);
    const order = this.paintTriangles_(ctx, screen);
    this.paintLine_(ctx, width, height);
    const towards = this.camera_.towards.map((c) => c.toFixed(3)).join(',');
    this.draws_ = (this.draws_ ?? 0) + 1;
    Object.assign(canvas.dataset, {
      draws: String(this.draws_), drawn: String(order.length), zoom: String(Number(this.zoom_.toPrecision(4))), view: towards,
      drawMs: (performance.now() - started).toFixed(1),
    });
  }

  /** The visible triangles, far to near, each in its field colour times its flat shade. */
  paintTriangles_(ctx, screen) {
    const t = this.surface_.surface.triangles;
    const { values, scale } = this.field_;
    const span = scale.max - scale.min;
    const order = paintOrder(t, screen);
    ctx.lineWidth = 0.6;  // each triangle's own colour over its edges hides the seams between them
    ctx.lineJoin = 'round';
    for (const f of order) {
      const v = values[f];
      const base = Number.isFinite(v) ? colourAt(span > 0 ? (v - scale.min) / span : 0.5, scale.map) : NEUTRAL;
      const light = shade(normalOf(this.deformed_, t[3 * f], t[3 * f + 1], t[3 * f + 2]), this.camera_);
      const colour = `rgb(${base.map((c) => Math.round(c * light)).join(',')})`;
      ctx.fillStyle = colour;
      ctx.strokeStyle = colour;
      ctx.beginPath();
      for (let k = 0; k < 3; k++) {
        const a = t[3 * f + k];
        if (k === 0) ctx.moveTo(screen[3 * a], screen[3 * a + 1]);
        else ctx.lineTo(screen[3 * a], screen[3 * a + 1]);
      }
      ctx.closePath();
      ctx.fill();
      ctx.stroke();
    }
    return order;
  }

  /** The pressure line, in the plane, over everything (white under black, visible on any colour). */
  paintLine_(ctx, width, height) {
    if (!this.line_?.length) return;
    const screen = project(this.line_, this.camera_, this.ball_, width, height, this.zoom_);
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

  listen_() {
    const canvas = this.canvas_;
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.zoomBy(Math.exp(-e.deltaY * 0.0015));
    }, { passive: false });
    canvas.addEventListener('pointerdown', (e) => {
      this.drag_ = [e.clientX, e.clientY];
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener('pointermove', (e) => {
      if (!this.drag_) return;
      this.turn((e.clientX - this.drag_[0]) * TURN_PER_PIXEL, (e.clientY - this.drag_[1]) * TURN_PER_PIXEL);
      this.drag_ = [e.clientX, e.clientY];
    });
    const stop = () => {
      this.drag_ = null;
    };
    canvas.addEventListener('pointerup', stop);
    canvas.addEventListener('pointercancel', stop);
    canvas.addEventListener('keydown', (e) => {
      const actions = {
        '+': () => this.zoomBy(1.25),
        '=': () => this.zoomBy(1.25),
        '-': () => this.zoomBy(0.8),
        0: () => this.resetView(),
        ArrowLeft: () => this.turn(-KEY_TURN, 0),
        ArrowRight: () => this.turn(KEY_TURN, 0),
        ArrowUp: () => this.turn(0, -KEY_TURN),
        ArrowDown: () => this.turn(0, KEY_TURN),
      };
      if (actions[e.key]) {
        e.preventDefault();
        actions[e.key]();
      }
    });
  }
}
