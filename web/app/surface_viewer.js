// The interactive 3D view of a tetrahedral result's deformed boundary surface on a 2D canvas:
// shaded triangles painted far to near (surface_painting.js), coloured by a field
// (surface_fields.js; NaN in a neutral grey), with the pressure line drawn over them. The
// default view looks at the contact faces from the plane's side and frames them with the body
// around; orbit (about their centre) by drag or the arrow keys, zoom by wheel or + / −, 0 or
// resetView() for the default view. A canvas 2D rather than WebGL: headless Chromium without a
// GPU draws it the same, and a few thousand triangles take milliseconds.
import { boundingBall, defaultCamera, pitch, project, yaw } from './surface_camera.js';
import { paintPolyline, paintSurface } from './surface_painting.js';
import { CanvasView } from './canvas_view.js';

const ZOOM_MIN = 0.3;
const ZOOM_MAX = 50;
const TURN_PER_PIXEL = 0.008;      // radians of orbit per pixel dragged
const KEY_TURN = Math.PI / 18;     // 10° per arrow key
const FOCUS_MAX = 3;               // the default framing enlarges the contact faces at most this much

export class SurfaceViewer extends CanvasView {
  constructor({ canvas }) {
    super(canvas);
    this.surface_ = null;  // {mesh, surface, frame, contact}
    this.field_ = null;    // {values (per triangle), vertexValues (or none), scale {map, min, max}}
    this.line_ = null;     // Float64Array of x, y, z triples, NaN between runs
    this.zoom_ = 1;
    this.camera_ = defaultCamera(null);
    this.listen_();
  }

  /**
   * A new surface: {mesh, surface, frame, contact}: the plane's frame orients the default
   * camera, the contact faces (contact[f] = 1) are what it frames.
   */
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

  /**
   * The deformed points x + m·u, the ball that holds them, and the framing: the view's centre
   * (that of the contact faces, or of the body without them) and how much the contact faces
   * are enlarged over the fit of the whole body (1 to FOCUS_MAX): so that they fill the view,
   * the body round them showing at its edges. Kept until m or the mesh change.
   */
  geometry_() {
    if (this.deformed_) return;
    const { mesh, surface, contact } = this.surface_;
    const u = mesh.pointData.u;
    const m = this.magnification_;
    this.deformed_ = Float64Array.from(mesh.points3, (x, i) => (u ? x + m * u.values[Math.floor(i / 3) * u.components + (i % 3)] : x));
    this.ball_ = boundingBall(this.deformed_);
    const onContact = [];
    for (let f = 0; f < (contact?.length ?? 0); f++) {
      if (!contact[f]) continue;
      for (let k = 0; k < 3; k++) onContact.push(...this.deformed_.subarray(3 * surface.triangles[3 * f + k], 3 * surface.triangles[3 * f + k] + 3));
    }
    const focus = onContact.length ? boundingBall(onContact) : this.ball_;
    const enlarge = Math.min(FOCUS_MAX, Math.max(1, this.ball_.radius / (focus.radius || this.ball_.radius)));
    this.framing_ = { centre: focus.centre, radius: this.ball_.radius / enlarge };
  }

  draw_() {
    const canvas = this.canvas_;
    // Not laid out (the view is hidden): the ResizeObserver redraws when it is shown.
    if (!this.surface_ || canvas.clientWidth === 0 || canvas.clientHeight === 0) return;
    if (!this.field_) {  // nothing to colour by: an empty view rather than a stale one
      canvas.getContext('2d').clearRect(0, 0, canvas.width, canvas.height);
      return;
    }
    this.geometry_();
    const started = performance.now();
    const ratio = window.devicePixelRatio || 1;
    const [width, height] = [canvas.clientWidth, canvas.clientHeight];
    canvas.width = Math.round(width * ratio);
    canvas.height = Math.round(height * ratio);
    const ctx = canvas.getContext('2d');
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, width, height);
    const screen = project(this.deformed_, this.camera_, this.framing_, width, height, this.zoom_);
    const { triangles } = this.surface_.surface;
    const order = paintSurface(ctx, { triangles, screen, deformed: this.deformed_, camera: this.camera_, field: this.field_ });
    if (this.line_?.length) paintPolyline(ctx, project(this.line_, this.camera_, this.framing_, width, height, this.zoom_));
    const towards = this.camera_.towards.map((c) => c.toFixed(3)).join(',');
    this.draws_ = (this.draws_ ?? 0) + 1;
    Object.assign(canvas.dataset, {
      draws: String(this.draws_), drawn: String(order.length), zoom: String(Number(this.zoom_.toPrecision(4))), view: towards,
      drawMs: (performance.now() - started).toFixed(1),
    });
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
