// Workload (g): one drag frame of a 1000-point NURBS, as the playground does it. Shared by the
// Node harness and the browser page so both time exactly the same code.
//
// A frame = move control point i (setControlPoint), resample the curve at 4000 equally spaced u,
// and the basis strip: 200 u equally spaced over the support [u_i, u_{i+p+1}] of the dragged
// point's basis function, every basis function at each. splinelab draws the strip three ways:
// span(u) + basisNonZero(u) (the p + 1 non-zero values, as the baseline computes them), basis(u)
// (all n + 1 values), and one basisCurves(200) call (all 1000 functions over the whole domain).
import { bspline, uniformParams } from "./inputs.mjs";
import { basisStrip, deBoorSample, prepareBSpline } from "./baseline.mjs";

export const DRAG = { points: 1000, samples: 4000, strip: 200, index: 500 };

function quantile(sorted, q) {
  return sorted[Math.min(sorted.length - 1, Math.floor(q * sorted.length))];
}

function stats(times) {
  const s = [...times].sort((a, b) => a - b);
  return {
    medianMs: quantile(s, 0.5),
    p95Ms: quantile(s, 0.95),
    maxMs: s[s.length - 1],
    frames: s.length,
  };
}

/** Runs `frames` drag frames per contender, interleaved; returns timings (ms) and agreement. */
export function dragBench(sl, { frames = 100, warmup = 10 } = {}) {
  const input = bspline(DRAG.points, 3, true);
  const { degree: p, knots } = input;
  const i = DRAG.index;
  const x0 = input.points[2 * i];
  const y0 = input.points[2 * i + 1];
  const position = (f) => [x0 + 3 * Math.cos(0.1 * f), y0 + 3 * Math.sin(0.1 * f)];
  const stripUs = uniformParams(knots[i], knots[i + p + 1], DRAG.strip);

  const curve = new sl.BSplineCurve(input.points, 2, p, knots, input.weights);
  const curve2 = new sl.BSplineCurve(input.points, 2, p, knots, input.weights);
  let slPoints = null;
  const slStrip = [];
  const splinelab = (f) => {
    curve.setControlPoint(i, position(f));
    slPoints = curve.sampleUniform(DRAG.samples);
    for (let s = 0; s < DRAG.strip; s++) slStrip[s] = curve.basis(stripUs[s]);
  };
  const curve3 = new sl.BSplineCurve(input.points, 2, p, knots, input.weights);
  const nonZeroStrip = [];
  const nonZeroSpans = new Int32Array(DRAG.strip);
  const splinelabNonZero = (f) => {
    curve3.setControlPoint(i, position(f));
    curve3.sampleUniform(DRAG.samples);
    for (let s = 0; s < DRAG.strip; s++) {
      nonZeroSpans[s] = curve3.span(stripUs[s]);
      nonZeroStrip[s] = curve3.basisNonZero(stripUs[s]);
    }
  };
  const splinelabCurves = (f) => {
    curve2.setControlPoint(i, position(f));
    curve2.sampleUniform(DRAG.samples);
    curve2.basisCurves(DRAG.strip);
  };

  // The baseline keeps its buffers across frames (made once per size change, as the app does).
  const base = prepareBSpline(input);
  const sampleUs = uniformParams(knots[p], knots[knots.length - 1 - p], DRAG.samples);
  const basePoints = new Float64Array(2 * DRAG.samples);
  const baseStrip = new Float64Array(DRAG.strip * (p + 1));
  const baseSpans = new Int32Array(DRAG.strip);
  const w = input.weights[i];
  const baseline = (f) => {
    const [x, y] = position(f);
    base.cw[3 * i] = w * x;
    base.cw[3 * i + 1] = w * y;
    deBoorSample(base, sampleUs, basePoints);
    basisStrip(base, stripUs, baseStrip, baseSpans);
  };

  const contenders = [
    {
      lib: "splinelab",
      method: "setControlPoint + sampleUniform(4000) + 200× span(u), basisNonZero(u)",
      run: splinelabNonZero,
      times: [],
    },
    {
      lib: "splinelab",
      method: "setControlPoint + sampleUniform(4000) + 200× basis(u)",
      run: splinelab,
      times: [],
    },
    {
      lib: "splinelab",
      method: "setControlPoint + sampleUniform(4000) + basisCurves(200)",
      run: splinelabCurves,
      times: [],
    },
    {
      lib: "js-baseline",
      method: "in-place point + de Boor ×4000 + 200× A2.2 basis",
      run: baseline,
      times: [],
    },
  ];
  for (let f = 0; f < warmup + frames; f++) {
    for (let c = 0; c < contenders.length; c++) {
      const contender = contenders[(c + f) % contenders.length];
      const t0 = performance.now();
      contender.run(f);
      const dt = performance.now() - t0;
      if (f >= warmup) contender.times.push(dt);
    }
  }

  // Agreement after the last frame: curve points and the non-zero strip values.
  let pointDiff = 0;
  for (let k = 0; k < basePoints.length; k++)
    pointDiff = Math.max(pointDiff, Math.abs(basePoints[k] - slPoints[k]));
  let basisDiff = 0;
  for (let s = 0; s < DRAG.strip; s++) {
    for (let j = 0; j <= p; j++) {
      const v = slStrip[s][baseSpans[s] - p + j];
      basisDiff = Math.max(basisDiff, Math.abs(v - baseStrip[s * (p + 1) + j]));
      // The sparse call: the same span (else Infinity) and the same p + 1 values.
      const sparse = Math.abs(nonZeroStrip[s][j] - baseStrip[s * (p + 1) + j]);
      basisDiff = Math.max(basisDiff, nonZeroSpans[s] === baseSpans[s] ? sparse : Infinity);
    }
  }
  curve.free();
  curve2.free();
  curve3.free();
  return {
    contenders: contenders.map(({ lib, method, times }) => ({ lib, method, ...stats(times) })),
    agreement: { pointMaxDiff: pointDiff, basisMaxDiff: basisDiff },
  };
}
