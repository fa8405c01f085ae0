// What the 2D mesh view (mesh_viewer.js) and the 3D surface view (surface_viewer.js) share: a
// canvas drawn at most once per animation frame, and a displacement magnification whose change
// drops the deformed points (this.deformed_) so the next drawing computes them again.
export class CanvasView {
  constructor(canvas) {
    this.canvas_ = canvas;
    this.magnification_ = 1;
    this.deformed_ = null;
    this.frame_ = 0;
  }

  setMagnification(m) {
    if (m === this.magnification_ && this.deformed_) return;
    this.magnification_ = m;
    this.deformed_ = null;
    this.redraw();
  }

  /** Draws (this.draw_()) at the next animation frame: many events per frame cost one drawing. */
  redraw() {
    if (this.frame_) return;
    this.frame_ = requestAnimationFrame(() => {
      this.frame_ = 0;
      this.draw_();
    });
  }
}
