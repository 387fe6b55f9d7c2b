/**
 * A tiny fixed camera for drawing a 3D picture in a 2D figure (e.g. the homogeneous space
 * (wx, wy, w) of a rational curve): an oblique parallel projection, fitted into a box of the
 * canvas. Display code only; nothing here computes a curve.
 *
 * The maths. A space point (X, Y, Z) goes to the plane coordinates
 *   u = X + a·Y,   v = s·Z + b·Y,
 * so X points right, Z up, and Y recedes up and to the right by (a, b) per unit (a cabinet-style
 * oblique view; a = b = 0 is the orthographic front view). The stretch s of the Z axis is chosen
 * per picture (e.g. so the heights match the XY extent). Then the canvas point is
 *   x = oₓ + k·u,   y = o_y − k·v   (canvas y grows downwards),
 * with the scale k and origin (oₓ, o_y) from `fit`: the largest k that fits the extent of the
 * points given to `include` into the box, centred. The whole map is linear in (X, Y, Z), so
 * lines stay lines and rays through the origin stay rays through the image of the origin.
 */
export class ObliqueCamera {
  /** @param {{ receding: [number, number] }} o the (a, b) direction of the Y axis per unit. */
  constructor({ receding }) {
    this.a = receding[0];
    this.b = receding[1];
    /** The stretch s of the Z axis. */
    this.stretch = 1;
    this.k = 1;
    this.ox = 0;
    this.oy = 0;
    this.u0 = 0;
    this.u1 = 0;
    this.v0 = 0;
    this.v1 = 0;
  }

  /** Starts a new extent holding only the origin (call `include`, then `fit`). */
  reset(stretch = this.stretch) {
    this.stretch = stretch;
    this.u0 = this.u1 = this.v0 = this.v1 = 0;
  }

  /** Grows the extent by the space point (X, Y, Z). */
  include(X, Y, Z) {
    const u = X + this.a * Y;
    const v = this.stretch * Z + this.b * Y;
    this.u0 = Math.min(this.u0, u);
    this.u1 = Math.max(this.u1, u);
    this.v0 = Math.min(this.v0, v);
    this.v1 = Math.max(this.v1, v);
  }

  /**
   * Fits the extent into the canvas box [x0, x1] × [y0, y1], centred; an extent thinner than
   * `minExtent` in a direction counts as that thin (no division by zero).
   */
  fit(x0, y0, x1, y1, minExtent = 1e-9) {
    const { u0, u1, v0, v1 } = this;
    this.k = Math.min(
      (x1 - x0) / Math.max(u1 - u0, minExtent),
      (y1 - y0) / Math.max(v1 - v0, minExtent),
    );
    this.ox = (x0 + x1) / 2 - ((u0 + u1) / 2) * this.k;
    this.oy = (y0 + y1) / 2 + ((v0 + v1) / 2) * this.k;
  }

  /** Canvas x of the space point (X, Y, Z) (Z does not move it sideways). */
  sx(X, Y, Z) {
    return this.ox + (X + this.a * Y) * this.k;
  }

  /** Canvas y of the space point (X, Y, Z) (X does not move it up or down). */
  sy(X, Y, Z) {
    return this.oy - (this.stretch * Z + this.b * Y) * this.k;
  }
}
