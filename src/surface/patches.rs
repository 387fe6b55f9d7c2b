//! Bézier extraction (a B-spline surface as one Bézier patch per span pair), the measured
//! continuity across its seams, and the flatness bound of a Bézier net that the adaptive
//! tessellation and the line intersection subdivide by.

use super::BSplineSurface;
use crate::bspline::KnotVector;
use crate::error::Result;
use glam::{DVec3, DVec4};

/// Relative tolerance of [`BSplineSurface::seams`]: derivatives `a`, `b` are equal when
/// `|a − b| ≤ 1e-9 (1 + max(|a|, |b|))` (as the curves' continuity check).
pub const SEAM_TOLERANCE: f64 = 1e-9;

/// Points per neighbouring patch pair at which [`BSplineSurface::seams`] compares derivatives:
/// equally spaced along the seam, ends included.
const SEAM_SAMPLES: usize = 5;

/// One Bézier patch of a surface with the rectangle of the surface's domain it covers.
#[derive(Debug, Clone)]
pub(super) struct Piece {
    /// The patch, on `[0, 1]²`.
    pub(super) patch: BSplineSurface,
    /// Its u interval in the parent's domain.
    pub(super) u: (f64, f64),
    /// Its v interval in the parent's domain.
    pub(super) v: (f64, f64),
}

/// How far a Bézier net is from its corners' bilinear interpolant, see [`BSplineSurface::flatness`].
#[derive(Debug, Clone, Copy)]
pub(super) struct Flatness {
    /// `δ`: a bound on `|S(u, v) − L(u, v)|` over `[0, 1]²`.
    pub(super) deviation: f64,
    /// `|D|`, the twist of the corners `D = P_00 − P_m0 − P_0n + P_mn`.
    pub(super) twist: f64,
}

/// The clamped Bézier knot vector of `count` points: `0 … 0 1 … 1` (`count` of each).
fn bezier_knots(count: usize) -> Result<KnotVector> {
    let knots = (0..2 * count)
        .map(|i| if i < count { 0.0 } else { 1.0 })
        .collect();
    KnotVector::new(knots, count.saturating_sub(1), count)
}

impl BSplineSurface {
    /// The same surface with every distinct knot of the domain (ends included) raised to
    /// multiplicity `p` in u and `q` in v, so the `(p + 1)(q + 1)` active control points of
    /// each non-empty span pair are that span's Bézier net (NURBS Book §5.4): one refinement
    /// (A5.4) per direction, not one insertion per knot.
    fn extracted(&self) -> Result<Self> {
        self.refined_u(&self.knots_u.extraction_knots())?
            .refined_v(&self.knots_v.extraction_knots())
    }

    /// The Bézier patches with their rectangles, u spans outer; see
    /// [`BSplineSurface::to_bezier_patches`].
    pub(super) fn pieces(&self) -> Result<Vec<Piece>> {
        let e = self.extracted()?;
        let (p, q) = (e.degree_u(), e.degree_v());
        let (ku, kv) = (bezier_knots(p + 1)?, bezier_knots(q + 1)?);
        let knots_u = e.knots_u.as_slice();
        let knots_v = e.knots_v.as_slice();
        let mut pieces = Vec::new();
        for su in e.knots_u.spans() {
            for sv in e.knots_v.spans() {
                let mut net = Vec::with_capacity((p + 1) * (q + 1));
                for i in su - p..=su {
                    let row = i * e.cols;
                    net.extend_from_slice(e.net.get(row + sv - q..=row + sv).unwrap_or(&[]));
                }
                let patch = BSplineSurface {
                    net,
                    rows: p + 1,
                    cols: q + 1,
                    rational: self.rational,
                    knots_u: ku.clone(),
                    knots_v: kv.clone(),
                };
                pieces.push(Piece {
                    patch,
                    u: (knots_u[su], knots_u[su + 1]),
                    v: (knots_v[sv], knots_v[sv + 1]),
                });
            }
        }
        Ok(pieces)
    }

    /// One Bézier patch (on `[0, 1]²`) per non-empty span pair `[u_k, u_{k+1}] × [v_l, v_{l+1}]`,
    /// u spans outer: patch `a·(spans in v) + b` covers the a-th u span and the b-th v span, and
    /// `patch(s, t) = S(u_k + s (u_{k+1} − u_k), v_l + t (v_{l+1} − v_l))`. By knot insertion
    /// of every knot to multiplicity `p` (u) and `q` (v); rational surfaces give rational patches.
    ///
    /// # Errors
    /// None in practice (the insertions are valid by construction); a knot-vector error would
    /// be passed on.
    pub fn to_bezier_patches(&self) -> Result<Vec<Self>> {
        Ok(self.pieces()?.into_iter().map(|p| p.patch).collect())
    }

    /// The measured parametric continuity across every distinct interior knot: `(u_seams,
    /// v_seams)`, each a list of `(knot, c)` in knot order. `c` is the largest `k ≤ p` (`q` for
    /// v) such that the derivatives `∂^j S/∂u^j` (`∂v^j`), `j = 0..=k`, of the two neighbouring
    /// Bézier patches agree at [`SEAM_SAMPLES`] points along the seam on every span of the
    /// other direction, to [`SEAM_TOLERANCE`] relative (derivatives with respect to the
    /// global parameter: a patch's `j`-th derivative divided by its span length to the `j`);
    /// `−1` where even the points differ (a gap, e.g. a knot of multiplicity `p + 1` with
    /// different rows on either side). Measured, not read from the multiplicity: a knot of
    /// multiplicity `r` gives at least `p − r`, more when the net happens to be smoother.
    /// A Bézier patch has no interior knots: two empty lists.
    ///
    /// # Errors
    /// None in practice (as [`BSplineSurface::to_bezier_patches`]).
    #[allow(clippy::type_complexity)]
    pub fn seams(&self) -> Result<(Vec<(f64, i32)>, Vec<(f64, i32)>)> {
        let pieces = self.pieces()?;
        let spans_v = self.knots_v.spans().count().max(1);
        let grid: Vec<&[Piece]> = pieces.chunks(spans_v).collect();
        let mut u_seams = Vec::new();
        for pair in grid.windows(2) {
            let (left, right) = (pair[0], pair[1]);
            let t = left.first().map_or(0.0, |p| p.u.1);
            let mut c = self.degree_u() as i32;
            for (l, r) in left.iter().zip(right) {
                c = c.min(seam_continuity(l, r, true)?);
            }
            u_seams.push((t, c));
        }
        let mut v_seams = Vec::new();
        for b in 1..spans_v {
            let t = grid
                .first()
                .and_then(|row| row.get(b))
                .map_or(0.0, |p| p.v.0);
            let mut c = self.degree_v() as i32;
            for row in &grid {
                if let (Some(l), Some(r)) = (row.get(b - 1), row.get(b)) {
                    c = c.min(seam_continuity(l, r, false)?);
                }
            }
            v_seams.push((t, c));
        }
        Ok((u_seams, v_seams))
    }

    /// The flatness of a Bézier patch (knots `0 … 0 1 … 1`): how far it is from the bilinear
    /// interpolant `L` of its corners `P_00, P_m0, P_0n, P_mn`.
    ///
    /// **Deviation.** With the homogeneous net `H_ij = (w_ij P_ij, w_ij)`, `S = H/w` and
    /// `S − L = (H − wL)/w`. `H − wL` is a polynomial of degree `(m + 1, n + 1)`; its Bernstein
    /// coefficients follow from degree elevation of `H` and the Bernstein product of `w`
    /// (degree `(m, n)`) with `L` (degree `(1, 1)`, coefficients the corners `C_ef`):
    /// `G_ab = Σ_{i+e=a} Σ_{j+f=b} α_{a,i} β_{b,j} w_ij (P_ij − C_ef)` with `α_{a,a} =
    /// (m + 1 − a)/(m + 1)`, `α_{a,a−1} = a/(m + 1)` (likewise `β` with `n`). Bernstein
    /// polynomials are ≥ 0 and sum to 1, and `w ≥ min w_ij`, so
    /// `|S(u, v) − L(u, v)| ≤ δ = max |G_ab| / min w_ij` everywhere on `[0, 1]²`. (Polynomial
    /// patches: `w ≡ 1`, and `G` is the degree-elevated net of `P_ij − L(i/m, j/n)`.)
    ///
    /// **Twist.** `L(u, v) = P_00 + u(P_m0 − P_00) + v(P_0n − P_00) + uv D` with
    /// `D = P_00 − P_m0 − P_0n + P_mn`.
    pub(super) fn flatness(&self) -> Flatness {
        let (m, n) = (self.rows - 1, self.cols - 1);
        let point = |i: usize, j: usize| {
            self.net
                .get(i * self.cols + j)
                .map_or(DVec3::ZERO, |h| h.truncate() / h.w)
        };
        let corners = [[point(0, 0), point(0, n)], [point(m, 0), point(m, n)]];
        let twist = (corners[0][0] - corners[1][0] - corners[0][1] + corners[1][1]).length();
        let min_w = self.net.iter().map(|h| h.w).fold(f64::INFINITY, f64::min);
        let elevate = |a: usize, i: usize, m: usize| {
            if i == a {
                (m + 1 - a) as f64 / (m + 1) as f64
            } else {
                a as f64 / (m + 1) as f64
            }
        };
        let mut worst: f64 = 0.0;
        for a in 0..=m + 1 {
            for b in 0..=n + 1 {
                let mut g = DVec3::ZERO;
                for (e, ce) in corners.iter().enumerate() {
                    let Some(i) = a.checked_sub(e).filter(|&i| i <= m) else {
                        continue;
                    };
                    for (f, c) in ce.iter().enumerate() {
                        let Some(j) = b.checked_sub(f).filter(|&j| j <= n) else {
                            continue;
                        };
                        let h = self
                            .net
                            .get(i * self.cols + j)
                            .copied()
                            .unwrap_or(DVec4::ZERO);
                        g += elevate(a, i, m) * elevate(b, j, n) * (h.truncate() - h.w * *c);
                    }
                }
                worst = worst.max(g.length());
            }
        }
        Flatness {
            deviation: worst / min_w,
            twist,
        }
    }

    /// The four quarters of a Bézier patch split at `(½, ½)`: `[low u & low v, low u & high v,
    /// high u & low v, high u & high v]`.
    pub(super) fn quarters(&self) -> Result<[Self; 4]> {
        self.split_bezier(0.5, 0.5)
    }
}

/// The continuity across the seam between Bézier pieces `left` and `right` (neighbours in u
/// when `along_u`, else in v): see [`BSplineSurface::seams`].
fn seam_continuity(left: &Piece, right: &Piece, along_u: bool) -> Result<i32> {
    let same = |a: DVec3, b: DVec3| {
        (a - b).length() <= SEAM_TOLERANCE * (1.0 + a.length().max(b.length()))
    };
    let (degree, hl, hr) = if along_u {
        (
            left.patch.degree_u(),
            left.u.1 - left.u.0,
            right.u.1 - right.u.0,
        )
    } else {
        (
            left.patch.degree_v(),
            left.v.1 - left.v.0,
            right.v.1 - right.v.0,
        )
    };
    let mut c = -1;
    for k in 0..=degree {
        for s in 0..SEAM_SAMPLES {
            let t = s as f64 / (SEAM_SAMPLES - 1) as f64;
            let (dl, dr) = if along_u {
                (
                    left.patch.derivative(1.0, t, k, 0)?,
                    right.patch.derivative(0.0, t, k, 0)?,
                )
            } else {
                (
                    left.patch.derivative(t, 1.0, 0, k)?,
                    right.patch.derivative(t, 0.0, 0, k)?,
                )
            };
            let scale = |h: f64| h.powi(-(k as i32));
            if !same(dl * scale(hl), dr * scale(hr)) {
                return Ok(c);
            }
        }
        c = k as i32;
    }
    Ok(c)
}
