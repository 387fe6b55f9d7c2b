//! Conics as rational quadratic Bézier curves, and exact circular/elliptic arcs as NURBS.

use crate::bezier::BezierCurve;
use crate::bspline::BSplineCurve;
use crate::error::ConicError;
use crate::error::{check_coordinate_of, check_finite, Error, Result};
use crate::geom::{sin_cos, Cartesian};
use glam::DVec2;
use std::f64::consts::FRAC_PI_2;

/// The largest sweep of one rational quadratic piece in [`ellipse_arc`] (90°): smaller pieces
/// keep the middle weight `cos(Δ/2) >= √2/2` and the control triangle compact.
pub const MAX_ARC_PIECE: f64 = FRAC_PI_2;

/// The type of conic a rational quadratic Bézier curve with weights `w0, w1, w2` lies on,
/// decided by the shape factor `k = w1² / (w0 w2)` (in the standard form `w0 = w2 = 1` it is
/// `w1²`): ellipse for `k < 1`, parabola for `k = 1`, hyperbola for `k > 1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConicKind {
    /// `w1 < 1` in standard form (a circle for the right triangle and weight).
    Ellipse,
    /// `w1 = 1`: the polynomial quadratic.
    Parabola,
    /// `w1 > 1`.
    Hyperbola,
}

impl ConicKind {
    /// `"ellipse" | "parabola" | "hyperbola"`.
    pub fn name(self) -> &'static str {
        match self {
            ConicKind::Ellipse => "ellipse",
            ConicKind::Parabola => "parabola",
            ConicKind::Hyperbola => "hyperbola",
        }
    }
}

/// Classifies by the shape factor `w1² / (w0 w2)`; `|k − 1| <= 1e-12` counts as a parabola.
///
/// # Errors
/// [`Error::NonPositiveWeight`] / [`Error::NotFinite`] for bad weights.
pub fn conic_kind(w0: f64, w1: f64, w2: f64) -> Result<ConicKind> {
    /// How close to 1 the shape factor must be to call the conic a parabola.
    const PARABOLA_TOLERANCE: f64 = 1e-12;
    crate::geom::check_weights(&[w0, w1, w2], 3)?;
    let k = w1 * w1 / (w0 * w2);
    Ok(if (k - 1.0).abs() <= PARABOLA_TOLERANCE {
        ConicKind::Parabola
    } else if k < 1.0 {
        ConicKind::Ellipse
    } else {
        ConicKind::Hyperbola
    })
}

/// The exact circular arc of the isosceles control triangle `P0 P1 P2` (`|P0P1| = |P1P2|`):
/// weights `1, sin θ, 1` where `θ` is half the angle at `P1` (equivalently `cos(Δ/2)` for the
/// arc's sweep `Δ`). The arc is tangent to `P0P1` at `P0` and to `P1P2` at `P2`.
///
/// # Errors
/// [`ConicError::NotIsosceles`] unless the legs are equal (to `1e-9` relative) and the triangle is
/// not degenerate (collinear points or a zero leg).
pub fn circle_arc_from_triangle(p0: DVec2, p1: DVec2, p2: DVec2) -> Result<BezierCurve<DVec2>> {
    for (name, v) in [
        ("x0", p0.x),
        ("y0", p0.y),
        ("x1", p1.x),
        ("y1", p1.y),
        ("x2", p2.x),
        ("y2", p2.y),
    ] {
        check_finite(name, None, v)?;
    }
    let (a, b) = (p0 - p1, p2 - p1);
    let (la, lb) = (a.length(), b.length());
    if la == 0.0 || lb == 0.0 || a.perp_dot(b).abs() <= 1e-12 * la * lb {
        return Err(Error::Conic(ConicError::DegenerateTriangle {}));
    }
    if (la - lb).abs() > 1e-9 * la.max(lb) {
        return Err(Error::Conic(ConicError::NotIsosceles {
            first: la,
            second: lb,
        }));
    }
    // The middle weight is sin(θ/2) for the angle θ at P1 (= cos of half the arc's sweep π − θ):
    // half the chord between the unit vectors along the legs, |a/|a| − b/|b|| = 2 sin(θ/2),
    // which stays accurate for small θ where acos(a·b/(|a||b|)) would not.
    let w1 = 0.5 * (a / la - b / lb).length();
    BezierCurve::new(vec![p0, p1, p2], Some(&[1.0, w1, 1.0]))
}

/// The arc `center + cos θ · axis_x + sin θ · axis_y` for `θ` from `start` to `start + sweep`
/// (radians; negative sweeps run clockwise), as an exact NURBS of degree 2 on `[0, 1]`: the
/// sweep is cut into `⌈|sweep| / 90°⌉` equal pieces, each a rational quadratic with end weights
/// 1 and middle weight `cos(Δ/2)`, joined by double knots. Perpendicular axes of equal length
/// give a circle, other axes an ellipse (an affine image of the circle, which stays exact).
/// A full turn (`|sweep| = 2π`) gives the 9-point circle with knots
/// `0,0,0,¼,¼,½,½,¾,¾,1,1,1`.
///
/// # Errors
/// [`Error::NotFinite`]; [`ConicError::InvalidSweep`] for a zero sweep, a sweep beyond a full turn
/// or parallel (degenerate) axes.
pub fn ellipse_arc<C: Cartesian>(
    center: C,
    axis_x: C,
    axis_y: C,
    start: f64,
    sweep: f64,
) -> Result<BSplineCurve<C>> {
    check_finite("start-angle", None, start)?;
    check_finite("sweep", None, sweep)?;
    for (what, p) in [("center", center), ("axis_x", axis_x), ("axis_y", axis_y)] {
        for k in 0..C::DIM {
            check_coordinate_of(what, k, p.coord(k))?;
        }
    }
    let full = std::f64::consts::TAU;
    if sweep == 0.0 || sweep.abs() > full * (1.0 + 1e-12) {
        return Err(Error::Conic(ConicError::InvalidSweep { sweep }));
    }
    if C::cross_norm(axis_x, axis_y).abs() <= 1e-12 * axis_x.norm() * axis_y.norm() {
        return Err(Error::Conic(ConicError::ParallelAxes {}));
    }
    let pieces = ((sweep.abs() / MAX_ARC_PIECE) - 1e-9).ceil().max(1.0) as usize;
    let delta = sweep / pieces as f64;
    let w_mid = sin_cos(0.5 * delta).1;
    let at = |theta: f64, scale: f64| {
        let (sin, cos) = sin_cos(theta);
        center + (axis_x * cos + axis_y * sin) * scale
    };
    let mut points = Vec::with_capacity(2 * pieces + 1);
    let mut weights = Vec::with_capacity(2 * pieces + 1);
    let mut knots = vec![0.0; 3];
    for i in 0..pieces {
        let theta0 = start + delta * i as f64;
        if i == 0 {
            points.push(at(theta0, 1.0));
            weights.push(1.0);
        }
        // The middle point: where the end tangents meet, at distance 1/cos(Δ/2) along the
        // bisector (of the unit circle, before the affine map).
        points.push(at(theta0 + 0.5 * delta, 1.0 / w_mid));
        weights.push(w_mid);
        let end = if i + 1 == pieces {
            start + sweep
        } else {
            theta0 + delta
        };
        points.push(at(end, 1.0));
        weights.push(1.0);
        if i + 1 < pieces {
            let u = (i + 1) as f64 / pieces as f64;
            knots.extend([u, u]);
        }
    }
    knots.extend([1.0; 3]);
    BSplineCurve::new(points, 2, knots, Some(&weights))
}

/// The circular arc `center + r·(cos θ, sin θ)` for θ from `start` to `start + sweep` (radians;
/// a negative sweep runs clockwise) as an exact NURBS: [`ellipse_arc`] with the axes `(r, 0)`
/// and `(0, r)`. A full turn is the 9-point circle.
///
/// # Errors
/// [`Error::NotFinite`] or [`Error::NotPositive`] for the radius, then as [`ellipse_arc`].
///
/// ```
/// use splinelab::prelude::*;
/// let tau = std::f64::consts::TAU;
/// let c = splinelab::rational::circular_arc(glam::DVec2::ZERO, 2.0, 0.0, tau).unwrap();
/// assert_eq!(c.control_points().len(), 9);
/// assert!((c.evaluate(0.3).unwrap().length() - 2.0).abs() < 1e-14);
/// ```
pub fn circular_arc(center: DVec2, r: f64, start: f64, sweep: f64) -> Result<BSplineCurve<DVec2>> {
    check_radius("r", r)?;
    ellipse_arc(center, DVec2::new(r, 0.0), DVec2::new(0.0, r), start, sweep)
}

/// The full ellipse with semi-axes `rx`, `ry`, the first axis turned by `rotation` radians:
/// `center + rx cos θ·e_x + ry sin θ·e_y` with `e_x = (cos φ, sin φ)`, `e_y = (−sin φ, cos φ)`,
/// as an exact NURBS ([`ellipse_arc`] over a full turn).
///
/// # Errors
/// [`Error::NotFinite`] or [`Error::NotPositive`] for `rx`, then `ry`; [`Error::NotFinite`]
/// for the rotation; then as [`ellipse_arc`].
pub fn ellipse(center: DVec2, rx: f64, ry: f64, rotation: f64) -> Result<BSplineCurve<DVec2>> {
    check_radius("rx", rx)?;
    check_radius("ry", ry)?;
    check_finite("rotation", None, rotation)?;
    let (sin, cos) = sin_cos(rotation);
    let (ex, ey) = (DVec2::new(cos, sin), DVec2::new(-sin, cos));
    ellipse_arc(center, ex * rx, ey * ry, 0.0, std::f64::consts::TAU)
}

/// A radius: finite and > 0 (`name` names it in the error).
fn check_radius(name: &'static str, r: f64) -> Result<()> {
    check_finite(name, None, r)?;
    if r <= 0.0 {
        return Err(Error::NotPositive { name, value: r });
    }
    Ok(())
}
