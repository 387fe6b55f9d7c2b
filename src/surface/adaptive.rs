//! Adaptive tessellation: a quadtree over the Bézier patches, split until the control net is
//! flat enough, triangulated without cracks.

use super::mesh::fill_missing_normals;
use super::{BSplineSurface, Mesh};
use crate::error::{check_tolerance, Error, Result};

/// Deepest quadtree level below a Bézier patch (a leaf then spans `2^-24` of its patch).
pub const MAX_ADAPTIVE_DEPTH: u32 = 24;

/// Most vertices one [`BSplineSurface::tessellate_adaptive`] makes: ~56 bytes each in the result
/// (position, normal, uv, and about two triangles), so at most ~4 MB — and a work budget: the
/// quadtree reaches the cap in ~0.3 s in Node, so a tolerance too small for the surface fails
/// in a fraction of a second (2^18 took 1.2 s). A uniform 180 × 180 grid fits under it.
pub const MAX_ADAPTIVE_VERTICES: usize = 1 << 16;

/// Lattice steps per Bézier patch side: leaf corners and centres are whole numbers on it.
const LATTICE: u64 = 1 << (MAX_ADAPTIVE_DEPTH + 1);

/// A leaf of the quadtree: lower corner `(u0, v0)` and side `size` on the lattice.
#[derive(Debug, Clone, Copy)]
struct Leaf {
    u0: u64,
    v0: u64,
    size: u64,
}

impl BSplineSurface {
    /// A triangle mesh within `tolerance` (model units) of the surface: every point of every
    /// triangle is within `tolerance` of the surface point at the same (linearly interpolated)
    /// parameters, so within `tolerance` of the surface. Vertices are exact surface points at
    /// their `(u, v)` (kept in [`Mesh::uvs`]) with the normals of [`BSplineSurface::normal`];
    /// triangles are counter-clockwise seen from the side the normals point to.
    ///
    /// **Subdivision.** Each Bézier patch ([`BSplineSurface::to_bezier_patches`]) is a quadtree
    /// root; a node is split at `(½, ½)` (de Casteljau) until `2δ + |D|/4 ≤ tolerance`, with
    /// `δ` and `D` its net's deviation bound and corner twist (`flatness`:
    /// `|S − L| ≤ δ` for the bilinear interpolant `L` of the node's corners).
    ///
    /// **Why that suffices.** A leaf's triangles have their vertices `S(x_k)` at parameters
    /// `x_k` in the leaf; a point of a triangle is `X = Σ λ_k S(x_k)` (`λ_k ≥ 0`, `Σ λ_k = 1`),
    /// at parameters `x = Σ λ_k x_k`. With `E = S − L` and the leaf's local coordinates
    /// `x = (s, t) ∈ [0, 1]²`, `L(s, t) = A + Bs + Ct + D st`, so
    /// `X − S(x) = Σ λ_k E(x_k) − E(x) + D (Σ λ_k s_k t_k − s̄ t̄)`. The first two terms are at
    /// most `δ` each; the last is `D` times the covariance of `(s, t)` under the weights `λ`,
    /// at most `σ_s σ_t ≤ ½ · ½` because `s, t ∈ [0, 1]`. Hence `|X − S(x)| ≤ 2δ + |D|/4`.
    /// (Positions are stored as `f32`: add their rounding, ~`6e-8` of the coordinates.)
    ///
    /// **No cracks.** Leaf corners sit on a dyadic lattice (exact integers per patch); a vertex
    /// is one lattice point, evaluated once, so neighbours share it (one index, one value). A leaf whose
    /// sides carry corners of smaller neighbours (T-junctions) includes them: it is a fan from
    /// its centre over all its boundary vertices in order; otherwise two triangles
    /// `(00, 10, 11)`, `(00, 11, 01)`. Both sides of every leaf edge therefore use the same
    /// vertices along it. A flat patch (a plane with an affine net) gives 2 triangles.
    ///
    /// # Errors
    /// [`Error::InvalidTolerance`] unless `tolerance` is finite and > 0; [`Error::TooLarge`]
    /// for more than [`MAX_ADAPTIVE_VERTICES`] vertices (or patches), or a leaf still not flat
    /// at depth [`MAX_ADAPTIVE_DEPTH`] (a tolerance near rounding).
    pub fn tessellate_adaptive(&self, tolerance: f64) -> Result<Mesh> {
        let tolerance = check_tolerance(tolerance)?;
        let breaks_u = breaks(self.knots_u.as_slice(), self.knots_u.domain());
        let breaks_v = breaks(self.knots_v.as_slice(), self.knots_v.domain());
        let (spans_u, spans_v) = (breaks_u.len() - 1, breaks_v.len() - 1);
        let patches = spans_u.saturating_mul(spans_v);
        if patches > MAX_ADAPTIVE_VERTICES {
            return Err(Error::TooLarge {
                what: "adaptive-vertices-patches",
                value: patches,
                max: MAX_ADAPTIVE_VERTICES,
            });
        }
        let pieces = self.pieces()?;
        let mut leaves = Vec::new();
        let mut stack = Vec::new();
        for (k, piece) in pieces.into_iter().enumerate() {
            let (a, b) = ((k / spans_v) as u64, (k % spans_v) as u64);
            stack.push((piece.patch, a * LATTICE, b * LATTICE, 0u32));
        }
        while let Some((patch, u0, v0, depth)) = stack.pop() {
            let f = patch.flatness();
            let size = LATTICE >> depth;
            if 2.0 * f.deviation + 0.25 * f.twist <= tolerance {
                // Each leaf's lower corner is a vertex of its own: leaves ≤ vertices.
                if leaves.len() >= MAX_ADAPTIVE_VERTICES {
                    return Err(Error::TooLarge {
                        what: "adaptive-vertices-leaves",
                        value: leaves.len() + 1,
                        max: MAX_ADAPTIVE_VERTICES,
                    });
                }
                leaves.push(Leaf { u0, v0, size });
                continue;
            }
            if depth >= MAX_ADAPTIVE_DEPTH {
                return Err(Error::TooLarge {
                    what: "adaptive-depth",
                    value: depth as usize + 1,
                    max: MAX_ADAPTIVE_DEPTH as usize,
                });
            }
            let half = size / 2;
            let [a, b, c, d] = patch.quarters()?;
            stack.push((d, u0 + half, v0 + half, depth + 1));
            stack.push((c, u0 + half, v0, depth + 1));
            stack.push((b, u0, v0 + half, depth + 1));
            stack.push((a, u0, v0, depth + 1));
        }
        let lattice = Lattice { breaks_u, breaks_v };
        self.triangulate(&leaves, &lattice)
    }

    /// The crack-free triangulation of the leaves (see [`BSplineSurface::tessellate_adaptive`]).
    /// The corners, sorted by `(u, v)` and by `(v, u)`, are both the vertex list (a corner's
    /// id is its rank) and the lattice lines: the corners strictly inside a leaf's side are a
    /// binary-searched range. Centres of fans follow the corners.
    fn triangulate(&self, leaves: &[Leaf], lattice: &Lattice) -> Result<Mesh> {
        let mut by_u: Vec<(u64, u64)> = Vec::with_capacity(4 * leaves.len());
        for l in leaves {
            let (u1, v1) = (l.u0 + l.size, l.v0 + l.size);
            by_u.extend_from_slice(&[(l.u0, l.v0), (u1, l.v0), (u1, v1), (l.u0, v1)]);
        }
        by_u.sort_unstable();
        by_u.dedup();
        let mut by_v: Vec<(u64, u64)> = by_u.iter().map(|&(u, v)| (v, u)).collect();
        by_v.sort_unstable();
        if by_u.len() > MAX_ADAPTIVE_VERTICES {
            return Err(Error::TooLarge {
                what: "adaptive-vertices",
                value: by_u.len(),
                max: MAX_ADAPTIVE_VERTICES,
            });
        }
        let mut mesh = MeshBuilder::default();
        for &key in &by_u {
            mesh.push(self, lattice, key)?;
        }
        let id = |key: (u64, u64)| by_u.binary_search(&key).map_or(0, |k| k as u32);
        let mut boundary = Vec::new();
        for l in leaves {
            let (u0, v0, u1, v1) = (l.u0, l.v0, l.u0 + l.size, l.v0 + l.size);
            // Counter-clockwise in (u, v): bottom, right, top, left.
            boundary.clear();
            boundary.push((u0, v0));
            boundary.extend(inside(&by_v, v0, u0, u1).map(|u| (u, v0)));
            boundary.push((u1, v0));
            boundary.extend(inside(&by_u, u1, v0, v1).map(|v| (u1, v)));
            boundary.push((u1, v1));
            boundary.extend(inside(&by_v, v1, u0, u1).rev().map(|u| (u, v1)));
            boundary.push((u0, v1));
            boundary.extend(inside(&by_u, u0, v0, v1).rev().map(|v| (u0, v)));
            if let [a, b, c, d] = boundary[..] {
                let [a, b, c, d] = [id(a), id(b), id(c), id(d)];
                mesh.indices.extend_from_slice(&[a, b, c, a, c, d]);
                continue;
            }
            let centre = mesh.push(self, lattice, (u0 + l.size / 2, v0 + l.size / 2))?;
            for (k, &a) in boundary.iter().enumerate() {
                let b = boundary
                    .get(k + 1)
                    .or(boundary.first())
                    .copied()
                    .unwrap_or(a);
                mesh.indices.extend_from_slice(&[centre, id(a), id(b)]);
            }
        }
        fill_missing_normals(
            &mesh.points,
            &mut mesh.normals,
            &mesh.indices,
            &mesh.missing,
        );
        Ok(Mesh {
            positions: mesh.points.iter().map(|&x| x as f32).collect(),
            normals: mesh.normals.iter().map(|&x| x as f32).collect(),
            uvs: mesh.uvs,
            indices: mesh.indices,
        })
    }
}

/// The second coordinates strictly inside `(a, b)` of the points `(at, ·)` of `sorted`, in order.
fn inside(
    sorted: &[(u64, u64)],
    at: u64,
    a: u64,
    b: u64,
) -> impl DoubleEndedIterator<Item = u64> + '_ {
    let from = sorted.partition_point(|&x| x <= (at, a));
    let to = sorted.partition_point(|&x| x < (at, b));
    sorted.get(from..to).unwrap_or(&[]).iter().map(|&(_, y)| y)
}

/// The distinct knots in the domain `[a, b]`, ends included: the patch boundaries.
fn breaks(knots: &[f64], (a, b): (f64, f64)) -> Vec<f64> {
    let mut out: Vec<f64> = knots
        .iter()
        .copied()
        .filter(|t| (a..=b).contains(t))
        .collect();
    out.dedup();
    out
}

/// Lattice coordinates to parameters: patch `k` of a direction covers `[breaks[k],
/// breaks[k + 1]]` with `LATTICE` steps.
struct Lattice {
    breaks_u: Vec<f64>,
    breaks_v: Vec<f64>,
}

/// The parameter of lattice coordinate `x` (one way only: a patch's end is the next patch's
/// start, and the last patch's end is the domain's end, exactly).
fn parameter(breaks: &[f64], x: u64) -> f64 {
    let last = breaks.len().saturating_sub(2) as u64;
    let k = (x / LATTICE).min(last);
    let step = x - k * LATTICE;
    let (Some(&a), Some(&b)) = (breaks.get(k as usize), breaks.get(k as usize + 1)) else {
        return 0.0;
    };
    match step {
        0 => a,
        LATTICE => b,
        _ => a + (b - a) * (step as f64 / LATTICE as f64),
    }
}

/// The vertices (one per lattice point) and triangles being built.
#[derive(Default)]
struct MeshBuilder {
    points: Vec<f64>,
    normals: Vec<f64>,
    uvs: Vec<f32>,
    missing: Vec<usize>,
    indices: Vec<u32>,
}

impl MeshBuilder {
    /// A new vertex at lattice point `key`, evaluated on the surface; its index.
    fn push(
        &mut self,
        surface: &BSplineSurface,
        lattice: &Lattice,
        key: (u64, u64),
    ) -> Result<u32> {
        let k = self.uvs.len() / 2;
        if k >= MAX_ADAPTIVE_VERTICES {
            return Err(Error::TooLarge {
                what: "adaptive-vertices",
                value: k + 1,
                max: MAX_ADAPTIVE_VERTICES,
            });
        }
        let (u, v) = (
            parameter(&lattice.breaks_u, key.0),
            parameter(&lattice.breaks_v, key.1),
        );
        let point = surface.evaluate(u, v)?;
        let normal = surface.normal(u, v).unwrap_or_else(|_| {
            self.missing.push(k);
            glam::DVec3::ZERO
        });
        self.points.extend(point.to_array());
        self.normals.extend(normal.to_array());
        self.uvs.extend_from_slice(&[u as f32, v as f32]);
        Ok(k as u32)
    }
}
