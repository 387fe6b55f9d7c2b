/**
 * Is a point hidden behind a surface? Drawing and picking support of the 3D handles
 * (handles3d.js): the segment from the eye E to the point P against every triangle of the shown
 * meshes (the arrays WebGL draws: what the reader sees, not the exact surface).
 *
 * Möller–Trumbore: for the triangle (A, B, C) with edges e1 = B − A, e2 = C − A and the segment
 * E + s·d, d = P − E, s ∈ [0, 1]: with q = d × e2, det = e1·q (≈ 0: the segment runs parallel
 * to the plane), the barycentric coordinates are β = (E − A)·q / det, γ = d·((E − A) × e1) / det
 * and s = e2·((E − A) × e1) / det. The segment is blocked when β ≥ 0, γ ≥ 0, β + γ ≤ 1 and the hit
 * lies strictly before P: s·|d| < |d| − `margin` (world units; a point on the surface, a corner
 * of a patch, does not hide itself).
 */

/** Determinants below this (relative to |d|·|e1|·|e2|) count as parallel. */
const PARALLEL = 1e-12;

/** Triangles per culling box: consecutive in index order (a tessellation's grid rows). */
export const OCCLUSION_BLOCK = 64;

/**
 * The axis-aligned boxes of every OCCLUSION_BLOCK consecutive triangles of `mesh`, flat
 * `[xmin, ymin, zmin, xmax, ymax, zmax, …]`, each padded by a millionth of its size and place
 * (a box may only be too large: the culling then costs time, never a hit). Made once per frame
 * and shared by every handle's test (View3D#occluded).
 */
export function triangleBlocks(mesh) {
  const p = mesh.positions;
  const idx = mesh.indices;
  const triangles = Math.floor(idx.length / 3);
  const count = Math.ceil(triangles / OCCLUSION_BLOCK);
  const boxes = new Float64Array(6 * count);
  for (let b = 0; b < count; b++) {
    let x0 = Number.POSITIVE_INFINITY;
    let y0 = x0;
    let z0 = x0;
    let x1 = Number.NEGATIVE_INFINITY;
    let y1 = x1;
    let z1 = x1;
    const end = 3 * Math.min(triangles, (b + 1) * OCCLUSION_BLOCK);
    for (let t = 3 * b * OCCLUSION_BLOCK; t < end; t++) {
      const v = 3 * idx[t];
      const x = p[v];
      const y = p[v + 1];
      const z = p[v + 2];
      if (x < x0) x0 = x;
      if (x > x1) x1 = x;
      if (y < y0) y0 = y;
      if (y > y1) y1 = y;
      if (z < z0) z0 = z;
      if (z > z1) z1 = z;
    }
    const pad =
      1e-6 *
      (Math.max(x1 - x0, y1 - y0, z1 - z0) +
        Math.max(
          Math.abs(x0),
          Math.abs(x1),
          Math.abs(y0),
          Math.abs(y1),
          Math.abs(z0),
          Math.abs(z1),
        ));
    const k = 6 * b;
    boxes[k] = x0 - pad;
    boxes[k + 1] = y0 - pad;
    boxes[k + 2] = z0 - pad;
    boxes[k + 3] = x1 + pad;
    boxes[k + 4] = y1 + pad;
    boxes[k + 5] = z1 + pad;
  }
  return boxes;
}

/** Does the segment E + s·d, s ∈ [0, 1], meet box k of `boxes` (slabs, closed)? */
function segmentMeetsBox(e, d, boxes, k) {
  let lo = 0;
  let hi = 1;
  for (let a = 0; a < 3; a++) {
    const min = boxes[k + a];
    const max = boxes[k + 3 + a];
    if (d[a] === 0) {
      if (e[a] < min || e[a] > max) return false;
      continue;
    }
    let s0 = (min - e[a]) / d[a];
    let s1 = (max - e[a]) / d[a];
    if (s0 > s1) [s0, s1] = [s1, s0];
    if (s0 > lo) lo = s0;
    if (s1 < hi) hi = s1;
    if (lo > hi) return false;
  }
  return true;
}

/**
 * True when a triangle of `mesh` (`{ positions, indices }`, flat xyz and index triples) meets
 * the segment from eye (ex, ey, ez) to point (px, py, pz) more than `margin` before the point.
 * With `blocks` (`triangleBlocks(mesh)`), only the triangles of boxes the segment meets are tried.
 */
export function segmentBlocked(mesh, ex, ey, ez, px, py, pz, margin, blocks = null) {
  const dx = px - ex;
  const dy = py - ey;
  const dz = pz - ez;
  const length = Math.hypot(dx, dy, dz);
  if (length <= margin) return false;
  const triangles = Math.floor(mesh.indices.length / 3);
  const eye = [ex, ey, ez];
  const d = [dx, dy, dz];
  if (!blocks) return rangeBlocked(mesh, 0, triangles, eye, d, length, margin);
  for (let b = 0; 6 * b < blocks.length; b++) {
    if (!segmentMeetsBox(eye, d, blocks, 6 * b)) continue;
    const end = Math.min(triangles, (b + 1) * OCCLUSION_BLOCK);
    if (rangeBlocked(mesh, b * OCCLUSION_BLOCK, end, eye, d, length, margin)) return true;
  }
  return false;
}

/** The Möller–Trumbore test of the header over triangles [from, to) of `mesh`. */
function rangeBlocked(mesh, from, to, [ex, ey, ez], [dx, dy, dz], length, margin) {
  const p = mesh.positions;
  const idx = mesh.indices;
  const sMax = 1 - margin / length;
  const parallel2 = PARALLEL * PARALLEL * length * length;
  for (let t = 3 * from; t < 3 * to; t += 3) {
    const a = 3 * idx[t];
    const b = 3 * idx[t + 1];
    const c = 3 * idx[t + 2];
    const ax = p[a];
    const ay = p[a + 1];
    const az = p[a + 2];
    const e1x = p[b] - ax;
    const e1y = p[b + 1] - ay;
    const e1z = p[b + 2] - az;
    const e2x = p[c] - ax;
    const e2y = p[c + 1] - ay;
    const e2z = p[c + 2] - az;
    const qx = dy * e2z - dz * e2y;
    const qy = dz * e2x - dx * e2z;
    const qz = dx * e2y - dy * e2x;
    const det = e1x * qx + e1y * qy + e1z * qz;
    // |det| ≤ PARALLEL·|d|·|e1|·|e2|, squared: no square roots in the loop (Math.hypot twice per
    // triangle was most of a drag frame's time).
    const e1 = e1x * e1x + e1y * e1y + e1z * e1z;
    const e2 = e2x * e2x + e2y * e2y + e2z * e2z;
    if (det * det <= parallel2 * e1 * e2) continue;
    const inv = 1 / det;
    const tx = ex - ax;
    const ty = ey - ay;
    const tz = ez - az;
    const beta = (tx * qx + ty * qy + tz * qz) * inv;
    if (beta < 0 || beta > 1) continue;
    const rx = ty * e1z - tz * e1y;
    const ry = tz * e1x - tx * e1z;
    const rz = tx * e1y - ty * e1x;
    const gamma = (dx * rx + dy * ry + dz * rz) * inv;
    if (gamma < 0 || beta + gamma > 1) continue;
    const s = (e2x * rx + e2y * ry + e2z * rz) * inv;
    if (s > 0 && s < sMax) return true;
  }
  return false;
}
