//! Global B-spline interpolation, least squares and closed interpolation against independent
//! expectations: the Croatian notes' worked example solved by hand, the defining equations
//! (`C(t_i) = p_i`, `C'(t_0) = D_0`, the normal equations, `C^{p−1}` at a closed seam) checked
//! with the curve's own evaluation and basis, a dense solve written here, and fixtures from
//! scipy (`tests/fixtures/make_interp_bspline_fixtures.py`). Runs natively and in Node.

mod common;

use common::*;
use splinelab::error::InterpError;
use splinelab::interp::global::knots;
use splinelab::interp::{
    self, approximate_bspline, interpolate_bspline, interpolation_system, InterpolationOptions,
    RowKind,
};
use splinelab::prelude::*;
use splinelab::{BSplineCurve, DVec2, DVec3, Error};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// Random increasing parameters (gaps in [0.3, 1.7]) and points in [−10, 10]².
fn random_data(rng: &mut Rng, count: usize) -> (Vec<DVec2>, Vec<f64>) {
    let mut t = 0.0;
    let mut params = Vec::with_capacity(count);
    let mut points = Vec::with_capacity(count);
    for _ in 0..count {
        params.push(t);
        t += rng.range(0.3, 1.7);
        points.push(rng.point2(10.0));
    }
    (points, params)
}

fn options2() -> InterpolationOptions<DVec2> {
    InterpolationOptions::default()
}

/// The largest coordinate of the points: the scale for relative tolerances.
fn scale(points: &[DVec2]) -> f64 {
    points
        .iter()
        .fold(1.0f64, |m, p| m.max(p.x.abs()).max(p.y.abs()))
}

// --- The Croatian notes' example (lines 240–300): p = 2, five points at 0..4, a start
// derivative, knots 0 0 0 1 2 3 4 4 4, six unknowns r_0 … r_5. -------------------------------

fn croatian_data() -> (Vec<DVec2>, Vec<f64>, InterpolationOptions<DVec2>) {
    let points = pts2(&[(0.0, 0.0), (2.0, 4.0), (4.0, 2.0), (6.0, 6.0), (8.0, 0.0)]);
    let params = vec![0.0, 1.0, 2.0, 3.0, 4.0];
    let options = InterpolationOptions {
        knots: Some(vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0]),
        start_derivative: Some(DVec2::new(2.0, 8.0)),
        ..options2()
    };
    (points, params, options)
}

#[test]
fn croatian_example_matrix_is_the_notes_six_by_six() {
    let (points, params, options) = croatian_data();
    let s = interpolation_system(&points, 2, &params, &options).unwrap();
    #[rustfmt::skip]
    let notes = [
        1.0, 0.0, 0.0, 0.0, 0.0, 0.0,
        -2.0, 2.0, 0.0, 0.0, 0.0, 0.0,
        0.0, 0.5, 0.5, 0.0, 0.0, 0.0,
        0.0, 0.0, 0.5, 0.5, 0.0, 0.0,
        0.0, 0.0, 0.0, 0.5, 0.5, 0.0,
        0.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    assert_eq!(s.size, 6);
    assert_eq!(s.matrix, notes);
    assert_eq!(
        s.rows,
        [
            RowKind::Point,
            RowKind::StartDerivative,
            RowKind::Point,
            RowKind::Point,
            RowKind::Point,
            RowKind::Point
        ]
    );
    assert_eq!(s.knots, [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0]);
    assert_eq!(
        s.rhs,
        pts2(&[
            (0.0, 0.0),
            (2.0, 8.0),
            (2.0, 4.0),
            (4.0, 2.0),
            (6.0, 6.0),
            (8.0, 0.0)
        ])
    );
}

#[test]
fn croatian_example_solution_by_hand() {
    // r_0 = p_0 = (0, 0); −2r_0 + 2r_1 = D_0 = (2, 8) → r_1 = (1, 4);
    // (r_1 + r_2)/2 = p_1 = (2, 4) → r_2 = (3, 4); (r_2 + r_3)/2 = (4, 2) → r_3 = (5, 0);
    // (r_3 + r_4)/2 = (6, 6) → r_4 = (7, 12); r_5 = p_4 = (8, 0).
    let hand = pts2(&[
        (0.0, 0.0),
        (1.0, 4.0),
        (3.0, 4.0),
        (5.0, 0.0),
        (7.0, 12.0),
        (8.0, 0.0),
    ]);
    let (points, params, options) = croatian_data();
    let s = interpolation_system(&points, 2, &params, &options).unwrap();
    for (i, (&got, &want)) in s.solution.iter().zip(&hand).enumerate() {
        assert_close2(got, want, 1e-14, &format!("r_{i}"));
    }
    let c = interpolate_bspline(&points, 2, &params, &options).unwrap();
    assert_eq!(c.control_points().len(), 6);
    for (i, (&got, &want)) in c.control_points().iter().zip(&hand).enumerate() {
        assert_close2(got, want, 1e-14, &format!("P_{i}"));
    }
    assert_close2(
        c.derivative(0.0, 1).unwrap(),
        DVec2::new(2.0, 8.0),
        1e-13,
        "C'(0)",
    );
}

// --- The defining equations on random data. ---------------------------------------------------

#[test]
fn interpolation_conditions_hold_for_degrees_1_to_10() {
    let mut rng = Rng::new(7);
    for p in 1..=10 {
        for extra in [0, 1, 5, 17] {
            let (points, params) = random_data(&mut rng, p + 1 + extra);
            let c = interpolate_bspline(&points, p, &params, &options2()).unwrap();
            let tol = 1e-12 * scale(&points);
            for (i, (&t, &q)) in params.iter().zip(&points).enumerate() {
                assert_close2(
                    c.evaluate(t).unwrap(),
                    q,
                    tol,
                    &format!("p = {p}, C(t_{i})"),
                );
            }
            assert_eq!(c.domain(), (params[0], *params.last().unwrap()));
        }
    }
}

#[test]
fn derivative_conditions_hold() {
    let mut rng = Rng::new(11);
    for p in 1..=10 {
        for (start, end) in [(true, false), (false, true), (true, true)] {
            let count = (p + 1).max(3) + 2;
            let (points, params) = random_data(&mut rng, count);
            let d0 = rng.point2(5.0);
            let d1 = rng.point2(5.0);
            let options = InterpolationOptions {
                start_derivative: start.then_some(d0),
                end_derivative: end.then_some(d1),
                ..options2()
            };
            let c = interpolate_bspline(&points, p, &params, &options).unwrap();
            let extra = usize::from(start) + usize::from(end);
            assert_eq!(c.control_points().len(), count + extra, "p = {p}");
            let tol = 1e-12 * scale(&points).max(5.0);
            for (i, (&t, &q)) in params.iter().zip(&points).enumerate() {
                assert_close2(
                    c.evaluate(t).unwrap(),
                    q,
                    tol,
                    &format!("p = {p}, C(t_{i})"),
                );
            }
            let (a, b) = c.domain();
            if start {
                assert_close2(
                    c.derivative(a, 1).unwrap(),
                    d0,
                    tol,
                    &format!("p = {p} C'(t_0)"),
                );
            }
            if end {
                assert_close2(
                    c.derivative(b, 1).unwrap(),
                    d1,
                    tol,
                    &format!("p = {p} C'(t_n)"),
                );
            }
        }
    }
}

#[test]
fn degree_one_is_the_polyline() {
    let points = pts2(&[(0.0, 0.0), (1.0, 3.0), (4.0, 1.0), (5.0, 5.0)]);
    let params = [0.0, 1.0, 3.0, 4.0];
    let c = interpolate_bspline(&points, 1, &params, &options2()).unwrap();
    assert_eq!(c.control_points(), points);
    assert_eq!(c.knots().as_slice(), [0.0, 0.0, 1.0, 3.0, 4.0, 4.0]);
    assert_close2(
        c.evaluate(2.0).unwrap(),
        DVec2::new(2.5, 2.0),
        1e-15,
        "C(2)",
    );
}

#[test]
fn works_in_3d() {
    let points = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 2.0, 3.0),
        DVec3::new(3.0, 1.0, -1.0),
        DVec3::new(4.0, 4.0, 2.0),
    ];
    let params = [0.0, 1.0, 2.5, 3.0];
    let c = interpolate_bspline(&points, 3, &params, &InterpolationOptions::default()).unwrap();
    for (&t, &q) in params.iter().zip(&points) {
        assert_close3(c.evaluate(t).unwrap(), q, 1e-13, "C(t_i)");
    }
}

#[test]
fn default_knots_satisfy_schoenberg_whitney_for_random_params() {
    // The sites are the params, t_0 repeated for a start derivative and t_n for an end one; the
    // condition u_i < τ_i < u_{i+p+1} (equal only at a clamped end) is checked here directly.
    let mut rng = Rng::new(3);
    for _ in 0..2000 {
        let p = 1 + (rng.next_u64() % 10) as usize;
        let start = rng.next_u64().is_multiple_of(2);
        let end = rng.next_u64().is_multiple_of(2);
        let d = usize::from(start) + usize::from(end);
        let count = 2.max(p + 1 - d) + (rng.next_u64() % 8) as usize;
        let mut params = vec![rng.range(-5.0, 5.0)];
        for _ in 1..count {
            // Gaps spanning six orders of magnitude.
            let gap = 10f64.powf(rng.range(-3.0, 3.0));
            params.push(params.last().unwrap() + gap);
        }
        let u = knots::averaging_knots(&params, p, start, end);
        let mut sites = params.clone();
        if start {
            sites.insert(0, params[0]);
        }
        if end {
            sites.push(params[count - 1]);
        }
        assert_eq!(u.len(), sites.len() + p + 1);
        let (a, b) = (u[p], u[sites.len()]);
        assert_eq!((a, b), (params[0], params[count - 1]));
        for (i, &tau) in sites.iter().enumerate() {
            let lo_ok = u[i] < tau || (u[i] == a && tau == a);
            let hi_ok = tau < u[i + p + 1] || (u[i + p + 1] == b && tau == b);
            assert!(
                lo_ok && hi_ok,
                "p = {p}, start {start}, end {end}, i = {i}: τ = {tau} vs ({}, {}); knots {u:?}",
                u[i],
                u[i + p + 1]
            );
        }
        // Non-decreasing, and no knot repeated more than p + 1 times.
        assert!(u.windows(2).all(|w| w[0] <= w[1]), "{u:?}");
        assert!(u.windows(p + 2).all(|w| w[0] < w[p + 1]), "{u:?}");
    }
}

#[test]
fn moderate_random_spacing_solves_for_every_degree() {
    let mut rng = Rng::new(4);
    for _ in 0..300 {
        let p = 1 + (rng.next_u64() % 10) as usize;
        let start = rng.next_u64().is_multiple_of(2);
        let end = rng.next_u64().is_multiple_of(2);
        let d = usize::from(start) + usize::from(end);
        let count = 2.max(p + 1 - d) + (rng.next_u64() % 8) as usize;
        let mut params = vec![0.0];
        for _ in 1..count {
            let gap = 10f64.powf(rng.range(-0.5, 0.5));
            params.push(params.last().unwrap() + gap);
        }
        let points: Vec<DVec2> = (0..count).map(|_| rng.point2(1.0)).collect();
        let options = InterpolationOptions {
            start_derivative: start.then_some(DVec2::new(1.0, 0.0)),
            end_derivative: end.then_some(DVec2::new(0.0, 1.0)),
            ..options2()
        };
        let c = interpolate_bspline(&points, p, &params, &options).unwrap();
        for (&t, &q) in params.iter().zip(&points) {
            assert_close2(c.evaluate(t).unwrap(), q, 1e-10, &format!("p = {p}"));
        }
    }
}

#[test]
fn schoenberg_whitney_violations_are_refused() {
    let points = pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (3.0, 1.0), (4.0, 0.0)]);
    let params = [0.0, 1.0, 2.0, 3.0, 4.0];
    // Quadratic, 5 control points, interior knots 0.25 and 0.5: N_1's support (0, 0.5) misses
    // t_1 = 1.
    let options = InterpolationOptions {
        knots: Some(vec![0.0, 0.0, 0.0, 0.25, 0.5, 4.0, 4.0, 4.0]),
        ..options2()
    };
    let e = interpolate_bspline(&points, 2, &params, &options).unwrap_err();
    assert_eq!(
        e,
        Error::Interp(InterpError::SchoenbergWhitney {
            index: 1,
            param: 1.0,
            lo: 0.0,
            hi: 0.5,
            degree: 2
        })
    );
    assert!(e.to_string().contains("singular"), "{e}");
    // Knots of the wrong count.
    let options = InterpolationOptions {
        knots: Some(vec![0.0, 0.0, 0.0, 0.0, 4.0, 4.0, 4.0, 4.0]),
        ..options2()
    };
    let e = interpolate_bspline(&points, 3, &params, &options).unwrap_err();
    assert!(matches!(e, Error::KnotCount { expected: 9, .. }), "{e:?}");
}

// --- Least squares. ---------------------------------------------------------------------------

#[test]
fn least_squares_with_every_point_is_the_interpolant() {
    let mut rng = Rng::new(5);
    for p in 1..=5 {
        let (points, params) = random_data(&mut rng, p + 6);
        let fit = approximate_bspline(&points, p, points.len(), &params, None).unwrap();
        let interp = interpolate_bspline(&points, p, &params, &options2()).unwrap();
        assert_eq!(fit.knots(), interp.knots());
        let tol = 1e-11 * scale(&points);
        for (a, b) in fit.control_points().iter().zip(interp.control_points()) {
            assert_close2(*a, b, tol, &format!("p = {p}"));
        }
    }
}

#[test]
fn least_squares_ends_are_exact_and_the_residual_is_orthogonal() {
    let mut rng = Rng::new(9);
    for p in 1..=6 {
        for count in [p + 1, p + 2, p + 5] {
            let (points, params) = random_data(&mut rng, p + 12);
            let c = approximate_bspline(&points, p, count, &params, None).unwrap();
            let cp = c.control_points();
            assert_eq!(cp.len(), count);
            let m = points.len() - 1;
            assert_eq!(cp[0], points[0]);
            assert_eq!(cp[count - 1], points[m]);
            assert_close2(c.evaluate(params[m]).unwrap(), points[m], 1e-12, "end");
            // Normal equations: Σ_k N_i(t_k) (C(t_k) − Q_k) = 0 for each interior unknown i.
            let mut sums = vec![DVec2::ZERO; count];
            let mut weights = vec![0.0f64; count];
            for k in 1..m {
                let basis = c.basis(params[k]).unwrap();
                let r = c.evaluate(params[k]).unwrap() - points[k];
                for (i, &b) in basis.iter().enumerate() {
                    sums[i] += r * b;
                    weights[i] += b.abs() * r.length();
                }
            }
            for i in 1..count - 1 {
                assert!(
                    sums[i].length() <= 1e-11 * (1.0 + weights[i]) * scale(&points),
                    "p = {p}, count {count}: (Nᵀ(NP − R))_{i} = {}",
                    sums[i]
                );
            }
        }
    }
}

#[test]
fn least_squares_count_out_of_range_is_refused() {
    let mut rng = Rng::new(1);
    let (points, params) = random_data(&mut rng, 6);
    for count in [3, 7] {
        let e = approximate_bspline(&points, 3, count, &params, None).unwrap_err();
        assert_eq!(
            e,
            Error::Interp(InterpError::ControlCountOutOfRange {
                count,
                min: 4,
                max: 6
            })
        );
    }
}

// --- Closed curves. -----------------------------------------------------------------------------

fn closed_data(rng: &mut Rng, distinct: usize) -> (Vec<DVec2>, Vec<f64>) {
    let (mut points, mut params) = random_data(rng, distinct + 1);
    points[distinct] = points[0];
    params[distinct] = params[distinct - 1] + 1.0;
    (points, params)
}

#[test]
fn closed_curves_interpolate_and_join_with_c_p_minus_1() {
    let mut rng = Rng::new(21);
    for p in 1..=10 {
        for distinct in [p.max(2), p + 3, 2 * p + 9] {
            let (points, params) = closed_data(&mut rng, distinct);
            let options = InterpolationOptions {
                closed: true,
                ..options2()
            };
            let c = interpolate_bspline(&points, p, &params, &options).unwrap();
            assert_eq!(c.wrapped(), p);
            let (a, b) = c.domain();
            assert_eq!((a, b), (params[0], params[distinct]));
            let tol = 1e-11 * scale(&points);
            for (i, (&t, &q)) in params.iter().zip(&points).enumerate() {
                assert_close2(
                    c.evaluate(t).unwrap(),
                    q,
                    tol,
                    &format!("p = {p}, C(t_{i})"),
                );
            }
            for order in 1..p {
                let (d0, d1) = (
                    c.derivative(a, order).unwrap(),
                    c.derivative(b, order).unwrap(),
                );
                let size = d0.length().max(d1.length()).max(1.0);
                assert_close2(
                    d0,
                    d1,
                    1e-9 * size,
                    &format!("p = {p}, N = {distinct}: C^({order}) at the seam"),
                );
            }
        }
    }
}

#[test]
fn closed_needs_the_last_point_equal_to_the_first() {
    let points = pts2(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 1e-9)]);
    let options = InterpolationOptions {
        closed: true,
        ..options2()
    };
    let e = interpolate_bspline(&points, 3, &[0.0, 1.0, 2.0, 3.0, 4.0], &options).unwrap_err();
    assert_eq!(e, Error::Interp(InterpError::NotClosed { last: 4 }));
}

// --- The banded solve against a dense solve written here. -------------------------------------

/// Gaussian elimination with partial pivoting on a dense matrix (rows `n × n`, one right side).
fn dense_solve(mut a: Vec<f64>, mut b: Vec<f64>, n: usize) -> Vec<f64> {
    for c in 0..n {
        let r = (c..n)
            .max_by(|&x, &y| a[x * n + c].abs().total_cmp(&a[y * n + c].abs()))
            .unwrap();
        for j in 0..n {
            a.swap(c * n + j, r * n + j);
        }
        b.swap(c, r);
        for r in c + 1..n {
            let f = a[r * n + c] / a[c * n + c];
            for j in c..n {
                a[r * n + j] -= f * a[c * n + j];
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = vec![0.0; n];
    for i in (0..n).rev() {
        let s: f64 = (i + 1..n).map(|j| a[i * n + j] * x[j]).sum();
        x[i] = (b[i] - s) / a[i * n + i];
    }
    x
}

#[test]
fn banded_solve_matches_a_dense_solve() {
    let mut rng = Rng::new(13);
    for p in 1..=7 {
        for closed in [false, true] {
            let (points, params) = if closed {
                closed_data(&mut rng, p + 8)
            } else {
                random_data(&mut rng, p + 8)
            };
            let options = InterpolationOptions {
                start_derivative: (!closed).then_some(DVec2::new(3.0, -1.0)),
                end_derivative: (!closed && p > 1).then_some(DVec2::new(-2.0, 2.0)),
                closed,
                ..options2()
            };
            let s = interpolation_system(&points, p, &params, &options).unwrap();
            for k in 0..2 {
                let rhs: Vec<f64> = s.rhs.iter().map(|v| v.to_array()[k]).collect();
                let x = dense_solve(s.matrix.clone(), rhs, s.size);
                for (i, (&xi, sol)) in x.iter().zip(&s.solution).enumerate() {
                    assert_close(
                        sol.to_array()[k],
                        xi,
                        1e-11 * (1.0 + xi.abs()),
                        &format!("p = {p}, closed {closed}: x_{i}[{k}]"),
                    );
                }
            }
        }
    }
}

#[test]
fn system_above_64_unknowns_is_too_large() {
    let mut rng = Rng::new(2);
    let (points, params) = random_data(&mut rng, 65);
    let e = interpolation_system(&points, 3, &params, &options2()).unwrap_err();
    assert!(
        matches!(
            e,
            Error::TooLarge {
                value: 65,
                max: 64,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(interp::interpolate_bspline(&points, 3, &params, &options2()).is_ok());
}

#[allow(dead_code)]
fn unused(_: BSplineCurve<DVec2>) {}

// --- scipy fixtures (tests/fixtures/make_interp_bspline_fixtures.py). ---------------------------

/// One fixture case as read from the file.
#[derive(Default)]
struct Case {
    kind: String,
    degree: usize,
    count: usize,
    params: Vec<f64>,
    points: Vec<DVec2>,
    derivs: Vec<f64>,
    knots: Vec<f64>,
    control: Vec<DVec2>,
    values: Vec<(f64, DVec2)>,
}

impl Case {
    /// Our curve for the case, with default knots (the fixture's knots were computed by the
    /// script from the same rules, or by scipy for periodic curves).
    fn ours(&self) -> BSplineCurve<DVec2> {
        let (p, d) = (self.degree, &self.derivs);
        let start = matches!(self.kind.as_str(), "start" | "both").then(|| DVec2::new(d[0], d[1]));
        let end = matches!(self.kind.as_str(), "end" | "both").then(|| DVec2::new(d[2], d[3]));
        if self.kind == "lsq" {
            return approximate_bspline(&self.points, p, self.count, &self.params, None).unwrap();
        }
        let options = InterpolationOptions {
            start_derivative: start,
            end_derivative: end,
            closed: self.kind == "periodic",
            ..options2()
        };
        interpolate_bspline(&self.points, p, &self.params, &options).unwrap()
    }

    fn check(&self) -> usize {
        let what = format!("{} p = {} count {}", self.kind, self.degree, self.count);
        let c = self.ours();
        let size = scale(&self.points).max(scale(&self.control));
        let knots = c.knots().as_slice();
        assert_eq!(knots.len(), self.knots.len(), "{what}: knots");
        // scipy makes a periodic linear spline as the open polyline (knots x_0, x…, x_n, its
        // special case for k = 1); only the two outermost knots differ from the periodic ones,
        // and they do not act on the domain.
        let outer = usize::from(self.kind == "periodic" && self.degree == 1);
        let inner = outer..knots.len() - outer;
        for (i, (&a, &b)) in knots[inner.clone()]
            .iter()
            .zip(&self.knots[inner])
            .enumerate()
        {
            assert_close(
                a,
                b,
                1e-13 * (1.0 + b.abs()),
                &format!("{what}: u_{}", i + outer),
            );
        }
        let cp = c.control_points();
        assert_eq!(cp.len(), self.control.len(), "{what}: control points");
        for (i, (&a, &b)) in cp.iter().zip(&self.control).enumerate() {
            assert_close2(a, b, 1e-12 * size, &format!("{what}: P_{i}"));
        }
        for &(u, v) in &self.values {
            assert_close2(
                c.evaluate(u).unwrap(),
                v,
                1e-12 * size,
                &format!("{what}: C({u})"),
            );
        }
        cp.len() + self.values.len()
    }
}

#[test]
fn fixtures_from_scipy_make_interp_spline_and_numpy_least_squares() {
    let text = include_str!("fixtures/interp_bspline_scipy.txt");
    let mut cases: Vec<Case> = Vec::new();
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
    {
        let mut words = line.split_whitespace();
        let tag = words.next().unwrap();
        if tag == "case" {
            let kind = words.next().unwrap().to_string();
            let degree = words.next().unwrap().parse().unwrap();
            let count = words.next().unwrap().parse().unwrap();
            cases.push(Case {
                kind,
                degree,
                count,
                ..Case::default()
            });
            continue;
        }
        let nums: Vec<f64> = words.map(|w| w.parse().unwrap()).collect();
        let case = cases.last_mut().unwrap();
        let pairs =
            |v: &[f64]| -> Vec<DVec2> { v.chunks(2).map(|c| DVec2::new(c[0], c[1])).collect() };
        match tag {
            "params" => case.params = nums,
            "points" => case.points = pairs(&nums),
            "derivs" => case.derivs = nums,
            "knots" => case.knots = nums,
            "control" => case.control = pairs(&nums),
            "value" => case.values.push((nums[0], DVec2::new(nums[1], nums[2]))),
            other => panic!("unknown fixture line {other}"),
        }
    }
    let kinds: std::collections::BTreeSet<&str> = cases.iter().map(|c| c.kind.as_str()).collect();
    assert_eq!(
        kinds.into_iter().collect::<Vec<_>>(),
        ["both", "end", "interp", "lsq", "periodic", "start"]
    );
    let checked: usize = cases.iter().map(Case::check).sum();
    assert!(checked > 1000, "only {checked} fixture values");
}

// --- More closed-curve and option cases. --------------------------------------------------------

#[test]
fn closed_uniform_cubic_rows_are_one_sixth_two_thirds_one_sixth() {
    // Uniform params and an odd degree: scipy's periodic knots are the integers, every site is
    // a knot, and row i holds N(t_i) = 1/6, 2/3, 1/6 in columns i, i+1, i+2 (mod N).
    let n = 6;
    let mut points: Vec<DVec2> = (0..n)
        .map(|i| DVec2::new((i as f64).cos(), (i as f64).sin()))
        .collect();
    points.push(points[0]);
    let params: Vec<f64> = (0..=n).map(|i| i as f64).collect();
    let options = InterpolationOptions {
        closed: true,
        ..options2()
    };
    let s = interpolation_system(&points, 3, &params, &options).unwrap();
    assert_eq!(s.size, n);
    assert_eq!(s.rows, vec![RowKind::Point; n]);
    for i in 0..n {
        for j in 0..n {
            let want = match (j + n - i) % n {
                0 | 2 => 1.0 / 6.0,
                1 => 2.0 / 3.0,
                _ => 0.0,
            };
            assert_close(s.matrix[i * n + j], want, 1e-15, &format!("A[{i}][{j}]"));
        }
    }
    let knots: Vec<f64> = (-3..=n as i32 + 3).map(f64::from).collect();
    assert_eq!(s.knots, knots);
    // The same curve as BSplineCurve::closed (uniform knots u_j = j) on the distinct control
    // points, shifted by p = 3 in the parameter.
    let c = interpolate_bspline(&points, 3, &params, &options).unwrap();
    let reference = BSplineCurve::closed(s.solution.clone(), 3, None).unwrap();
    for k in 0..=60 {
        let t = k as f64 * 0.1;
        assert_close2(
            c.evaluate(t).unwrap(),
            reference.evaluate(t + 3.0).unwrap(),
            1e-14,
            &format!("t = {t}"),
        );
    }
}

#[test]
fn closed_curves_in_3d() {
    let mut rng = Rng::new(31);
    let mut points: Vec<DVec3> = (0..7).map(|_| rng.point3(4.0)).collect();
    points.push(points[0]);
    let params: Vec<f64> = (0..8).map(|i| i as f64 * 0.75).collect();
    let options = InterpolationOptions {
        closed: true,
        ..InterpolationOptions::default()
    };
    let c = interpolate_bspline(&points, 4, &params, &options).unwrap();
    for (&t, &q) in params.iter().zip(&points) {
        assert_close3(c.evaluate(t).unwrap(), q, 1e-12, "C(t_i)");
    }
    let (a, b) = c.domain();
    for order in 1..4 {
        let (d0, d1) = (
            c.derivative(a, order).unwrap(),
            c.derivative(b, order).unwrap(),
        );
        assert_close3(
            d0,
            d1,
            1e-9 * d0.length().max(1.0),
            &format!("order {order}"),
        );
    }
}

#[test]
fn explicit_knots_with_derivatives_and_params_outside_their_domain() {
    let points = pts2(&[(0.0, 0.0), (1.0, 2.0), (3.0, 1.0), (4.0, 3.0)]);
    let params = [0.0, 1.0, 2.0, 3.0];
    // Cubic with both derivatives: 6 unknowns, 10 knots, interior 1 and 2.
    let options = InterpolationOptions {
        knots: Some(vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0, 3.0]),
        start_derivative: Some(DVec2::new(1.0, 1.0)),
        end_derivative: Some(DVec2::new(1.0, -1.0)),
        ..options2()
    };
    let c = interpolate_bspline(&points, 3, &params, &options).unwrap();
    for (&t, &q) in params.iter().zip(&points) {
        assert_close2(c.evaluate(t).unwrap(), q, 1e-13, "C(t_i)");
    }
    assert_close2(
        c.derivative(0.0, 1).unwrap(),
        DVec2::new(1.0, 1.0),
        1e-13,
        "C'(0)",
    );
    assert_close2(
        c.derivative(3.0, 1).unwrap(),
        DVec2::new(1.0, -1.0),
        1e-13,
        "C'(3)",
    );
    // Knots whose domain stops at 2.5 leave t_3 = 3 outside.
    let options = InterpolationOptions {
        knots: Some(vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.5, 2.5, 2.5, 2.5]),
        ..options
    };
    let e = interpolate_bspline(&points, 3, &params, &options).unwrap_err();
    assert_eq!(
        e.to_string(),
        "params[3]: t = 3 is outside the domain [0, 2.5]"
    );
}

#[test]
fn degree_one_with_end_derivatives_adds_a_vertex_per_derivative() {
    let points = pts2(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0)]);
    let params = [0.0, 2.0, 4.0];
    let options = InterpolationOptions {
        start_derivative: Some(DVec2::new(0.0, 1.0)),
        ..options2()
    };
    let c = interpolate_bspline(&points, 1, &params, &options).unwrap();
    // Knots 0 0 1 2 4 4: the extra vertex at u = 1 is P_0 + 1·D_0 = (0, 1).
    assert_eq!(c.knots().as_slice(), [0.0, 0.0, 1.0, 2.0, 4.0, 4.0]);
    assert_eq!(
        c.control_points(),
        pts2(&[(0.0, 0.0), (0.0, 1.0), (2.0, 0.0), (2.0, 2.0)])
    );
}

#[test]
fn two_points_and_both_derivatives_make_the_cubic_hermite_curve() {
    // Knots 0 0 0 0 1 1 1 1: the Bézier form q_1 = p_0 + D_0/3, q_2 = p_1 − D_1/3.
    let points = pts2(&[(0.0, 0.0), (3.0, 0.0)]);
    let options = InterpolationOptions {
        start_derivative: Some(DVec2::new(0.0, 3.0)),
        end_derivative: Some(DVec2::new(0.0, -3.0)),
        ..options2()
    };
    let c = interpolate_bspline(&points, 3, &[0.0, 1.0], &options).unwrap();
    let want = pts2(&[(0.0, 0.0), (0.0, 1.0), (3.0, 1.0), (3.0, 0.0)]);
    for (a, b) in c.control_points().iter().zip(&want) {
        assert_close2(*a, *b, 1e-15, "Bézier point");
    }
}

#[test]
fn validation_follows_the_documented_order() {
    let nan = pts2(&[(0.0, f64::NAN), (1.0, 1.0)]);
    let closed_conflict = InterpolationOptions {
        closed: true,
        end_derivative: Some(DVec2::ZERO),
        ..options2()
    };
    // Coordinates before the degree, the degree before the point count, the count before the
    // params, the params before the options, options before the closing point.
    let e = interpolate_bspline(&nan, 0, &[0.0], &closed_conflict).unwrap_err();
    assert!(matches!(e, Error::NotFinite { .. }), "{e:?}");
    let two = pts2(&[(0.0, 0.0), (1.0, 1.0)]);
    let e = interpolate_bspline(&two, 11, &[0.0], &closed_conflict).unwrap_err();
    assert_eq!(
        e,
        Error::DegreeOutOfRange {
            degree: 11,
            max: 10
        }
    );
    let e = interpolate_bspline(&two, 3, &[0.0], &options2()).unwrap_err();
    assert!(
        matches!(
            e,
            Error::TooFewDataPoints {
                needed: 4,
                got: 2,
                ..
            }
        ),
        "{e:?}"
    );
    let four = pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (3.0, 3.0)]);
    let e = interpolate_bspline(&four, 2, &[0.0, 1.0, 1.0], &closed_conflict).unwrap_err();
    assert_eq!(
        e,
        Error::Interp(InterpError::ParamCount {
            params: 3,
            points: 4
        })
    );
    let e = interpolate_bspline(&four, 2, &[0.0, 1.0, 1.0, 2.0], &closed_conflict).unwrap_err();
    assert!(
        matches!(
            e,
            Error::Interp(InterpError::ParamsNotIncreasing { index: 2, .. })
        ),
        "{e:?}"
    );
    let e = interpolate_bspline(&four, 2, &[0.0, 1.0, 2.0, 3.0], &closed_conflict).unwrap_err();
    assert!(matches!(e, Error::ConflictingOptions { .. }), "{e:?}");
    let closed = InterpolationOptions {
        closed: true,
        ..options2()
    };
    let e = interpolate_bspline(&four, 2, &[0.0, 1.0, 2.0, 3.0], &closed).unwrap_err();
    assert_eq!(e, Error::Interp(InterpError::NotClosed { last: 3 }));
    let bad_derivative = InterpolationOptions {
        start_derivative: Some(DVec2::new(f64::INFINITY, 0.0)),
        ..options2()
    };
    let e = interpolate_bspline(&four, 2, &[0.0, 1.0, 2.0, 3.0], &bad_derivative).unwrap_err();
    assert!(
        e.to_string().contains("startDerivative: coordinate 0"),
        "{e}"
    );
}

#[test]
fn least_squares_with_explicit_knots() {
    let mut rng = Rng::new(17);
    let (points, params) = random_data(&mut rng, 12);
    let (a, b) = (params[0], params[11]);
    let mid = 0.5 * (a + b);
    // Cubic, 6 control points, interior knots at 1/3 and 1/2 of the way.
    let knots = [a, a, a, a, a + (b - a) / 3.0, mid, b, b, b, b];
    let c = approximate_bspline(&points, 3, 6, &params, Some(&knots)).unwrap();
    assert_eq!(c.knots().as_slice(), knots);
    assert_eq!(c.control_points()[0], points[0]);
    assert_eq!(c.control_points()[5], points[11]);
    // A knot vector whose last spans hold no parameter: N_5 = 1 only at b, so N_4 and N_5 cannot
    // both be matched with parameters (the greedy subsequence check names N_4).
    let crowded = [a, a, a, a, b - 1e-9, b - 5e-10, b, b, b, b];
    let e = approximate_bspline(&points, 3, 6, &params, Some(&crowded)).unwrap_err();
    assert!(
        matches!(e, Error::Interp(InterpError::SchoenbergWhitney { .. })),
        "{e:?}"
    );
}

#[test]
fn least_squares_in_3d_with_two_control_points_is_the_chord() {
    let points = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 5.0, 2.0),
        DVec3::new(2.0, -1.0, 0.0),
        DVec3::new(3.0, 3.0, 3.0),
    ];
    let c = approximate_bspline(&points, 1, 2, &[0.0, 1.0, 2.0, 3.0], None).unwrap();
    assert_eq!(c.control_points(), vec![points[0], points[3]]);
}

#[test]
fn least_squares_default_knots_leave_a_parameter_for_every_basis_function() {
    // NURBS Book eq. 9.69 puts a parameter in every knot span, so some increasing choice of
    // parameters satisfies Schoenberg–Whitney and the normal equations are positive definite.
    let mut rng = Rng::new(23);
    for _ in 0..2000 {
        let p = 1 + (rng.next_u64() % 10) as usize;
        let points = p + 1 + (rng.next_u64() % 30) as usize;
        let count = p + 1 + (rng.next_u64() % (points - p) as u64) as usize;
        let mut params = vec![0.0];
        for _ in 1..points {
            let gap = 10f64.powf(rng.range(-2.0, 2.0));
            params.push(params.last().unwrap() + gap);
        }
        let u = knots::least_squares_knots(&params, p, count);
        assert_eq!(u.len(), count + p + 1);
        assert!(u.windows(2).all(|w| w[0] <= w[1]), "{u:?}");
        knots::check_schoenberg_whitney_subsequence(&u, p, count, &params)
            .unwrap_or_else(|e| panic!("p = {p}, {points} points, count {count}: {e}"));
    }
}
