// The interactive deformed-mesh view: zoom (wheel, + / −), pan (drag, arrow keys), reset (0
// or the Reset button), mesh edges on or off, and a probe that reports the value and the
// coordinates under the pointer (hover) or at a clicked point (pinned, marked with a cross).
import { bounds, deformedPoints, drawMesh, fitTransform, locatePoint } from './mesh_drawing.js';
import { probeSummary } from './mesh_fields.js';
import { CanvasView } from './canvas_view.js';

const ZOOM_MIN = 0.5;
const ZOOM_MAX = 2000;
const DRAG_PIXELS = 4;  // a press that moves less is a click (a probe), not a pan

export class MeshViewer extends CanvasView {
  /**
   * canvas: the <canvas>; probe: the element that shows the probe's text; format(v): number
   * formatting for the probe.
   */
  constructor({ canvas, probe, format }) {
    super(canvas);
    this.probe_ = probe;
    this.format_ = format;
    this.mesh_ = null;
    this.field_ = null;  // {label, unitText, values, scale}
    this.edges_ = false;
    this.camera_ = { zoom: 1, tx: 0, ty: 0 };  // screen-space zoom and shift over the fit
    this.pinned_ = null;  // probed point in undeformed coordinates {cell, weights}
    this.drag_ = null;
    this.listen_();
  }

  /** A new mesh: the view is reset. */
  setMesh(mesh) {
    this.mesh_ = mesh;
    this.deformed_ = null;
    this.pinned_ = null;
    this.resetView();
  }

  /** The colouring: {label, unitText, values (one per triangle), scale {map, min, max}}. */
  setField(field) {
    this.field_ = field;
    this.showProbe_(this.pinned_);
    this.redraw();
  }


  setEdges(on) {
    this.edges_ = on;
    this.redraw();
  }

  resetView() {
    this.camera_ = { zoom: 1, tx: 0, ty: 0 };
    this.redraw();
  }

  get zoom() {
    return this.camera_.zoom;
  }


  /** Zooms by `factor` about the canvas point (px, py) in CSS pixels (default: the centre). */
  zoomBy(factor, px = this.canvas_.clientWidth / 2, py = this.canvas_.clientHeight / 2) {
    const c = this.camera_;
    const zoom = Math.min(ZOOM_MAX, Math.max(ZOOM_MIN, c.zoom * factor));
    const f = zoom / c.zoom;
    this.camera_ = { zoom, tx: f * c.tx + px * (1 - f), ty: f * c.ty + py * (1 - f) };
    this.redraw();
  }

  panBy(dx, dy) {
    this.camera_.tx += dx;
    this.camera_.ty += dy;
    this.redraw();
  }

  /** The deformed points and the box that holds them and the undeformed mesh, kept until
   *  the mesh or the magnification change. */
  geometry_() {
    if (!this.deformed_) {
      this.deformed_ = deformedPoints(this.mesh_, this.magnification_);
      this.box_ = bounds(this.mesh_.points, this.deformed_);
    }
  }

  /** The mesh-to-CSS-pixel transform of the current view. */
  transform_() {
    this.geometry_();
    const fit = fitTransform(this.box_, this.canvas_.clientWidth, this.canvas_.clientHeight);
    const { zoom, tx, ty } = this.camera_;
    return { a: zoom * fit.a, bx: zoom * fit.bx + tx, by: zoom * fit.by + ty };
  }

  draw_() {
    const canvas = this.canvas_;
    // Not laid out (the job view is hidden): the ResizeObserver redraws when it is shown.
    if (!this.mesh_ || !this.field_ || canvas.clientWidth === 0 || canvas.clientHeight === 0) return;
    this.geometry_();
    const ratio = window.devicePixelRatio || 1;
    canvas.width = Math.round(canvas.clientWidth * ratio);
    canvas.height = Math.round(canvas.clientHeight * ratio);
    const ctx = canvas.getContext('2d');
    ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
    ctx.clearRect(0, 0, canvas.clientWidth, canvas.clientHeight);
    const t = this.transform_();
    const started = performance.now();
    drawMesh(ctx, ratio, this.mesh_, this.deformed_, this.field_.values, this.field_.scale, t, {
      edges: this.edges_,
      outline: this.magnification_ !== 0 ? this.mesh_.points : null,
    });
    if (this.pinned_) this.drawCross_(ctx, t, this.pinned_);
    canvas.dataset.drawMs = (performance.now() - started).toFixed(1);
    canvas.dataset.zoom = String(Number(this.camera_.zoom.toPrecision(4)));
    canvas.dataset.edges = this.edges_ ? 'on' : 'off';
  }

  /** A point of a triangle (barycentric weights) in the given point coordinates. */
  pointOf_(hit, pts) {
    const tri = this.mesh_.triangles;
    let x = 0, y = 0;
    for (let k = 0; k < 3; k++) {
      const v = tri[3 * hit.cell + k];
      x += hit.weights[k] * pts[2 * v];
      y += hit.weights[k] * pts[2 * v + 1];
    }
    return [x, y];
  }

  drawCross_(ctx, t, hit) {
    const [x, y] = this.pointOf_(hit, this.deformed_);
    const X = t.bx + t.a * x;
    const Y = t.by - t.a * y;
    ctx.lineWidth = 2;
    for (const [colour, r] of [['#ffffff', 8], ['#d0021b', 6]]) {
      ctx.strokeStyle = colour;
      ctx.beginPath();
      ctx.moveTo(X - r, Y);
      ctx.lineTo(X + r, Y);
      ctx.moveTo(X, Y - r);
      ctx.lineTo(X, Y + r);
      ctx.stroke();
    }
  }

  /** The triangle under the canvas point (CSS pixels), or null. */
  hitAt(px, py) {
    if (!this.mesh_) return null;
    const t = this.transform_();
    return locatePoint(this.mesh_, this.deformed_, (px - t.bx) / t.a, (t.by - py) / t.a);
  }

  /** Shows the probe of `hit` (or the hint when null) in the probe element. */
  showProbe_(hit, pinned = hit === this.pinned_) {
    const out = this.probe_;
    if (!hit || !this.field_ || !this.mesh_) {
      out.textContent = 'Probe: hover over the mesh for the value at a point, click to pin it.';
      delete out.dataset.cell;
      return;
    }
    const [x, y] = this.pointOf_(hit, this.mesh_.points);
    const value = this.field_.values[hit.cell];
    const f = this.format_;
    const more = probeSummary(this.mesh_, hit, f);
    out.textContent = `${pinned ? 'Pinned' : 'Probe'}: x = ${f(x)}, y = ${f(y)} (undeformed) · ` +
      `${this.field_.label} = ${f(value)} (${this.field_.unitText}) · triangle ${hit.cell}` +
      (more.text ? ` · ${more.text}` : '');
    Object.assign(out.dataset, { cell: String(hit.cell), value: String(value), x: String(x), y: String(y) });
    if (more.u) Object.assign(out.dataset, { ux: String(more.u[0]), uy: String(more.u[1]) });
  }

  listen_() {
    const canvas = this.canvas_;
    const local = (e) => {
      const r = canvas.getBoundingClientRect();
      return [e.clientX - r.left, e.clientY - r.top];
    };
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      this.zoomBy(Math.exp(-e.deltaY * 0.0015), ...local(e));
    }, { passive: false });
    canvas.addEventListener('pointerdown', (e) => {
      this.drag_ = { start: local(e), last: local(e), moved: false };
      canvas.setPointerCapture(e.pointerId);
    });
    canvas.addEventListener('pointermove', (e) => {
      const p = local(e);
      if (!this.drag_) {
        this.showProbe_(this.hitAt(...p), false);
        return;
      }
      const d = this.drag_;
      if (Math.hypot(p[0] - d.start[0], p[1] - d.start[1]) > DRAG_PIXELS) d.moved = true;
      if (d.moved) this.panBy(p[0] - d.last[0], p[1] - d.last[1]);
      d.last = p;
    });
    canvas.addEventListener('pointerup', (e) => {
      const d = this.drag_;
      this.drag_ = null;
      if (d && !d.moved) {
        this.pinned_ = this.hitAt(...local(e));
        this.showProbe_(this.pinned_, true);
        this.redraw();
      }
    });
    canvas.addEventListener('pointerleave', () => {
      if (!this.drag_) this.showProbe_(this.pinned_, true);
    });
    canvas.addEventListener('keydown', (e) => {
      const step = 40;
      const actions = {
        '+': () => this.zoomBy(1.25),
        '=': () => this.zoomBy(1.25),
        '-': () => this.zoomBy(0.8),
        0: () => this.resetView(),
        ArrowLeft: () => this.panBy(step, 0),
        ArrowRight: () => this.panBy(-step, 0),
        ArrowUp: () => this.panBy(0, step),
        ArrowDown: () => this.panBy(0, -step),
      };
      if (actions[e.key]) {
        e.preventDefault();
        actions[e.key]();
      }
    });
  }
}
