//! Property tests (proptest) of the core on random input rather than chosen examples:
//!
//! - every constructor (Bézier, B-spline and NURBS, closed B-spline, composite Bézier, the cubic
//!   interpolants, Lagrange, global interpolation and least squares, surfaces) returns `Ok` or
//!   `Err` for any numbers — random dims, point counts, degrees, knots and weights including
//!   NaN, ±∞, negative and huge values — and never panics, nor do evaluations of what it built;
//! - invariants that hold for any valid curve: knot insertion, refinement, Bézier extraction,
//!   Bézier splitting and degree elevation keep every point (compared at many parameters with
//!   the parent's own evaluation: two different algorithms, de Boor on different nets or
//!   de Casteljau on different polygons, must agree); interpolants pass through their points;
//!   B-spline basis functions are non-negative and sum to 1.
//!
//! Case counts are kept small (`CASES`) so the file runs in a few seconds in `cargo test`.
//! Native only: proptest does not build for wasm32.
#![cfg(not(target_arch = "wasm32"))]

use proptest::prelude::*;
use proptest::test_runner::Config;
use splinelab::bezier::{BezierCurve, CompositeCurve};
use splinelab::bspline::BSplineCurve;
use splinelab::bspline::Parameterization;
use splinelab::interp::{
    approximate_bspline, interpolate_bspline, CubicSpline, EndCondition, InterpolationOptions,
    LagrangeCurve,
};
use splinelab::prelude::*;
use splinelab::surface::interpolate_surface;
use splinelab::{BSplineSurface, DVec2, DVec3};

/// Cases per property (proptest's default is 256).
const CASES: u32 = 96;

fn config() -> Config {
    Config {
        cases: CASES,
        failure_persistence: None,
        ..Config::default()
    }
}

/// Any f64 a caller might pass: mostly ordinary, sometimes NaN, ±∞, ±0, huge or tiny.
fn any_number() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -10.0..10.0f64,
        1 => prop::sample::select(vec![
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            1e308,
            -1e308,
            5e-324,
            f64::MAX,
        ]),
    ]
}

/// `n` numbers: all ordinary when `clean` (so construction gets deep), else from [`any_number`].
fn values(n: usize, clean: bool) -> BoxedStrategy<Vec<f64>> {
    if clean {
        prop::collection::vec(-10.0..10.0f64, n).boxed()
    } else {
        prop::collection::vec(any_number(), n).boxed()
    }
}

fn numbers(max: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(any_number(), 0..max)
}

/// Random knots: sorted or not, repeated, any numbers.
fn any_knots(max: usize) -> impl Strategy<Value = Vec<f64>> {
    prop_oneof![
        numbers(max),
        numbers(max).prop_map(|mut k| {
            k.sort_by(f64::total_cmp);
            k
        }),
    ]
}

fn any_weights(max: usize) -> impl Strategy<Value = Option<Vec<f64>>> {
    prop::option::of(numbers(max))
}

/// Input shaped like a valid curve most of the time, so that calls get past the first check:
/// `count` points of `dim` coordinates (else any length), `count + degree + 1` knots, sorted
/// (else any), `count` weights — all from [`any_number`], so some are NaN, ±∞ or negative.
/// Returns (coords, degree, knots, weights).
#[allow(clippy::type_complexity)]
fn shaped(dim: usize) -> impl Strategy<Value = (Vec<f64>, usize, Vec<f64>, Option<Vec<f64>>)> {
    (1usize..12, 0usize..9, 0u8..10).prop_flat_map(move |(count, degree, mutation)| {
        let coords = if mutation == 0 {
            numbers(40).boxed()
        } else {
            values(count * dim, mutation >= 5)
        };
        let knots = prop::collection::vec(
            any_number(),
            count + degree + 1 + usize::from(mutation == 1),
        )
        .prop_map(move |mut k| {
            if mutation != 2 {
                k.sort_by(f64::total_cmp);
            }
            k
        });
        let weights = prop::option::of(prop_oneof![
            prop::collection::vec(any_number(), count),
            prop::collection::vec(0.1..4.0f64, count),
        ]);
        (coords, Just(degree), knots, weights)
    })
}

/// Evaluates `f` at the ends and inside of `[a, b]`, and just outside: must not panic.
fn probe<T>(a: f64, b: f64, mut f: impl FnMut(f64) -> T) {
    for s in [-0.5, 0.0, 0.25, 0.5, 1.0, 1.5] {
        let _ = f(a + (b - a) * s);
    }
    let _ = f(f64::NAN);
}

/// `|x − y| ≤ tol·(1 + scale)`, coordinate by coordinate.
fn close2(x: DVec2, y: DVec2, scale: f64, tol: f64) -> bool {
    (x - y).abs().max_element() <= tol * (1.0 + scale)
}

/// The largest coordinate of the points (for relative tolerances).
fn scale2(points: &[DVec2]) -> f64 {
    points
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max)
}

/// Finite 2D points, `min..max` of them.
fn points2(min: usize, max: usize) -> impl Strategy<Value = Vec<DVec2>> {
    prop::collection::vec((-10.0..10.0f64, -10.0..10.0f64), min..max)
        .prop_map(|v| v.into_iter().map(|(x, y)| DVec2::new(x, y)).collect())
}

/// Strictly increasing parameters, `n` of them, with gaps of at least 0.05.
fn increasing(n: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(0.05..2.0f64, n).prop_map(|gaps| {
        let mut t = 0.0;
        gaps.into_iter()
            .map(|g| {
                let v = t;
                t += g;
                v
            })
            .collect()
    })
}

/// A valid B-spline: degree p, n + 1 ≥ p + 1 points, clamped or unclamped knots with interior
/// multiplicities up to p, weights (positive) or none.
fn bspline() -> impl Strategy<Value = BSplineCurve<DVec2>> {
    (1usize..=5, 0usize..7, any::<bool>(), any::<bool>())
        .prop_flat_map(|(p, extra, clamped, rational)| {
            let count = p + 1 + extra;
            let interior = count - p - 1;
            (
                Just(p),
                points2(count, count + 1),
                // interior knots as fractions, some repeated (rounded to a coarse grid)
                prop::collection::vec(0.01..0.99f64, interior),
                Just(clamped),
                prop::collection::vec(0.2..5.0f64, count),
                Just(rational),
            )
        })
        .prop_filter_map(
            "a valid B-spline",
            |(p, points, mut inner, clamped, w, rational)| {
                inner.iter_mut().for_each(|u| *u = (*u * 8.0).round() / 8.0);
                inner.sort_by(f64::total_cmp);
                // keep multiplicities ≤ p
                let mut knots: Vec<f64> = Vec::new();
                if clamped {
                    knots.extend(std::iter::repeat_n(0.0, p + 1));
                } else {
                    knots.extend((0..=p).map(|i| -((p - i) as f64) * 0.3));
                }
                for u in inner {
                    let u = u.clamp(0.125, 0.875);
                    let m = knots.iter().filter(|&&k| k == u).count();
                    knots.push(if m >= p { u + 0.01 * (m as f64) } else { u });
                }
                knots.sort_by(f64::total_cmp);
                if clamped {
                    knots.extend(std::iter::repeat_n(1.0, p + 1));
                } else {
                    knots.extend((0..=p).map(|i| 1.0 + i as f64 * 0.3));
                }
                let weights = rational.then_some(w);
                BSplineCurve::new(points, p, knots, weights.as_deref()).ok()
            },
        )
}

/// A valid Bézier curve of degree 1..=8, rational or not, on [0, 1].
fn bezier() -> impl Strategy<Value = BezierCurve<DVec2>> {
    (2usize..=9)
        .prop_flat_map(|count| {
            (
                points2(count, count + 1),
                prop::option::of(prop::collection::vec(0.2..5.0f64, count)),
            )
        })
        .prop_map(|(points, w)| BezierCurve::new(points, w.as_deref()).expect("a valid Bézier"))
}

/// `count` parameters spread over `[a, b]`, ends included.
fn spread(a: f64, b: f64, count: usize) -> impl Iterator<Item = f64> {
    (0..count).map(move |i| a + (b - a) * i as f64 / (count - 1) as f64)
}

proptest! {
    #![proptest_config(Config { cases: 4 * CASES, ..config() })]

    // ---- no panic, whatever the input ----

    #[test]
    fn bezier_constructors_never_panic(
        (coords, _, _, w) in shaped(2), a in any_number(), b in any_number(),
    ) {
        if let Ok(c) = BezierCurve::<DVec2>::from_flat(&coords, w.as_deref()) {
            probe(0.0, 1.0, |t| (c.evaluate(t), c.derivative(t, 2), c.split(t)));
            let _ = (c.elevate(), c.arc_length(Some(1e-6)), c.flatten(0.01), c.with_interval(a, b));
        }
        if let Ok(c) = BezierCurve::<DVec3>::from_flat(&coords, w.as_deref()) {
            probe(0.0, 1.0, |t| (c.evaluate(t), c.de_casteljau(t), c.derivative(t, 1)));
            let _ = (c.arc_length(None), c.bounding_box());
        }
    }

    #[test]
    fn bspline_constructors_never_panic((coords, degree, knots, w) in prop_oneof![
        shaped(2),
        (numbers(40), 0usize..12, any_knots(30), any_weights(25)),
    ]) {
        for c in [
            BSplineCurve::<DVec2>::from_flat(&coords, degree, knots.clone(), w.as_deref()),
            BSplineCurve::<DVec2>::closed(
                coords.chunks_exact(2).map(|p| DVec2::new(p[0], p[1])).collect(), degree, w.as_deref(),
            ),
        ].into_iter().flatten() {
            let (a, b) = c.domain();
            probe(a, b, |u| (c.evaluate(u), c.derivative(u, 1), c.basis(u), c.insert_knot(u, 2)));
            let _ = (c.to_bezier(), c.refine(&knots), c.basis_curves(5));
        }
        if let Ok(c) = BSplineCurve::<DVec3>::from_flat(&coords, degree, knots, w.as_deref()) {
            let (a, b) = c.domain();
            probe(a, b, |u| c.de_boor(u));
        }
    }

    #[test]
    fn composite_constructor_never_panics(
        (coords, degrees) in prop::collection::vec(0usize..6, 0..5).prop_flat_map(|d| {
            let count: usize = d.iter().map(|k| k + 1).sum();
            (prop_oneof![values(2 * count, true), values(2 * count, false), numbers(40)], Just(d))
        }),
        breaks in prop::option::of(any_knots(6)),
    ) {
        if let Ok(c) = CompositeCurve::<DVec2>::from_flat(&coords, &degrees, breaks.as_deref()) {
            let (a, b) = c.domain();
            probe(a, b, |t| (c.evaluate(t), c.derivative(t, 1)));
            let _ = c.continuity(1e-9);
        }
    }

    #[test]
    fn interpolant_constructors_never_panic(
        (coords, params) in (0usize..12).prop_flat_map(|n| (
            prop_oneof![values(2 * n, true), values(2 * n, false), numbers(30)],
            prop_oneof![increasing(n), any_knots(16)],
        )), tangents in numbers(30),
        tension in any_number(), alpha in any_number(), closed in any::<bool>(), degree in 0usize..8,
        count in 0usize..20,
    ) {
        let points: Vec<DVec2> = coords.chunks_exact(2).map(|p| DVec2::new(p[0], p[1])).collect();
        let vectors: Vec<DVec2> = tangents.chunks_exact(2).map(|p| DVec2::new(p[0], p[1])).collect();
        let start = vectors.first().copied().unwrap_or(DVec2::ZERO);
        let ends = [
            EndCondition::Natural, EndCondition::Quadratic, EndCondition::Bessel,
            EndCondition::NotAKnot, EndCondition::Periodic,
            EndCondition::Clamped { start, end: DVec2::new(tension, alpha) },
        ];
        let mut built = Vec::new();
        for end in ends {
            built.push(CubicSpline::interpolate(points.clone(), params.clone(), end));
        }
        built.push(CubicSpline::hermite(points.clone(), params.clone(), vectors.clone()));
        built.push(CubicSpline::cardinal(points.clone(), params.clone(), tension));
        built.push(CubicSpline::catmull_rom(points.clone(), alpha, closed));
        built.push(CubicSpline::bessel(points.clone(), params.clone()));
        built.push(CubicSpline::interpolate(points.clone(), Parameterization::Centripetal, EndCondition::Natural));
        for c in built.into_iter().flatten() {
            let (a, b) = c.domain();
            probe(a, b, |t| (c.evaluate(t), c.derivative(t, 3)));
        }
        if let Ok(c) = LagrangeCurve::new(points.clone(), &params) {
            let (a, b) = c.domain();
            probe(a, b, |t| (c.evaluate(t), c.basis(t), c.aitken(t)));
        }
        let options = InterpolationOptions { closed, ..InterpolationOptions::default() };
        if let Ok(c) = interpolate_bspline(&points, degree, &params, &options) {
            let (a, b) = c.domain();
            probe(a, b, |u| c.evaluate(u));
        }
        let with_derivatives = InterpolationOptions {
            start_derivative: Some(start),
            end_derivative: vectors.get(1).copied(),
            knots: (count % 2 == 1).then(|| tangents.clone()),
            closed: false,
        };
        let _ = interpolate_bspline(&points, degree, &params, &with_derivatives);
        if let Ok(c) = approximate_bspline(&points, degree, count, &params, None) {
            let (a, b) = c.domain();
            probe(a, b, |u| c.evaluate(u));
        }
        let _ = approximate_bspline(&points, degree, count, &params, Some(&tangents));
    }

    #[test]
    fn surface_constructors_never_panic(
        (rows, cols, du, dv, coords, ku, kv, w) in (0usize..7, 0usize..7, 0usize..5, 0usize..5, 0u8..6)
            .prop_flat_map(|(rows, cols, du, dv, mutation)| {
                let sorted = |k: Vec<f64>| {
                    let mut k = k;
                    k.sort_by(f64::total_cmp);
                    k
                };
                let (shaped, clean) = (mutation > 0, mutation > 2);
                let coords = if shaped { values(3 * rows * cols, clean) } else { numbers(80).boxed() };
                let ku = if shaped { values(rows + du + 1, clean).prop_map(sorted).boxed() } else { any_knots(14).boxed() };
                let kv = if shaped { values(cols + dv + 1, clean).prop_map(sorted).boxed() } else { any_knots(14).boxed() };
                let w = prop::option::of(prop_oneof![prop::collection::vec(0.1..4.0f64, rows * cols), numbers(40)]);
                (Just(rows), Just(cols), Just(du), Just(dv), coords, ku, kv, w)
            }),
    ) {
        let built = [
            BSplineSurface::from_flat(&coords, rows, cols, du, dv, ku, kv, w.as_deref()),
            BSplineSurface::bezier(&coords, rows, cols, w.as_deref()),
            interpolate_surface(&coords, rows, cols, du, dv, Parameterization::Chord),
        ];
        for s in built.into_iter().flatten() {
            let ((a, b), (c, d)) = (s.knots_u().domain(), s.knots_v().domain());
            probe(a, b, |u| probe(c, d, |v| (s.evaluate(u, v), s.normal(u, v), s.derivative(u, v, 1, 1))));
            let _ = (s.insert_knot_u(0.5 * (a + b), 1), s.to_bezier_patches(), s.tessellate(4, 4));
        }
    }

}

proptest! {
    #![proptest_config(config())]

    // ---- invariants ----

    #[test]
    fn basis_functions_are_a_non_negative_partition_of_unity(c in bspline(), s in 0.0..=1.0f64) {
        let (a, b) = c.domain();
        let u = a + (b - a) * s;
        let n = c.basis(u).unwrap();
        let sum: f64 = n.iter().sum();
        prop_assert!((sum - 1.0).abs() <= 1e-12, "sum {} at u = {}", sum, u);
        prop_assert!(n.iter().all(|&x| x >= 0.0), "negative basis value at u = {}: {:?}", u, n);
    }

    #[test]
    fn knot_insertion_keeps_the_curve(c in bspline(), s in 0.0..=1.0f64, times in 1usize..4) {
        let (a, b) = c.domain();
        let u = a + (b - a) * s;
        let room = c.degree() + 1 - c.knots().multiplicity(u).min(c.degree() + 1);
        prop_assume!(times <= room);
        let inserted = c.insert_knot(u, times).unwrap();
        let scale = scale2(&c.control_points());
        for x in spread(a, b, 41) {
            let (p, q) = (c.evaluate(x).unwrap(), inserted.evaluate(x).unwrap());
            prop_assert!(close2(p, q, scale, 1e-10), "at {}: {} vs {}", x, p, q);
        }
    }

    #[test]
    fn refinement_keeps_the_curve(c in bspline(), us in prop::collection::vec(0.0..=1.0f64, 1..8)) {
        let (a, b) = c.domain();
        let mut us: Vec<f64> = us.into_iter().map(|s| a + (b - a) * s).collect();
        us.sort_by(f64::total_cmp);
        let Ok(refined) = c.refine(&us) else {
            // only a multiplicity above p + 1 may refuse
            return Ok(());
        };
        prop_assert_eq!(refined.knots().as_slice().len(), c.knots().as_slice().len() + us.len());
        let scale = scale2(&c.control_points());
        for x in spread(a, b, 41) {
            let (p, q) = (c.evaluate(x).unwrap(), refined.evaluate(x).unwrap());
            prop_assert!(close2(p, q, scale, 1e-10), "at {}: {} vs {}", x, p, q);
        }
    }

    #[test]
    fn bezier_extraction_reproduces_each_span(c in bspline()) {
        let pieces = c.to_bezier().unwrap();
        let (a, b) = c.domain();
        let mut breaks: Vec<f64> = c.knots().as_slice().iter().copied().filter(|&u| u >= a && u <= b).collect();
        breaks.dedup();
        prop_assert_eq!(pieces.len(), breaks.len() - 1);
        let scale = scale2(&c.control_points());
        let last = pieces.len() - 1;
        for (k, (piece, span)) in pieces.iter().zip(breaks.windows(2)).enumerate() {
            // The curve is right-continuous: at a break of multiplicity p + 1 its value is the
            // next piece's, so a piece's own end is compared only on the last span.
            for s in spread(0.0, 1.0, 11).filter(|&s| s < 1.0 || k == last) {
                let u = span[0] + (span[1] - span[0]) * s;
                let (p, q) = (c.evaluate(u).unwrap(), piece.evaluate(s).unwrap());
                prop_assert!(close2(p, q, scale, 1e-10), "at {}: {} vs {}", u, p, q);
            }
        }
    }

    #[test]
    fn split_pieces_reproduce_the_parent(c in bezier(), t in 0.01..0.99f64) {
        let (left, right) = c.split(t).unwrap();
        let scale = scale2(&c.control_points());
        for s in spread(0.0, 1.0, 21) {
            let (p, q) = (c.evaluate(s * t).unwrap(), left.evaluate(s).unwrap());
            prop_assert!(close2(p, q, scale, 1e-11), "left at {}: {} vs {}", s, p, q);
            let (p, q) = (c.evaluate(t + s * (1.0 - t)).unwrap(), right.evaluate(s).unwrap());
            prop_assert!(close2(p, q, scale, 1e-11), "right at {}: {} vs {}", s, p, q);
        }
        // and they meet
        let (l, r) = (left.control_points(), right.control_points());
        prop_assert_eq!(l.last(), r.first());
    }

    #[test]
    fn degree_elevation_keeps_the_curve(c in bezier(), times in 1usize..4) {
        let mut e = c.clone();
        for _ in 0..times {
            e = e.elevate().unwrap();
        }
        prop_assert_eq!(e.degree(), c.degree() + times);
        let scale = scale2(&c.control_points());
        for s in spread(0.0, 1.0, 41) {
            let (p, q) = (c.evaluate(s).unwrap(), e.evaluate(s).unwrap());
            prop_assert!(close2(p, q, scale, 1e-11), "at {}: {} vs {}", s, p, q);
        }
    }

    #[test]
    fn interpolants_pass_through_their_points(
        (points, params) in (3usize..10).prop_flat_map(|n| (points2(n, n + 1), increasing(n))),
        tension in 0.0..1.0f64, degree in 1usize..6,
    ) {
        let scale = scale2(&points);
        let mut curves: Vec<(String, CubicSpline<DVec2>)> = Vec::new();
        for end in [EndCondition::Natural, EndCondition::Quadratic, EndCondition::Bessel, EndCondition::NotAKnot] {
            let name = format!("cubic {end:?}");
            curves.push((name, CubicSpline::interpolate(points.clone(), params.clone(), end).unwrap()));
        }
        curves.push(("cardinal".into(), CubicSpline::cardinal(points.clone(), params.clone(), tension).unwrap()));
        curves.push(("bessel".into(), CubicSpline::bessel(points.clone(), params.clone()).unwrap()));
        for (name, c) in &curves {
            for (t, p) in params.iter().zip(&points) {
                let q = c.evaluate(*t).unwrap();
                prop_assert!(close2(*p, q, scale, 1e-11), "{} at {}: {} vs {}", name, t, p, q);
            }
        }
        let lagrange = LagrangeCurve::new(points.clone(), &params).unwrap();
        for (t, p) in params.iter().zip(&points) {
            let q = lagrange.evaluate(*t).unwrap();
            prop_assert!(close2(*p, q, scale, 1e-9), "lagrange at {}: {} vs {}", t, p, q);
        }
        let degree = degree.min(points.len() - 1);
        let global = interpolate_bspline(&points, degree, &params, &InterpolationOptions::default()).unwrap();
        for (t, p) in params.iter().zip(&points) {
            let q = global.evaluate(*t).unwrap();
            prop_assert!(close2(*p, q, scale, 1e-9), "B-spline degree {} at {}: {} vs {}", degree, t, p, q);
        }
    }

    #[test]
    fn surface_knot_insertion_keeps_the_surface(
        (rows, cols, du, dv, coords) in (2usize..6, 2usize..6).prop_flat_map(|(r, c)| {
            (Just(r), Just(c), 1..r, 1..c, prop::collection::vec(-5.0..5.0f64, 3 * r * c))
        }),
        s in 0.01..0.99f64,
    ) {
        let clamped = |n: usize, p: usize| -> Vec<f64> {
            let inner = n - p - 1;
            let mut k = vec![0.0; p + 1];
            k.extend((1..=inner).map(|i| i as f64 / (inner + 1) as f64));
            k.extend(vec![1.0; p + 1]);
            k
        };
        let surface = BSplineSurface::from_flat(&coords, rows, cols, du, dv, clamped(rows, du), clamped(cols, dv), None).unwrap();
        let by_u = surface.insert_knot_u(s, 1).unwrap();
        let by_v = surface.insert_knot_v(1.0 - s, 1).unwrap();
        for u in spread(0.0, 1.0, 9) {
            for v in spread(0.0, 1.0, 9) {
                let p = surface.evaluate(u, v).unwrap();
                for q in [by_u.evaluate(u, v).unwrap(), by_v.evaluate(u, v).unwrap()] {
                    prop_assert!((p - q).abs().max_element() <= 1e-10, "at ({}, {}): {} vs {}", u, v, p, q);
                }
            }
        }
    }
}
