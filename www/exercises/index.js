/**
 * Exercises: a demo state with a goal that the core checks (one or more per syllabus section).
 * An exercise names its demo, the starting state (the fields it changes from the demo's
 * default), and `check(sl, state)`, which asks the wasm core about the student's current state
 * and returns `{ solved, detail }` (`detail`: the measured number, for the message). Its texts
 * are `exercise.<id>.title | task | hint` in the string tables. Opened at `#exercise=<id>` (the
 * state follows in `&s=`) or embedded with `<spline-lab exercise="<id>">` (lib/exercise.js).
 */
import { formatNumber, t, tp } from "../lib/strings.js";
import { orderText } from "../lib/continuity.js";
import { decodeStroke } from "../lib/stroke-code.js";
import { presetStroke } from "../demos/presets/sketch.js";

/** Flat [x0, y0, x1, y1, …] of [[x, y], …]. */
const flat = (points) => points.flat();
/** The largest of `values`. */
const largest = (values) => values.reduce((a, b) => Math.max(a, b), 0);
const SMALL = Object.freeze({ maximumSignificantDigits: 2 });
const num = (value) => formatNumber(value, SMALL);

/** The tolerance (world units) within which a hand-dragged joint counts as continuous. */
export const JOINT_TOLERANCE = 0.05;
/** The sketch exercise: at most this many pieces, at a tolerance of at least this many px. */
export const SKETCH_PIECES = 6;
export const SKETCH_TOLERANCE = 3;
/** Samples of a curve when the check measures it. */
const SAMPLES = 256;

/** The joint's continuity C^k of two Bézier pieces (the core's `jointContinuity`). */
function jointOrder(sl, state) {
  const left = new sl.BezierCurve(flat(state.left), 2);
  const right = new sl.BezierCurve(flat(state.right), 2);
  try {
    return sl.jointContinuity(left, right, JOINT_TOLERANCE).c;
  } finally {
    left.free();
    right.free();
  }
}

/** The first cubic of both joint exercises: P₀ … P₃, ending at P₃ = (4, 1). */
const LEFT_CUBIC = [
  [0, 0],
  [1, 3],
  [3, 3],
  [4, 1],
];

export const exercises = Object.freeze(
  [
    {
      id: "close-the-gap",
      section: 1,
      demo: "joining",
      state: {
        left: LEFT_CUBIC,
        right: [
          [5, 2],
          [6, -1],
          [7, 0],
          [8, 2],
        ],
        rule: "none",
      },
      /** C⁰: the pieces meet (the core's jointContinuity reports c ≥ 0). */
      check(sl, state) {
        const gap = Math.hypot(
          state.right[0][0] - state.left[3][0],
          state.right[0][1] - state.left[3][1],
        );
        return { solved: jointOrder(sl, state) >= 0, detail: num(gap) };
      },
    },
    {
      id: "piecewise-c1",
      section: 1,
      demo: "piecewise",
      state: {
        pieces: [
          { x: "1 - t^2", y: "t", from: "0", to: "1" },
          { x: "2 - t^2", y: "t", from: "1", to: "2" },
        ],
      },
      /**
       * C¹ at t = 1: the core's `joints()[0].c ≥ 1` (proven in exact arithmetic for polynomial
       * pieces; measured otherwise). One solution: x = t² − 4t + 3, y = t.
       */
      check(sl, state) {
        const curve = sl.parametricCurve(state.pieces);
        try {
          const joint = curve.joints()[0];
          if (!joint) return { solved: false, detail: t("piecewise.noJoints") };
          const found =
            joint.c < 0
              ? t("piecewise.verdict.broken")
              : joint.c === Infinity
                ? orderText("C", Infinity)
                : `${orderText("C", joint.c)}, ${orderText("G", joint.g)}`;
          return { solved: joint.c >= 1, detail: found };
        } finally {
          curve.free();
        }
      },
    },
    {
      id: "make-it-c1",
      section: 2,
      demo: "joining",
      state: {
        left: LEFT_CUBIC,
        right: [
          [4, 1],
          [6, 0],
          [7, 0],
          [8, 2],
        ],
        rule: "none",
      },
      /** C¹ between two cubics: 3(P₃ − P₂) = 3(Q₁ − Q₀), i.e. Q₁ = 2P₃ − P₂ = (5, −1). */
      check(sl, state) {
        return {
          solved: jointOrder(sl, state) >= 1,
          detail: String(Math.max(0, jointOrder(sl, state))),
        };
      },
    },
    {
      id: "bezier-pieces",
      section: 3,
      demo: "knot-insertion",
      state: { inserted: [], bezier: true },
      /**
       * Every interior knot raised to multiplicity p: the core's knotContinuity then reports
       * C⁰ (or less) at each of them, and the curve is a chain of Bézier segments.
       */
      check(sl, state) {
        const curve = new sl.BSplineCurve(flat(state.points), 2, state.degree, state.knots);
        const refined = state.inserted.length ? curve.refine(state.inserted) : curve.clone();
        try {
          const joints = refined.knotContinuity();
          const smooth = joints.filter((j) => j.continuity > 0).length;
          return { solved: smooth === 0, detail: String(smooth) };
        } finally {
          curve.free();
          refined.free();
        }
      },
    },
    {
      id: "quarter-circle",
      section: 4,
      demo: "conics",
      state: {
        points: [
          [4, 0],
          [4, 4],
          [0, 4],
        ],
        w1: 0.3,
      },
      /** Every sampled point at distance 4 from (0, 0), to 0.2 %: w₁ = cos 45° = √2/2. */
      check(sl, state) {
        const curve = new sl.BezierCurve(flat(state.points), 2, [1, state.w1, 1]);
        try {
          const xy = curve.sampleUniform(SAMPLES);
          const errors = [];
          for (let k = 0; k < SAMPLES; k++)
            errors.push(Math.abs(Math.hypot(xy[2 * k], xy[2 * k + 1]) - 4) / 4);
          const worst = largest(errors);
          return { solved: worst < 2e-3, detail: num(worst * 100) };
        } finally {
          curve.free();
        }
      },
    },
    {
      id: "natural-ends",
      section: 5,
      demo: "cubic-spline",
      state: { end: "not-a-knot" },
      /** Natural: the second derivative vanishes at both ends (the core's derivative(t, 2)). */
      check(sl, state) {
        if (state.end === "clamped") return { solved: false, detail: "—" };
        const spline = sl.cubicSpline(flat(state.points), 2, state.parametrization, state.end);
        try {
          const [a, b] = spline.domain();
          const ends = [a, b].map((t) => Math.hypot(...spline.derivative(t, 2)));
          const worst = largest(ends);
          return {
            solved: worst < 1e-9 * (1 + largest(flat(state.points).map(Math.abs))),
            detail: num(worst),
          };
        } finally {
          spline.free();
        }
      },
    },
    {
      id: "horn-torus",
      section: 6,
      demo: "surface-revolution",
      state: { mode: "torus", R: 3, r: 1 },
      /** A horn torus: the tube touches the axis, the profile circle's nearest point at x = 0. */
      check(sl, state) {
        if (state.mode !== "torus") return { solved: false, detail: "—" };
        const circle = sl.ellipseArc(
          [state.R, 0, 0],
          [state.r, 0, 0],
          [0, 0, state.r],
          0,
          2 * Math.PI,
        );
        try {
          const xyz = circle.sampleUniform(SAMPLES);
          let nearest = Infinity;
          for (let k = 0; k < SAMPLES; k++)
            nearest = Math.min(nearest, Math.hypot(xyz[3 * k], xyz[3 * k + 1]));
          return { solved: nearest < 0.02 * state.R, detail: num(nearest) };
        } finally {
          circle.free();
        }
      },
    },
    {
      id: "through-every-point",
      section: 7,
      demo: "interpolate-approximate",
      state: { role: "control" },
      /**
       * The curve the demo draws passes through every point (to 1e-9 of the data's size):
       * rebuilt from the state with the same core calls, measured at the chord parameters.
       */
      check(sl, state) {
        const data = flat(state.points);
        if (state.role === "control") return { solved: false, detail: "2" };
        const params = sl.parameterize(data, 2, "chord");
        const n = state.points.length;
        const curve =
          state.count === n
            ? sl.interpolateBSpline(data, 2, state.degree, params)
            : sl.approximateBSpline(data, 2, state.degree, state.count, params);
        try {
          const at = curve.sample(params);
          let met = 0;
          const scale = 1 + largest(data.map(Math.abs));
          for (let k = 0; k < n; k++) {
            if (Math.hypot(at[2 * k] - data[2 * k], at[2 * k + 1] - data[2 * k + 1]) < 1e-9 * scale)
              met++;
          }
          return { solved: met === n, detail: String(met) };
        } finally {
          curve.free();
        }
      },
    },
    {
      id: "sketch-pieces",
      section: 7,
      demo: "sketch",
      // A getter: the sample stroke is walked when the exercise opens, not as the page starts.
      get state() {
        return { stroke: presetStroke("wave"), tolerance: 3, edits: [] };
      },
      /**
       * The student's stroke fitted again by the core as the demo fits it (`fitCurveReport` at
       * ε = tolerance / scale; the edits are not the drawing): closed, at least one corner, at
       * most SKETCH_PIECES pieces, at a tolerance of SKETCH_TOLERANCE px or more.
       */
      check(sl, state) {
        const points = decodeStroke(state.stroke, { max: 4000, message: t("sketch.badStroke") });
        const continuity = state.output === "C1" ? "C1" : "G1";
        const fit = sl.fitCurveReport(points, 2, state.tolerance / state.scale, { continuity });
        try {
          const pieces = fit.curve.pieceCount;
          const corners = fit.corners.length;
          const solved =
            fit.closed &&
            corners >= 1 &&
            pieces <= SKETCH_PIECES &&
            state.tolerance >= SKETCH_TOLERANCE;
          const detail = t("exercise.sketch-pieces.detail", {
            pieces: tp("sketch.pieces", pieces),
            corners: tp("sketch.corners", corners),
            shape: t(fit.closed ? "sketch.closed" : "sketch.open"),
          });
          return { solved, detail };
        } finally {
          fit.curve.free();
        }
      },
    },
  ].map(Object.freeze),
);

/** The exercise `id`, or undefined. */
export function findExercise(id) {
  return exercises.find((e) => e.id === id);
}
