//! `fit_bspline` against independent expectations: samples of a known B-spline (its control
//! count is enough), every sample within the tolerance by brute force (the fitted curve
//! evaluated densely here, each sample's distance to that polyline), a closed stroke giving a
//! periodic curve whose ends meet with equal derivatives, degenerate strokes, and the errors.

mod common;

use common::*;
use splinelab::fit::{fit_bspline, BSplineFit};
use splinelab::prelude::*;
use splinelab::{BSplineCurve, DVec2, DVec3, Error};

/// The curve at `count + 1` parameters evenly over its domain.
fn dense(curve: &BSplineCurve<DVec2>, count: usize) -> Vec<DVec2> {
    let (a, b) = curve.domain();
    (0..=count)
        .map(|i| {
            curve
                .evaluate(a + (b - a) * i as f64 / count as f64)
                .unwrap()
        })
        .collect()
}

/// The distance from `q` to the curve by brute force: the nearest of 20 001 evenly spaced
/// curve points, then golden-section search over the parameter interval on either side of it.
fn brute_force_distance(curve: &BSplineCurve<DVec2>, poly: &[DVec2], q: DVec2) -> f64 {
    let (a, b) = curve.domain();
    let steps = poly.len() - 1;
    let (i, _) = poly
        .iter()
        .enumerate()
        .map(|(i, &c)| (i, (c - q).length()))
        .fold((0, f64::MAX), |m, x| if x.1 < m.1 { x } else { m });
    let at = |j: usize| a + (b - a) * j.min(steps) as f64 / steps as f64;
    let (mut lo, mut hi) = (at(i.saturating_sub(1)), at(i + 1));
    let d = |u: f64| (curve.evaluate(u).unwrap() - q).length();
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..60 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if d(x1) < d(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    d(0.5 * (lo + hi)).min((poly[i] - q).length())
}

/// The largest brute-force distance from a sample to the curve.
fn brute_force_error(fit: &BSplineFit<DVec2>, samples: &[DVec2]) -> f64 {
    let poly = dense(&fit.curve, 20_000);
    samples
        .iter()
        .map(|&q| brute_force_distance(&fit.curve, &poly, q))
        .fold(0.0, f64::max)
}

/// Every sample within the tolerance (brute force, with the polyline's chord error allowed),
/// and the reported error honest: at least the brute-force error, at most the tolerance.
#[track_caller]
fn assert_within(fit: &BSplineFit<DVec2>, samples: &[DVec2], tol: f64) {
    let brute = brute_force_error(fit, samples);
    let slack = 1e-6 * tol;
    assert!(brute <= tol + slack, "brute-force error {brute} > {tol}");
    assert!(
        fit.max_error <= tol,
        "reported error {} > {tol}",
        fit.max_error
    );
    assert!(
        fit.max_error + slack >= brute - 1e-4 * tol,
        "reported {} below the brute-force {brute}",
        fit.max_error
    );
}

/// A clamped B-spline with uniform interior knots through the given control points.
fn clamped(points: Vec<DVec2>, p: usize) -> BSplineCurve<DVec2> {
    let n = points.len();
    let spans = n - p;
    let mut knots = vec![0.0; p + 1];
    knots.extend((1..spans).map(|j| j as f64 / spans as f64));
    knots.extend(vec![1.0; p + 1]);
    BSplineCurve::new(points, p, knots, None).unwrap()
}

/// `count` samples of `curve` at parameters spaced unevenly (speed varying along the stroke).
fn samples_of(curve: &BSplineCurve<DVec2>, count: usize) -> Vec<DVec2> {
    (0..count)
        .map(|i| {
            let s = i as f64 / (count - 1) as f64;
            curve.evaluate(s).unwrap()
        })
        .collect()
}

#[test]
fn a_single_bezier_is_recovered_with_its_own_control_count() {
    for p in 2..=4 {
        let mut rng = Rng::new(7 + p as u64);
        let control: Vec<DVec2> = (0..=p)
            .map(|i| DVec2::new(100.0 * i as f64, rng.range(-60.0, 60.0)))
            .collect();
        let curve = clamped(control, p);
        let samples = samples_of(&curve, 300);
        let tol = 0.05;
        let fit = fit_bspline(&samples, p, tol, Some(false)).unwrap();
        assert!(!fit.closed);
        assert_eq!(
            fit.curve.control_points().len(),
            p + 1,
            "degree {p}: a Bézier needs p + 1"
        );
        assert_within(&fit, &samples, tol);
    }
}

#[test]
fn a_known_bspline_needs_no_more_control_points_than_it_has() {
    let mut rng = Rng::new(42);
    for (p, n) in [(2, 7), (3, 8), (3, 12)] {
        // A wavy curve: control points along x with random heights.
        let control: Vec<DVec2> = (0..n)
            .map(|i| DVec2::new(60.0 * i as f64, rng.range(-30.0, 30.0)))
            .collect();
        let curve = clamped(control, p);
        let samples = samples_of(&curve, 800);
        let tol = 0.5;
        let fit = fit_bspline(&samples, p, tol, None).unwrap();
        let got = fit.curve.control_points().len();
        assert!(
            got <= n,
            "degree {p}: {got} control points for a curve of {n}"
        );
        assert_within(&fit, &samples, tol);
    }
}

#[test]
fn noisy_strokes_stay_within_the_tolerance() {
    let mut rng = Rng::new(3);
    for (p, tol) in [(1, 1.0), (2, 1.0), (3, 1.0), (3, 2.0), (5, 1.5)] {
        let samples: Vec<DVec2> = (0..400)
            .map(|i| {
                let s = i as f64 / 399.0;
                DVec2::new(700.0 * s, 200.0 * (9.0 * s).sin() + 50.0 * (23.0 * s).cos())
                    + DVec2::new(rng.range(-0.5, 0.5), rng.range(-0.5, 0.5))
            })
            .collect();
        let fit = fit_bspline(&samples, p, tol, Some(false)).unwrap();
        assert_within(&fit, &samples, tol);
        // Jitter of at most 0.71 under a smooth curve: far fewer points than samples.
        assert!(
            fit.curve.control_points().len() < samples.len() / 8,
            "degree {p}: {} control points",
            fit.curve.control_points().len()
        );
        assert_eq!(fit.curve.evaluate(0.0).unwrap(), samples[0], "start");
        assert_eq!(fit.curve.evaluate(1.0).unwrap(), samples[399], "end");
    }
}

#[test]
fn a_circle_closes_into_a_periodic_curve() {
    let r = 120.0;
    let m = 240;
    let circle: Vec<DVec2> = (0..=m)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / m as f64;
            DVec2::new(400.0 + r * a.cos(), 300.0 + r * a.sin())
        })
        .collect();
    for p in [2, 3, 4] {
        for closed in [Some(true), None] {
            let tol = 0.25;
            let fit = fit_bspline(&circle, p, tol, closed).unwrap();
            assert!(fit.closed, "degree {p}, {closed:?}");
            assert_eq!(fit.curve.wrapped(), p);
            let (a, b) = fit.curve.domain();
            assert_close2(
                fit.curve.evaluate(a).unwrap(),
                fit.curve.evaluate(b).unwrap(),
                1e-9,
                "the ends meet",
            );
            for order in 1..p {
                let (da, db) = (
                    fit.curve.derivative(a, order).unwrap(),
                    fit.curve.derivative(b, order).unwrap(),
                );
                assert_close2(da, db, 1e-9 * da.length(), "derivatives agree at the seam");
                assert!(da.length() > 1.0, "a real derivative");
            }
            assert_within(&fit, &circle, tol);
            // Independent: a circle this size within 0.25 needs only a handful of points.
            let count = fit.curve.control_points().len() - p;
            assert!(count <= 16, "degree {p}: {count} distinct control points");
            // Every point of the curve on the circle within the tolerance (not just samples).
            for q in dense(&fit.curve, 2000) {
                let d = ((q - DVec2::new(400.0, 300.0)).length() - r).abs();
                assert!(d <= tol + 0.05, "curve point {q} off the circle by {d}");
            }
        }
    }
}

#[test]
fn an_open_arc_is_not_closed_by_default() {
    let arc: Vec<DVec2> = (0..=100)
        .map(|i| {
            let a = 3.0 * i as f64 / 100.0;
            DVec2::new(100.0 * a.cos(), 100.0 * a.sin())
        })
        .collect();
    let fit = fit_bspline(&arc, 3, 0.5, None).unwrap();
    assert!(!fit.closed);
    assert_eq!(fit.curve.wrapped(), 0);
    assert_within(&fit, &arc, 0.5);
}

#[test]
fn degenerate_strokes_do_not_fail() {
    let a = DVec2::new(1.0, 2.0);
    let b = DVec2::new(5.0, -1.0);
    // Two samples: a straight curve through both.
    let fit = fit_bspline(&[a, b], 3, 0.1, None).unwrap();
    assert_eq!(fit.curve.control_points().len(), 4);
    assert_close2(fit.curve.evaluate(0.0).unwrap(), a, 1e-12, "start");
    assert_close2(fit.curve.evaluate(1.0).unwrap(), b, 1e-12, "end");
    assert_close2(
        fit.curve.evaluate(0.5).unwrap(),
        (a + b) * 0.5,
        1e-12,
        "midpoint",
    );
    // Identical samples: the constant curve.
    let fit = fit_bspline(&[a; 5], 3, 0.1, None).unwrap();
    assert!(!fit.closed);
    assert_eq!(fit.max_error, 0.0);
    assert_eq!(fit.curve.evaluate(0.3).unwrap(), a);
    // Repeated samples inside a stroke are merged.
    let s = [a, a, b, b, b, DVec2::new(9.0, 3.0)];
    let fit = fit_bspline(&s, 2, 0.01, None).unwrap();
    assert_within(&fit, &s, 0.01);
    // Collinear samples: a straight curve with the fewest points.
    let line: Vec<DVec2> = (0..50)
        .map(|i| a + (b - a) * ((i * i) as f64 / 2401.0))
        .collect();
    for p in 1..=4 {
        let fit = fit_bspline(&line, p, 1e-6, None).unwrap();
        assert_eq!(fit.curve.control_points().len(), p + 1, "degree {p}");
        assert_within(&fit, &line, 1e-6);
    }
    // Fewer samples than the degree needs: one polynomial piece through them, degree p.
    let three = [a, b, DVec2::new(9.0, 3.0)];
    let fit = fit_bspline(&three, 5, 1e-9, None).unwrap();
    assert_eq!(fit.curve.degree(), 5);
    assert_eq!(fit.curve.control_points().len(), 6);
    assert!(fit.max_error <= 1e-9);
    assert_within(&fit, &three, 1e-6);
}

#[test]
fn three_dimensional_strokes_fit() {
    let helix: Vec<DVec3> = (0..300)
        .map(|i| {
            let a = i as f64 / 30.0;
            DVec3::new(50.0 * a.cos(), 50.0 * a.sin(), 8.0 * a)
        })
        .collect();
    let fit = fit_bspline(&helix, 3, 0.2, Some(false)).unwrap();
    let (a, b) = fit.curve.domain();
    let poly: Vec<DVec3> = (0..=20_000)
        .map(|i| {
            fit.curve
                .evaluate(a + (b - a) * i as f64 / 20_000.0)
                .unwrap()
        })
        .collect();
    for &q in &helix {
        let d = poly
            .iter()
            .map(|&c| (c - q).length())
            .fold(f64::MAX, f64::min);
        assert!(d <= 0.2 + 0.01, "sample {q} at {d}");
    }
    assert!(fit.max_error <= 0.2);
}

#[test]
fn bad_input_gives_coded_errors() {
    let s = [DVec2::ZERO, DVec2::new(1.0, 0.0), DVec2::new(2.0, 1.0)];
    let code = |r: Result<BSplineFit<DVec2>, Error>| r.unwrap_err().code();
    assert_eq!(code(fit_bspline(&s, 0, 0.1, None)), "degree-out-of-range");
    assert_eq!(code(fit_bspline(&s, 11, 0.1, None)), "degree-out-of-range");
    assert_eq!(
        code(fit_bspline(&s[..1], 3, 0.1, None)),
        "too-few-data-points"
    );
    assert_eq!(code(fit_bspline(&s, 3, 0.0, None)), "invalid-tolerance");
    assert_eq!(
        code(fit_bspline(&s, 3, f64::NAN, None)),
        "invalid-tolerance"
    );
    let bad = [DVec2::ZERO, DVec2::new(f64::NAN, 0.0)];
    assert_eq!(code(fit_bspline(&bad, 3, 0.1, None)), "not-finite");
    // A closed curve of degree 3 needs 4 distinct samples.
    assert_eq!(
        code(fit_bspline(&s, 3, 0.1, Some(true))),
        "too-few-data-points"
    );
    let too_many = vec![DVec2::ZERO; splinelab::fit::MAX_STROKE_SAMPLES + 1];
    assert_eq!(code(fit_bspline(&too_many, 3, 0.1, None)), "too-large");
    // Above the B-spline fitter's own budget (10⁵ samples; the stroke check allows 10⁶).
    let long: Vec<DVec2> = (0..100_001).map(|i| DVec2::new(i as f64, 0.0)).collect();
    assert_eq!(code(fit_bspline(&long, 3, 0.1, None)), "too-large");
}

#[test]
fn a_tight_tolerance_on_a_jittered_polyline_gives_no_swings_between_samples() {
    // A pen stroke of bench/strokes.mjs (seed 25, "polyline 1": three corners, Gaussian jitter
    // σ 0.44 px): at 1 px the fit needs nearly a control point per sample, and a least-squares
    // curve that close to interpolation once swung 10⁹ px away between samples.
    let text = include_str!("fixtures/fit_jittered_polyline.json");
    let coords: Vec<f64> = text
        .trim()
        .trim_matches(|c| c == '[' || c == ']')
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    let samples: Vec<DVec2> = coords.chunks(2).map(|c| DVec2::new(c[0], c[1])).collect();
    for tol in [1.0, 2.0] {
        let fit = fit_bspline(&samples, 3, tol, None).unwrap();
        assert_within(&fit, &samples, tol);
        let poly = dense(&fit.curve, 20_000);
        let far = poly
            .iter()
            .map(|&c| distance_to_polyline(c, &samples))
            .fold(0.0, f64::max);
        assert!(
            far < 10.0,
            "tolerance {tol}: the curve swings {far} px from the stroke"
        );
    }
}
