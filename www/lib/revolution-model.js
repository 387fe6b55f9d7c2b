import { errorText } from "./core-errors.js";
/**
 * The wasm side of the surface-revolution demo: the curves of the current mode and the surface
 * the core makes from them (`sl.revolve`, `sl.extrude`, `sl.ruled`), kept as one object with a
 * `free()` so the demo runtime frees it when it is replaced. A drag sets the curves' control
 * points in place and asks the core for the surface again (the surface of a moved profile is a
 * new net, not a moved point), timing that call for the lesson's readout.
 *
 * Also the number formatting of the demo's check line, and the distance of sampled points from
 * a torus — the measured check shown to students (|√((√(x² + y²) − R)² + z²) − r|), not a step of
 * any construction.
 */
import { localeDecimal, texDecimal } from "./format.js";

export const MODES = Object.freeze(["torus", "vase", "extrude", "ruled"]);
/** The torus check samples the surface on a GRID_CHECK × GRID_CHECK grid of (u, v). */
export const GRID_CHECK = 65;
/** The torus' R (distance of the circle's centre from the axis): the slider's and the handle's range. */
export const R_RANGE = Object.freeze([0.5, 6]);

const ORIGIN = Object.freeze([0, 0, 0]);
const Z_AXIS = Object.freeze([0, 0, 1]);
const DEG = Math.PI / 180;
const CUBIC = 3;

/** Profile [a, b] pairs as flat xyz: (a, 0, b) in the xz plane (vase) or (a, b, 0) (extrude). */
function profileFlat(profile, inXz) {
  const flat = new Float64Array(3 * profile.length);
  profile.forEach(([p, q], i) => {
    flat[3 * i] = p;
    flat[3 * i + 1] = inXz ? 0 : q;
    flat[3 * i + 2] = inXz ? q : 0;
  });
  return flat;
}

const xyz = new Float64Array(3);

export class Construction {
  /** Builds the mode's curves and surface; throws the core's refusal (the state is not taken). */
  constructor(s, sl) {
    this.sl = sl;
    this.mode = s.mode;
    this.curves = [];
    this.surface = null;
    /** Milliseconds of the last surface construction and of the last mesh (set by the demo). */
    this.timing = { surface: 0, mesh: 0 };
    try {
      this.curves = this._curves(s);
      this.surface = this._surface(s);
    } catch (err) {
      this.free();
      throw err;
    }
  }

  _curves(s) {
    const sl = this.sl;
    switch (s.mode) {
      case "torus":
        // The exact NURBS circle: 9 points, weights 1, √2/2, 1, … (four 90° arcs).
        return [sl.ellipseArc([s.R, 0, 0], [s.r, 0, 0], [0, 0, s.r], 0, 2 * Math.PI)];
      case "vase":
      case "extrude": {
        const flat = profileFlat(s.profile, s.mode === "vase");
        const knots = sl.knotVector(flat, 3, CUBIC, "clamped");
        return [new sl.BSplineCurve(flat, 3, CUBIC, knots)];
      }
      default:
        return [
          new sl.BezierCurve(Float64Array.from(s.curveA.flat()), 3),
          new sl.BezierCurve(Float64Array.from(s.curveB.flat()), 3),
        ];
    }
  }

  _surface(s) {
    const sl = this.sl;
    const start = performance.now();
    let surface;
    switch (s.mode) {
      case "torus":
        surface = sl.revolve(this.curves[0], ORIGIN, Z_AXIS, s.angle * DEG);
        break;
      case "vase":
        surface = sl.revolve(this.curves[0], ORIGIN, Z_AXIS);
        break;
      case "extrude":
        surface = sl.extrude(this.curves[0], s.direction);
        break;
      default:
        surface = sl.ruled(this.curves[0], this.curves[1]);
    }
    this.timing.surface = performance.now() - start;
    return surface;
  }

  /**
   * Point `index` of list `field` was dragged: only that control point is set in its curve
   * (`setControlPoint`), then the core makes the surface anew (or reports a refusal).
   */
  movePoint(s, field, index, ui) {
    const inXz = s.mode === "vase";
    if (field === "profile") {
      const [p, q] = s.profile[index];
      xyz[0] = p;
      xyz[1] = inXz ? 0 : q;
      xyz[2] = inXz ? q : 0;
      this.curves[0].setControlPoint(index, xyz);
    } else if (field === "curveA" || field === "curveB") {
      this.curves[field === "curveA" ? 0 : 1].setControlPoint(index, s[field][index]);
    }
    this.remake(s, ui);
  }

  /**
   * The surface made anew from the curves (after a new extrusion direction too); a refusal (a
   * zero direction) keeps the last surface and is reported in the status line.
   */
  remake(s, ui) {
    try {
      const next = this._surface(s);
      this.surface.free();
      this.surface = next;
    } catch (err) {
      ui.status(errorText(err), "error");
    }
  }

  free() {
    for (const curve of this.curves) curve.free();
    this.surface?.free();
    this.curves = [];
    this.surface = null;
  }
}

/** max over sampled points (flat xyz) of |√((√(x² + y²) − R)² + z²) − r|: the distance from the torus. */
export function torusDistance(points, R, r) {
  let worst = 0;
  for (let k = 0; k < points.length; k += 3) {
    const rho = Math.hypot(points[k], points[k + 1]) - R;
    worst = Math.max(worst, Math.abs(Math.hypot(rho, points[k + 2]) - r));
  }
  return worst;
}

const SUPERSCRIPT = {
  "-": "⁻",
  0: "⁰",
  1: "¹",
  2: "²",
  3: "³",
  4: "⁴",
  5: "⁵",
  6: "⁶",
  7: "⁷",
  8: "⁸",
  9: "⁹",
};

/** A small number as mantissa and exponent ("4.4", "-16"), or null for 0. */
function scientific(x) {
  if (x === 0) return null;
  const [m, e] = x.toExponential(1).split("e");
  return [m, String(Number(e))];
}

/** "4.4 × 10⁻¹⁶" (text), "0" for 0. */
export function sciText(x) {
  const parts = scientific(x);
  if (!parts) return "0";
  return `${localeDecimal(parts[0])} × 10${[...parts[1]].map((c) => SUPERSCRIPT[c]).join("")}`;
}

/** "4.4 \cdot 10^{-16}" (TeX), "0" for 0. */
export function sciTex(x) {
  const parts = scientific(x);
  return parts ? `${texDecimal(parts[0])} \\cdot 10^{${parts[1]}}` : "0";
}

/** A weight as TeX: 1, √2/2 and ½ by name (to 1e-12), else 4 decimals. */
export function weightTex(w) {
  if (Math.abs(w - 1) < 1e-12) return "1";
  if (Math.abs(w - Math.SQRT1_2) < 1e-12) return "\\tfrac{\\sqrt{2}}{2}";
  if (Math.abs(w - 0.5) < 1e-12) return "\\tfrac12";
  return texDecimal(w.toFixed(4));
}
