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

/**
 * True when a triangle of `mesh` (`{ positions, indices }`, flat xyz and index triples) meets
 * the segment from eye (ex, ey, ez) to point (px, py, pz) more than `margin` before the point.
 */
export function segmentBlocked(mesh, ex, ey, ez, px, py, pz, margin) {
  const p = mesh.positions;
  const idx = mesh.indices;
  const dx = px - ex;
  const dy = py - ey;
  const dz = pz - ez;
  const length = Math.hypot(dx, dy, dz);
  if (length <= margin) return false;
  const sMax = 1 - margin / length;
  const parallel2 = PARALLEL * PARALLEL * length * length;
  for (let t = 0; t + 2 < idx.length; t += 3) {
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
