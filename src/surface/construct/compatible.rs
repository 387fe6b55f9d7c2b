//! Making two B-spline curves compatible (NURBS Book §10.3): same degree, same domain, same
//! knot vector, so their control points can be paired into the rows of one net.

use crate::bspline::BSplineCurve;
use crate::error::Result;
use crate::interp::global::Setup;
use crate::interp::InterpolationOptions;
use crate::prelude::*;
use glam::{DVec3, DVec4};

/// `curve` with clamped knots (`p + 1` copies of each end of the domain) on `[0, 1]`: the
/// domain ends are inserted up to multiplicity `p` (Boehm), the knots and control points that
/// act only outside the domain are dropped, and the knots are mapped by `(u − a)/(b − a)`
/// (which does not change the points).
pub(super) fn clamped_unit(curve: &BSplineCurve<DVec3>) -> Result<BSplineCurve<DVec3>> {
    let p = curve.degree();
    let (a, b) = curve.domain();
    let mut c = curve.clone();
    for end in [a, b] {
        let have = c.knots().multiplicity(end);
        if have < p {
            c = c.insert_knot(end, p - have)?;
        }
    }
    let knots = c.knots().as_slice();
    let first = knots.iter().position(|&k| k == a).unwrap_or(0);
    let last = knots
        .iter()
        .rposition(|&k| k == b)
        .unwrap_or(knots.len() - 1);
    // With p copies of a at first.., the knot before them is replaced by a (p + 1 copies).
    let start = if c.knots().multiplicity(a) > p {
        first
    } else {
        first - 1
    };
    let end = if c.knots().multiplicity(b) > p {
        last
    } else {
        last + 1
    };
    let mut new_knots: Vec<f64> = knots[start..=end].to_vec();
    let count = new_knots.len() - p - 1;
    let h: Vec<DVec4> = c.homogeneous_points()[start..start + count].to_vec();
    let len = new_knots.len();
    for (i, k) in new_knots.iter_mut().enumerate() {
        *k = if i <= p {
            0.0
        } else if i >= len - p - 1 {
            1.0
        } else {
            (*k - a) / (b - a)
        };
    }
    from_homogeneous(h, p, new_knots, curve.is_rational())
}

/// A curve of homogeneous points, degree and knots.
fn from_homogeneous(
    h: Vec<DVec4>,
    degree: usize,
    knots: Vec<f64>,
    rational: bool,
) -> Result<BSplineCurve<DVec3>> {
    let points = h.iter().map(|h| h.truncate() / h.w).collect();
    let weights: Vec<f64> = h.iter().map(|h| h.w).collect();
    BSplineCurve::new(points, degree, knots, rational.then_some(&weights[..]))
}

/// The same (clamped) curve raised from degree `p` to `degree`: every distinct knot gains
/// `degree − p` copies, and the control points are those of the unique spline of the new
/// degree on those knots through the curve's own points at the Greville abscissae
/// `τ_i = (u_{i+1} + … + u_{i+p'})/p'` (the global interpolation of `crate::interp::global`
/// on the homogeneous points). The curve lies in that larger spline space, so interpolation
/// reproduces it exactly, up to rounding.
///
/// A curve with breaks (interior knots of multiplicity `p + 1`, where the Greville abscissae
/// would repeat) is elevated piece by piece between them and joined again.
pub(super) fn elevated(curve: &BSplineCurve<DVec3>, degree: usize) -> Result<BSplineCurve<DVec3>> {
    let p = curve.degree();
    if degree <= p {
        return Ok(curve.clone());
    }
    let knots = curve.knots().as_slice();
    // The first break: p + 1 equal knots u_s … u_{s+p} strictly inside the domain.
    let (a, b) = curve.domain();
    let split = (1..knots.len().saturating_sub(p + 1)).find(|&s| {
        knots[s] > a && knots[s] < b && knots[s + p] == knots[s] && knots[s - 1] < knots[s]
    });
    if let Some(s) = split {
        // Left: knots u_0 … u_{s+p}, points P_0 … P_{s−1}; right: u_s …, points P_s ….
        let h = curve.homogeneous_points();
        let rational = curve.is_rational();
        let left = from_homogeneous(h[..s].to_vec(), p, knots[..=s + p].to_vec(), rational)?;
        let right = from_homogeneous(h[s..].to_vec(), p, knots[s..].to_vec(), rational)?;
        let (left, right) = (elevated(&left, degree)?, elevated(&right, degree)?);
        let mut joined_knots = left.knots().as_slice().to_vec();
        joined_knots.extend_from_slice(&right.knots().as_slice()[degree + 1..]);
        let mut joined = left.homogeneous_points().to_vec();
        joined.extend_from_slice(right.homogeneous_points());
        return from_homogeneous(joined, degree, joined_knots, rational);
    }
    let t = degree - p;
    let mut knots = Vec::new();
    for run in curve.knots().as_slice().chunk_by(|x, y| x == y) {
        knots.extend(std::iter::repeat_n(run[0], run.len() + t));
    }
    let count = knots.len() - degree - 1;
    let params: Vec<f64> = (0..count)
        .map(|i| knots[i + 1..=i + degree].iter().sum::<f64>() / degree as f64)
        .collect();
    let mut data = Vec::with_capacity(4 * count);
    for &tau in &params {
        let h = homogeneous_at(curve, tau)?;
        data.extend(h.to_array());
    }
    let options = InterpolationOptions {
        knots: Some(knots.clone()),
        ..Default::default()
    };
    let solution = Setup::new_flat(&data, 4, degree, &params, &options)?.solve()?;
    let h = solution
        .chunks_exact(4)
        .map(|c| DVec4::new(c[0], c[1], c[2], c[3]))
        .collect();
    from_homogeneous(h, degree, knots, curve.is_rational())
}

/// The homogeneous point `Σ N_{i,p}(t) (w_i P_i, w_i)` of a curve.
fn homogeneous_at(curve: &BSplineCurve<DVec3>, t: f64) -> Result<DVec4> {
    let (k, local) = curve.basis_non_zero(t)?;
    let first = k - curve.degree();
    let h = &curve.homogeneous_points()[first..first + local.len()];
    Ok(h.iter().zip(&local).map(|(&h, &n)| h * n).sum())
}

/// Both curves refined to one knot vector: every distinct knot gets the larger of its two
/// multiplicities (knot refinement, A5.4, inserts what each lacks). Both must be clamped on
/// the same domain with the same degree.
pub(super) fn merged(
    a: &BSplineCurve<DVec3>,
    b: &BSplineCurve<DVec3>,
) -> Result<(BSplineCurve<DVec3>, BSplineCurve<DVec3>)> {
    let missing = |from: &BSplineCurve<DVec3>, into: &BSplineCurve<DVec3>| -> Vec<f64> {
        let mut out = Vec::new();
        for run in from.knots().as_slice().chunk_by(|x, y| x == y) {
            let have = into.knots().multiplicity(run[0]);
            out.extend(std::iter::repeat_n(run[0], run.len().saturating_sub(have)));
        }
        out
    };
    let (into_a, into_b) = (missing(b, a), missing(a, b));
    Ok((a.refine(&into_a)?, b.refine(&into_b)?))
}
