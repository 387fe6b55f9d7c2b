// Workloads (j) and (k) of the surfaces issue (14): adaptive against uniform tessellation at the
// same maximum error, and one drag frame of a 16×16 bicubic NURBS patch. Nothing here asserts a
// timing.
//
// (j) a clamped bicubic B-spline surface, 24×24 control points over the unit square, flat but for
//     a bump (4 raised points in the middle): `tessellateAdaptive(tolerance)` against the
//     uniform grid `tessellate(n, n)` with the smallest n whose measured maximum error is at most
//     (1) the adaptive mesh's measured maximum error and (2) the tolerance. Errors are measured
//     densely through the core: at barycentric points of every triangle (interpolated uv → the
//     surface point, against the triangle's point).
// (k) a drag frame of a 16×16 bicubic NURBS patch: `setControlPoint(8, 8, p)` + `tessellate(64,
//     64)` (positions, normals, uvs, indices).
import { rng, SEED } from "./inputs.mjs";

export const ADAPTIVE = { net: 24, tolerance: 1e-3, bump: 0.3, subdivisions: 6 };
export const SURFACE_DRAG = { net: 16, quads: 64, row: 8, col: 8 };

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 ? s[m] : 0.5 * (s[m - 1] + s[m]);
}

/** Clamped uniform knots of degree `p` for `count` points on [0, 1]. */
function clampedKnots(count, p) {
  const spans = count - p;
  const knots = [];
  for (let i = 0; i < count + p + 1; i++) knots.push(Math.min(Math.max(i - p, 0), spans) / spans);
  return knots;
}

/** Greville abscissae of a knot vector. */
function greville(knots, p) {
  const out = [];
  for (let i = 0; i + p + 1 < knots.length; i++) {
    let sum = 0;
    for (let k = 1; k <= p; k++) sum += knots[i + k];
    out.push(sum / p);
  }
  return out;
}

/** The (j) test patch: flat over the unit square (a linear-precision net) but for a bump. */
export function bumpSurface(sl, { net, bump } = ADAPTIVE) {
  const knots = clampedKnots(net, 3);
  const g = greville(knots, 3);
  const points = new Float64Array(3 * net * net);
  const mid = net / 2;
  for (let i = 0; i < net; i++)
    for (let j = 0; j < net; j++) {
      const k = 3 * (i * net + j);
      const raised = (i === mid - 1 || i === mid) && (j === mid - 1 || j === mid);
      points[k] = g[i];
      points[k + 1] = g[j];
      points[k + 2] = raised ? bump : 0;
    }
  return new sl.BSplineSurface(points, net, net, 3, 3, knots, knots);
}

/** Barycentric weights of the points of a triangle subdivided `k` times (corners included). */
function barycentric(k) {
  const out = [];
  for (let a = 0; a <= k; a++)
    for (let b = 0; a + b <= k; b++) out.push([a / k, b / k, (k - a - b) / k]);
  return out;
}

/** The largest |S(uv) − X| over barycentric points of every triangle of `mesh`. */
export function meshError(surface, mesh, k = ADAPTIVE.subdivisions) {
  const { positions, uvs, indices } = mesh;
  const weights = barycentric(k);
  let worst = 0;
  for (let t = 0; t < indices.length; t += 3) {
    const [i, j, l] = [indices[t], indices[t + 1], indices[t + 2]];
    for (const [a, b, c] of weights) {
      const u = a * uvs[2 * i] + b * uvs[2 * j] + c * uvs[2 * l];
      const v = a * uvs[2 * i + 1] + b * uvs[2 * j + 1] + c * uvs[2 * l + 1];
      const s = surface.evaluate(u, v);
      let d2 = 0;
      for (let q = 0; q < 3; q++) {
        const x = a * positions[3 * i + q] + b * positions[3 * j + q] + c * positions[3 * l + q];
        d2 += (s[q] - x) ** 2;
      }
      worst = Math.max(worst, d2);
    }
  }
  return Math.sqrt(worst);
}

/**
 * The maximum error of the uniform mesh `tessellate(n, n)` on [0, 1]², measured on a grid k
 * times finer (one `sampleGrid` call for the fine points and one for the vertices, in f64):
 * quad (a, b) with local (s, t) lies on triangle (00, 10, 11) when s ≥ t, else (00, 11, 01).
 */
export function uniformError(surface, n, k = ADAPTIVE.subdivisions) {
  const coarse = Array.from({ length: n + 1 }, (_, i) => i / n);
  const fine = Array.from({ length: n * k + 1 }, (_, i) => i / (n * k));
  const vertices = surface.sampleGrid(coarse, coarse);
  const points = surface.sampleGrid(fine, fine);
  const m = n * k + 1;
  const vertex = (a, b, q) => vertices[3 * (a * (n + 1) + b) + q];
  let worst = 0;
  for (let x = 0; x < m; x++) {
    const a = Math.min(Math.floor(x / k), n - 1);
    const s = x / k - a;
    for (let y = 0; y < m; y++) {
      const b = Math.min(Math.floor(y / k), n - 1);
      const t = y / k - b;
      let d2 = 0;
      for (let q = 0; q < 3; q++) {
        const p00 = vertex(a, b, q);
        const p10 = vertex(a + 1, b, q);
        const p11 = vertex(a + 1, b + 1, q);
        const p01 = vertex(a, b + 1, q);
        const on =
          s >= t
            ? p00 + s * (p10 - p00) + t * (p11 - p10)
            : p00 + s * (p11 - p01) + t * (p01 - p00);
        d2 += (points[3 * (x * m + y) + q] - on) ** 2;
      }
      worst = Math.max(worst, d2);
    }
  }
  return Math.sqrt(worst);
}

/** The smallest n ≤ 1024 with uniformError(n) ≤ target (binary search; the error falls ~1/n²). */
function smallestUniform(surface, target) {
  let lo = 1;
  let hi = 2;
  while (hi < 1024 && uniformError(surface, hi) > target) {
    lo = hi;
    hi *= 2;
  }
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (uniformError(surface, mid) > target) lo = mid;
    else hi = mid;
  }
  return hi;
}

/** (j): triangle counts of the adaptive mesh and of uniform grids with the same maximum error. */
export function adaptiveBench(sl, { tolerance = ADAPTIVE.tolerance } = {}) {
  const surface = bumpSurface(sl);
  const t0 = performance.now();
  const mesh = surface.tessellateAdaptive(tolerance);
  const adaptiveMs = performance.now() - t0;
  const adaptiveTriangles = mesh.indices.length / 3;
  const adaptiveError = meshError(surface, mesh);
  const nSame = smallestUniform(surface, adaptiveError);
  const nTol = smallestUniform(surface, tolerance);
  surface.free();
  return {
    patch: `clamped bicubic B-spline, ${ADAPTIVE.net}×${ADAPTIVE.net} net, flat with a bump of ${ADAPTIVE.bump}`,
    tolerance,
    adaptiveTriangles,
    adaptiveVertices: mesh.positions.length / 3,
    adaptiveError,
    adaptiveMs,
    uniformSameError: { n: nSame, triangles: 2 * nSame * nSame },
    uniformTolerance: { n: nTol, triangles: 2 * nTol * nTol },
    ratio: adaptiveTriangles / (2 * nSame * nSame),
    ratioAtTolerance: adaptiveTriangles / (2 * nTol * nTol),
  };
}

/**
 * The (k) patch: 16×16 control points over [0, 15]², random heights in [−1, 1] and weights in
 * [0.5, 2] (seeded), clamped uniform knots; `{ surface, points }` (the caller frees the surface).
 */
export function dragPatch(sl) {
  const { net } = SURFACE_DRAG;
  const random = rng(SEED + 14);
  const knots = clampedKnots(net, 3);
  const points = new Float64Array(3 * net * net);
  const weights = new Float64Array(net * net);
  for (let i = 0; i < net; i++)
    for (let j = 0; j < net; j++) {
      const k = i * net + j;
      points.set([i, j, 2 * (random() - 0.5)], 3 * k);
      weights[k] = 0.5 + 1.5 * random();
    }
  return { surface: new sl.BSplineSurface(points, net, net, 3, 3, knots, knots, weights), points };
}

/** (k): drag frames of a 16×16 bicubic NURBS patch; timings in ms. */
export function surfaceDragBench(sl, { frames = 100, warmup = 10 } = {}) {
  const { net, quads, row, col } = SURFACE_DRAG;
  const { surface, points } = dragPatch(sl);
  const k = 3 * (row * net + col);
  const times = [];
  let vertices = 0;
  for (let f = 0; f < warmup + frames; f++) {
    const t0 = performance.now();
    surface.setControlPoint(row, col, [
      points[k],
      points[k + 1],
      points[k + 2] + Math.sin(0.1 * f),
    ]);
    const mesh = surface.tessellate(quads, quads);
    const dt = performance.now() - t0;
    vertices = mesh.positions.length / 3;
    if (f >= warmup) times.push(dt);
  }
  surface.free();
  const sorted = [...times].sort((a, b) => a - b);
  return {
    method: `setControlPoint(${row}, ${col}, p) + tessellate(${quads}, ${quads})`,
    vertices,
    medianMs: median(times),
    p95Ms: sorted[Math.min(sorted.length - 1, Math.floor(0.95 * sorted.length))],
    maxMs: sorted[sorted.length - 1],
    frames: times.length,
  };
}
