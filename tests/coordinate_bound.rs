//! Coordinates are bounded by `MAX_COORDINATE` (1e120): near `f64::MAX` a derivative's
//! differences overflowed (`derivative` and `arcLength` gave NaN), so every constructor refuses
//! such a coordinate with the coded error "coordinate-too-large", and coordinates within the
//! bound keep derivatives and lengths finite. Values checked against closed forms: the cubic's
//! derivatives by the Bernstein form of the hodograph, the k-th derivative at t = 0 of an
//! alternating control polygon `p!/(p−k)! Δ^k P_0` with `Δ^k ((−1)^i M) = (−2)^k M`, a
//! straight cubic's length by Pythagoras. Runs natively and in Node.

mod common;

use common::*;
use splinelab::bezier::{self, BezierCurve};
use splinelab::bspline::BSplineCurve;
use splinelab::geom::MAX_COORDINATE;
use splinelab::interp::{CubicSpline, LagrangeCurve};
use splinelab::prelude::*;
use splinelab::{BSplineSurface, DVec2, Error};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// The code of the error `result` failed with (panics if it succeeded).
#[track_caller]
fn code<T: std::fmt::Debug>(result: splinelab::Result<T>) -> &'static str {
    result.expect_err("expected an error").code()
}

/// `|a − b| ≤ rel · |b|` for each coordinate, printing both.
#[track_caller]
fn close(a: DVec2, b: DVec2, rel: f64) {
    for k in 0..2 {
        assert!(
            (a[k] - b[k]).abs() <= rel * b[k].abs(),
            "{a:?} vs {b:?} (coordinate {k})"
        );
    }
}

/// `n!/(n−k)!` as a float (exact below 2^53 for the orders used here).
fn falling(n: usize, k: usize) -> f64 {
    ((n - k + 1)..=n).map(|i| i as f64).product()
}

#[test]
fn near_f64_max_every_entry_refuses_the_coordinate() {
    let huge = [0.0, 0.0, f64::MAX, 1.0, -f64::MAX, 2.0, 1.0, 0.0];
    assert_eq!(
        code(BezierCurve::<DVec2>::from_flat(&huge, None)),
        "coordinate-too-large"
    );
    assert_eq!(
        code(BSplineCurve::<DVec2>::from_flat(
            &huge,
            3,
            vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0],
            None
        )),
        "coordinate-too-large"
    );
    let pts = pts2(&[(0.0, 0.0), (1e200, 1.0), (2.0, 0.0)]);
    assert_eq!(
        code(CubicSpline::catmull_rom(pts, 0.5, false)),
        "coordinate-too-large"
    );
    assert_eq!(
        code(bezier::arc_lengths::<DVec2>(&huge, 3, None)),
        "coordinate-too-large"
    );
    let mut net = vec![0.0; 27];
    net[13] = -1e130;
    assert_eq!(
        code(BSplineSurface::bezier(&net, 3, 3, None)),
        "coordinate-too-large"
    );
    // A drag to a huge point is refused too, and the curve keeps its point.
    let mut c = BezierCurve::new(pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)]), None).unwrap();
    let e = c.set_control_point(1, DVec2::new(3.0, 1e121)).unwrap_err();
    assert_eq!(
        e,
        Error::CoordinateTooLarge {
            what: "new-point-coordinate",
            index: Some(1),
            value: 1e121,
            max: 1e120
        }
    );
    assert_eq!(c.control_points()[1], DVec2::new(1.0, 1.0));
}

#[test]
fn the_bound_is_inclusive_and_finiteness_comes_first() {
    assert_eq!(MAX_COORDINATE, 1e120);
    let next_up = f64::from_bits(MAX_COORDINATE.to_bits() + 1);
    assert!(BezierCurve::<DVec2>::from_flat(&[-1e120, 0.0, 1e120, 0.0], None).is_ok());
    assert_eq!(
        code(BezierCurve::<DVec2>::from_flat(
            &[0.0, 0.0, next_up, 0.0],
            None
        )),
        "coordinate-too-large"
    );
    // Coordinate by coordinate, each checked for finiteness and then for size.
    assert_eq!(
        code(BezierCurve::<DVec2>::from_flat(
            &[f64::NAN, 1e200, 1.0, 1.0],
            None
        )),
        "not-finite"
    );
    assert_eq!(
        code(BezierCurve::<DVec2>::from_flat(
            &[1e200, f64::NAN, 1.0, 1.0],
            None
        )),
        "coordinate-too-large"
    );
}

#[test]
fn coordinates_of_1e100_keep_derivatives_and_lengths_finite() {
    // The syllabus cubic (0,0) (2,2) (6,4) (8,2) scaled by 1e100. Its hodograph in Bernstein form,
    // P′(t) = 3[(1−t)²ΔP0 + 2t(1−t)ΔP1 + t²ΔP2] with ΔP = (2,2), (4,2), (2,−2), gives at t = 1/4
    // 3·(44, 28)/16 = (8.25, 5.25); P″(t) = 6[(1−t)Δ²P0 + tΔ²P1] with Δ²P = (2,0), (−2,−4) gives
    // (6, −6).
    let s = 1e100;
    let p = pts2(&[
        (0.0, 0.0),
        (2.0 * s, 2.0 * s),
        (6.0 * s, 4.0 * s),
        (8.0 * s, 2.0 * s),
    ]);
    let c = BezierCurve::new(p.clone(), None).unwrap();
    close(
        c.derivative(0.25, 1).unwrap(),
        DVec2::new(8.25 * s, 5.25 * s),
        1e-14,
    );
    close(
        c.derivative(0.25, 2).unwrap(),
        DVec2::new(6.0 * s, -6.0 * s),
        1e-14,
    );
    // The same cubic as a clamped B-spline with one span.
    let b = BSplineCurve::new(p, 3, vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0], None).unwrap();
    close(
        b.derivative(0.25, 1).unwrap(),
        DVec2::new(8.25 * s, 5.25 * s),
        1e-14,
    );
    close(
        b.derivative(0.25, 2).unwrap(),
        DVec2::new(6.0 * s, -6.0 * s),
        1e-14,
    );
    // A straight cubic from (0,0) to (3,4)·1e100 at uniform speed: length 5e100.
    let flat = [
        0.0,
        0.0,
        s,
        4.0 * s / 3.0,
        2.0 * s,
        8.0 * s / 3.0,
        3.0 * s,
        4.0 * s,
    ];
    let line = BezierCurve::<DVec2>::from_flat(&flat, None).unwrap();
    let length = line.arc_length(None).unwrap();
    assert!((length - 5e100).abs() <= 1e-12 * 5e100, "{length}");
    let batch = bezier::arc_lengths::<DVec2>(&flat, 3, None).unwrap();
    assert!((batch[0] - 5e100).abs() <= 1e-12 * 5e100, "{batch:?}");
}

#[test]
fn at_the_bound_every_derivative_of_a_degree_20_curve_is_finite() {
    // P_i = (−1)^i (M, M/2), the polygon with the largest differences the bound allows:
    // P^(k)(0) = 20!/(20−k)! Δ^k P_0 = 20!/(20−k)! (−2)^k (M, M/2), up to 2.6e144 at k = 20.
    let m = MAX_COORDINATE;
    let p: Vec<DVec2> = (0..=20)
        .map(|i| {
            if i % 2 == 0 {
                DVec2::new(m, m / 2.0)
            } else {
                DVec2::new(-m, -m / 2.0)
            }
        })
        .collect();
    let c = BezierCurve::new(p, None).unwrap();
    for k in 1..=20 {
        let scale = falling(20, k) * (-2.0f64).powi(k as i32);
        close(
            c.derivative(0.0, k).unwrap(),
            DVec2::new(scale * m, scale * m / 2.0),
            1e-12,
        );
    }
    // Its length is finite, positive and at most its control polygon's, 20·|(2M, M)| (a Bézier
    // curve is never longer than its control polygon).
    let length = c.arc_length(None).unwrap();
    let polygon = 20.0 * DVec2::new(2.0 * m, m).length();
    assert!(
        length.is_finite() && length > 0.0 && length <= polygon,
        "{length} vs {polygon}"
    );
}

#[test]
fn interpolating_constructors_check_their_points() {
    // They had checked no coordinate at all (a NaN point gave NaN tangents).
    let nan = pts2(&[(0.0, 0.0), (f64::NAN, 1.0), (2.0, 0.0)]);
    assert_eq!(
        code(CubicSpline::catmull_rom(nan.clone(), 0.5, false)),
        "not-finite"
    );
    assert_eq!(
        code(LagrangeCurve::new(nan, &[0.0, 1.0, 2.0])),
        "not-finite"
    );
    let huge = pts2(&[(0.0, 0.0), (1.0, -1e200), (2.0, 0.0)]);
    assert_eq!(
        code(LagrangeCurve::new(huge, &[0.0, 1.0, 2.0])),
        "coordinate-too-large"
    );
}
