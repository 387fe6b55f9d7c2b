//! Typed parametric curves (syllabus 1) against independent expectations: sympy's derivatives,
//! Frenet frames and exact Bézier forms (tests/fixtures/make_parametric_fixtures.py), the
//! notes' exercise answers and worked example, closed forms (a helix's curvature and torsion),
//! and the plot's promises checked by dense evaluation. Runs natively and in Node.

use splinelab::expr::Problem;
use splinelab::parametric::{ParametricCurve, PieceSource};
use splinelab::Error;
use std::f64::consts::PI;
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

const FIXTURES: &str = include_str!("fixtures/parametric_sympy.txt");

fn piece(x: &str, y: &str, from: &str, to: &str) -> PieceSource {
    PieceSource {
        x: x.into(),
        y: y.into(),
        z: None,
        from: from.into(),
        to: to.into(),
    }
}

fn curve(pieces: &[(&str, &str, &str, &str)]) -> ParametricCurve {
    let pieces: Vec<PieceSource> = pieces.iter().map(|p| piece(p.0, p.1, p.2, p.3)).collect();
    ParametricCurve::new(&pieces, &[]).unwrap()
}

/// The fixture lines of a kind, split in words.
fn lines<'a>(kind: &'a str) -> impl Iterator<Item = Vec<&'a str>> + 'a {
    FIXTURES
        .lines()
        .filter(move |l| l.starts_with(&format!("{kind} ")))
        .map(|l| l.split_whitespace().collect())
}

/// The texts of a fixture curve.
fn texts(name: &str) -> Vec<String> {
    let line = FIXTURES
        .lines()
        .find(|l| l.starts_with(&format!("curve {name} ")))
        .unwrap();
    let rest = line.splitn(4, ' ').nth(3).unwrap();
    rest.split(" ; ").map(str::to_string).collect()
}

fn fixture_curve(name: &str, from: &str, to: &str, params: &[(String, f64)]) -> ParametricCurve {
    let t = texts(name);
    let p = PieceSource {
        x: t[0].clone(),
        y: t[1].clone(),
        z: t.get(2).cloned(),
        from: from.into(),
        to: to.into(),
    };
    ParametricCurve::new(&[p], params).unwrap()
}

#[track_caller]
fn close(a: f64, b: f64, rel: f64) {
    let scale = a.abs().max(b.abs()).max(1.0);
    assert!((a - b).abs() <= rel * scale, "{a} vs {b} (diff {})", a - b);
}

fn problem(err: Error) -> (Problem, Option<usize>, Option<String>, usize, usize) {
    match err {
        Error::Expression { error } => {
            let e = *error;
            (e.problem, e.piece, e.field, e.start, e.end)
        }
        other => panic!("expected an expression error, got {other:?}"),
    }
}

#[test]
fn derivatives_match_sympy_to_order_8() {
    let curves = [
        (
            "lissajous",
            fixture_curve("lissajous", "0", "2pi", &[("a".into(), 2.0)]),
        ),
        ("nested", fixture_curve("nested", "0", "2", &[])),
        ("notes", fixture_curve("notes", "0", "1", &[])),
    ];
    let mut checked = 0;
    for w in lines("deriv") {
        let c = &curves.iter().find(|(n, _)| *n == w[1]).unwrap().1;
        let t: f64 = w[2].parse().unwrap();
        let k: usize = w[3].parse().unwrap();
        let got = c.derivative(t, k).unwrap();
        for (g, e) in got.iter().zip(&w[4..]) {
            close(*g, e.parse().unwrap(), 1e-11);
        }
        checked += 1;
    }
    assert_eq!(checked, 90);
}

#[test]
fn a_parameter_moves_in_place() {
    let mut c = fixture_curve("lissajous", "0", "2pi", &[("a".into(), 2.0)]);
    close(c.evaluate(0.3).unwrap()[0], (0.6f64).sin(), 1e-15);
    c.set_parameter("a", 3.0).unwrap();
    close(c.evaluate(0.3).unwrap()[0], (0.9f64).sin(), 1e-15);
    close(
        c.derivative(0.3, 1).unwrap()[0],
        3.0 * (0.9f64).cos(),
        1e-14,
    );
    let (p, ..) = problem(c.set_parameter("b", 1.0).unwrap_err());
    assert_eq!(p.code(), "unknown-parameter");
    assert!(c.set_parameter("a", f64::NAN).is_err());
    assert_eq!(c.parameter_values(), &[3.0]);
}

#[test]
fn the_frenet_frame_matches_sympy_and_the_helix() {
    let c = fixture_curve("twisted", "0", "2", &[]);
    for w in lines("frame") {
        let t: f64 = w[2].parse().unwrap();
        let e: Vec<f64> = w[3..].iter().map(|v| v.parse().unwrap()).collect();
        let f = c.frame(t).unwrap();
        close(f.curvature, e[0], 1e-12);
        close(f.torsion, e[1], 1e-12);
        for (g, x) in f
            .tangent
            .iter()
            .chain(&f.normal)
            .chain(&f.binormal)
            .zip(&e[2..])
        {
            close(*g, *x, 1e-12);
        }
    }
    // A helix (r cos t, r sin t, h t): κ = r/(r² + h²), τ = h/(r² + h²) everywhere.
    let helix = ParametricCurve::new(
        &[PieceSource {
            x: "2cos(t)".into(),
            y: "2sin(t)".into(),
            z: Some("t/2".into()),
            from: "0".into(),
            to: "4pi".into(),
        }],
        &[],
    )
    .unwrap();
    for t in [0.0, 1.0, 7.5] {
        let f = helix.frame(t).unwrap();
        close(f.curvature, 2.0 / 4.25, 1e-14);
        close(f.torsion, 0.5 / 4.25, 1e-14);
    }
    // 2D: the unit circle turns left with curvature 1; the normal points to the centre.
    let circle = curve(&[("cos(t)", "sin(t)", "0", "2pi")]);
    let f = circle.frame(1.0).unwrap();
    close(f.curvature, 1.0, 1e-14);
    close(f.normal[0], -(1.0f64).cos(), 1e-14);
    close(f.normal[1], -(1.0f64).sin(), 1e-14);
}

#[test]
fn the_notes_polynomial_has_the_notes_bezier_form() {
    let c = curve(&[("6.5t^5 - 7.2t^3 + 3t^2 - 2.1t - 5", "t", "0", "1")]);
    assert!(c.is_polynomial(0).unwrap());
    let form = c.to_bezier(0).unwrap();
    let xs: Vec<String> = form
        .exact
        .unwrap()
        .iter()
        .step_by(2)
        .map(ToString::to_string)
        .collect();
    assert_eq!(
        xs,
        ["-5", "-271/50", "-277/50", "-152/25", "-194/25", "-24/5"]
    );
    // sympy on another interval, y of degree 2 raised to the piece's degree 3.
    for w in lines("bezier") {
        let c = fixture_curve(w[1], w[2], w[3], &[]);
        let got: Vec<String> = c
            .to_bezier(0)
            .unwrap()
            .exact
            .unwrap()
            .iter()
            .map(ToString::to_string)
            .collect();
        assert_eq!(got, w[4..], "{}", w[1]);
    }
    let circle = curve(&[("cos(t)", "sin(t)", "0", "2pi")]);
    assert!(!circle.is_polynomial(0).unwrap());
    let (p, piece, ..) = problem(circle.to_bezier(0).unwrap_err());
    assert_eq!((p.code(), piece), ("not-polynomial", Some(0)));
}

/// The exercise of the Italian notes (004): x = 1 − t² on [0, 1), then three second pieces.
#[test]
fn the_notes_exercise_joints_are_proven() {
    let cases = [
        ("2 - t^2", -1.0, Some(0)),     // not C0: 0 against 1
        ("t^2 - 4t + 3", 1.0, Some(2)), // C1: x″ = −2 against 2
        ("t^2 - 2t + 1", 0.0, Some(1)), // C0 not C1: x′ = −2 against 0
    ];
    for (second, c, order) in cases {
        let curve = curve(&[("1 - t^2", "t", "0", "1"), (second, "t", "1", "2")]);
        let j = &curve.joints()[0];
        assert_eq!((j.c, j.exact, j.order), (c, true, order), "{second}");
        assert_eq!(j.t, 1.0);
    }
    // The one-sided values of the C1 case at order 2: x″(1⁻) = −2, x″(1⁺) = 2, y″ = 0.
    let c1 = curve(&[("1 - t^2", "t", "0", "1"), ("t^2 - 4t + 3", "t", "1", "2")]);
    let j = &c1.joints()[0];
    assert_eq!(j.left.as_deref(), Some(&[-2.0, 0.0][..]));
    assert_eq!(j.right.as_deref(), Some(&[2.0, 0.0][..]));
}

#[test]
fn geometric_continuity_is_told_apart_from_parametric() {
    // Same direction, double speed: G1 (and G∞ as one line) but not C1.
    let line = curve(&[("t", "t", "0", "1"), ("2t - 1", "2t - 1", "1", "2")]);
    let j = &line.joints()[0];
    assert_eq!((j.c, j.g, j.exact), (0.0, 3.0, true));
    // A corner: directions differ, G0 only.
    let corner = curve(&[("t", "0", "0", "1"), ("1", "t - 1", "1", "2")]);
    let j = &corner.joints()[0];
    assert_eq!((j.c, j.g), (0.0, 0.0));
    // Reversed direction at the joint: not G1.
    let back = curve(&[("t", "0", "0", "1"), ("2 - t", "0", "1", "2")]);
    assert_eq!(back.joints()[0].g, 0.0);
    // A parabola continued by its own polynomial: C∞, shown as infinity.
    let same = curve(&[("t", "t^2", "0", "1"), ("t", "t^2", "1", "2")]);
    let j = &same.joints()[0];
    assert_eq!(
        (j.c, j.g, j.exact, j.order),
        (f64::INFINITY, f64::INFINITY, true, None)
    );
    // A circle arc continued at twice the angular speed: G∞ geometrically (G3 reported), C0.
    let arcs = curve(&[
        ("cos(t)", "sin(t)", "0", "pi/2"),
        ("cos(2t - pi/2)", "sin(2t - pi/2)", "pi/2", "pi"),
    ]);
    let j = &arcs.joints()[0];
    assert_eq!((j.c, j.g, j.exact, j.order), (0.0, 3.0, false, Some(1)));
    // The cubic spline pieces x = t³ then a polynomial matching value, x′, x″ at 1: C2 not C3.
    let c2 = curve(&[("t", "t^3", "0", "1"), ("t", "t^3 + (t - 1)^3", "1", "2")]);
    let j = &c2.joints()[0];
    assert_eq!((j.c, j.exact, j.order), (2.0, true, Some(3)));
}

#[test]
fn transcendental_joints_use_a_scale_free_tolerance() {
    // sin and cos meet with equal derivatives to all orders at t = pi/2 (cos(t − π/2) = sin t).
    let smooth = curve(&[
        ("t", "sin(t)", "0", "pi/2"),
        ("t", "cos(t - pi/2)", "pi/2", "pi"),
    ]);
    let j = &smooth.joints()[0];
    assert_eq!((j.c, j.g, j.exact, j.order), (3.0, 3.0, false, None));
    // The same curve scaled by 1e6 in space and 1e-3 in t gives the same verdict.
    let scaled = curve(&[
        ("t", "1000000 sin(1000t)", "0", "pi/2000"),
        ("t", "1000000 cos(1000t - pi/2)", "pi/2000", "pi/1000"),
    ]);
    let j = &scaled.joints()[0];
    assert_eq!((j.c, j.g), (3.0, 3.0));
    // A jump of 1e-3 is a jump, proven by disjoint enclosures.
    let jump = curve(&[("t", "sin(t)", "0", "1"), ("t", "sin(t) + 0.001", "1", "2")]);
    let j = &jump.joints()[0];
    assert_eq!((j.c, j.exact, j.disjoint), (-1.0, false, true));
}

#[test]
fn evaluation_takes_the_right_piece_at_a_joint() {
    let c = curve(&[("1 - t^2", "t", "0", "1"), ("2 - t^2", "t", "1", "2")]);
    assert_eq!(c.evaluate(1.0).unwrap(), vec![1.0, 1.0]);
    assert_eq!(c.evaluate(0.5).unwrap(), vec![0.75, 0.5]);
    assert_eq!(c.evaluate(2.0).unwrap(), vec![-2.0, 2.0]);
    assert!(matches!(
        c.evaluate(2.5),
        Err(Error::ParameterOutOfRange { .. })
    ));
    assert!(c.evaluate(f64::NAN).is_err());
    assert!(c.derivative(0.5, 9).is_err());
    assert_eq!(c.domain(), (0.0, 2.0));
    // Undefined points are NaN.
    let log = curve(&[("t", "ln(t)", "0", "1")]);
    assert!(log.evaluate(0.0).unwrap()[1].is_nan());
    assert!(log.derivative(0.0, 1).unwrap()[1].is_nan());
    let root = curve(&[("t", "sqrt(t - 1)", "0", "2")]);
    assert!(root.evaluate(0.5).unwrap()[1].is_nan());
}

/// The distance from `p` to the segment `a b`.
fn segment_distance(p: &[f64], a: &[f64], b: &[f64]) -> f64 {
    let d: Vec<f64> = a.iter().zip(b).map(|(a, b)| b - a).collect();
    let len2: f64 = d.iter().map(|x| x * x).sum();
    let s = if len2 == 0.0 {
        0.0
    } else {
        (p.iter()
            .zip(a)
            .zip(&d)
            .map(|((p, a), d)| (p - a) * d)
            .sum::<f64>()
            / len2)
            .clamp(0.0, 1.0)
    };
    p.iter()
        .zip(a)
        .zip(&d)
        .map(|((p, a), d)| (p - a - s * d).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// Checks the plot's promises by dense evaluation: every vertex on the curve, each run's
/// chords within the tolerance of the curve between their ends, runs in increasing t.
fn check_plot(c: &ParametricCurve, tolerance: f64, bbox: Option<[f64; 4]>) -> usize {
    let plot = c.plot(tolerance, bbox).unwrap();
    let dim = c.dim();
    assert_eq!(plot.points.len(), plot.ts.len() * dim);
    let mut runs = 0;
    let mut previous: Option<(f64, Vec<f64>)> = None;
    for (k, t) in plot.ts.iter().enumerate() {
        let p = plot.points[k * dim..(k + 1) * dim].to_vec();
        if t.is_nan() {
            assert!(p.iter().all(|v| v.is_nan()));
            previous = None;
            continue;
        }
        let on = c.evaluate(*t).unwrap();
        for (a, b) in p.iter().zip(&on) {
            close(*a, *b, 1e-12);
        }
        if let Some((t0, p0)) = &previous {
            assert!(t > t0);
            for s in 1..64 {
                let u = t0 + (t - t0) * f64::from(s) / 64.0;
                let q = c.evaluate(u).unwrap();
                let d = segment_distance(&q, p0, &p);
                assert!(d <= tolerance * (1.0 + 1e-9), "t = {u}: {d} > {tolerance}");
            }
        } else {
            runs += 1;
        }
        previous = Some((*t, p));
    }
    runs
}

#[test]
fn the_plot_keeps_its_promises() {
    let circle = curve(&[("cos(t)", "sin(t)", "0", "2pi")]);
    assert_eq!(check_plot(&circle, 1e-3, None), 1);
    let plot = circle.plot(1e-3, None).unwrap();
    assert!(plot.complete);
    assert!(
        plot.ts.len() < 2000,
        "{} vertices for a circle",
        plot.ts.len()
    );
    // tan t on [0, 2pi] within a window: three runs, none crossing a pole.
    let tan = curve(&[("t", "tan(t)", "0", "2pi")]);
    assert_eq!(check_plot(&tan, 1e-2, Some([0.0, -10.0, 7.0, 10.0])), 3);
    // A jump between pieces breaks the run; a joint where the pieces meet does not.
    let jump = curve(&[("t", "t", "0", "1"), ("t", "t + 1", "1", "2")]);
    assert_eq!(check_plot(&jump, 1e-3, None), 2);
    let meet = curve(&[("1 - t^2", "t", "0", "1"), ("t^2 - 4t + 3", "t", "1", "2")]);
    assert_eq!(check_plot(&meet, 1e-3, None), 1);
    // floor jumps at every integer: one run per step.
    let steps = curve(&[("t", "floor(t)", "0", "3.5")]);
    assert_eq!(check_plot(&steps, 1e-3, None), 4);
    // sqrt(t) on [-1, 1] is drawn where it is defined.
    let root = curve(&[("t", "sqrt(t)", "-1", "1")]);
    assert_eq!(check_plot(&root, 1e-3, None), 1);
    // 1/t: two runs, no line across the pole.
    let hyperbola = curve(&[("t", "1/t", "-1", "1")]);
    assert_eq!(
        check_plot(&hyperbola, 1e-3, Some([-1.0, -50.0, 1.0, 50.0])),
        2
    );
}

#[test]
fn the_plot_of_sin_one_over_t_ends_at_its_budget() {
    let c = curve(&[("t", "sin(1/t)", "-1", "1")]);
    let plot = c.plot(1e-3, None).unwrap();
    assert!(!plot.complete);
    // What is drawn is still correct.
    check_plot(&c, 1e-3, None);
    // Far from 0 the curve is drawn.
    assert!(plot.ts.iter().any(|t| (0.5..1.0).contains(t)));
    assert!(plot.ts.iter().any(|t| (-1.0..-0.5).contains(t)));
}

/// Pieces, then the expected code, piece, field, start and end.
type Case<'a> = (
    &'a [(&'a str, &'a str, &'a str, &'a str)],
    &'a str,
    Option<usize>,
    &'a str,
    usize,
    usize,
);

#[test]
fn bad_input_is_a_coded_error_in_place() {
    let cases: [Case; 6] = [
        (
            &[("cos(t)", "sin t", "0", "1")],
            "function-needs-parentheses",
            Some(0),
            "y",
            0,
            3,
        ),
        (
            &[("t", "t + q", "0", "1")],
            "unknown-name",
            Some(0),
            "y",
            4,
            5,
        ),
        (
            &[("t", "t", "0", "1"), ("t", "t", "1.5", "2")],
            "pieces-do-not-join",
            Some(1),
            "from",
            0,
            0,
        ),
        (
            &[("t", "t", "1", "1")],
            "empty-piece-interval",
            Some(0),
            "to",
            0,
            0,
        ),
        (
            &[("t", "t", "0", "2t")],
            "bound-uses-t",
            Some(0),
            "to",
            0,
            2,
        ),
        (
            &[("t", "t", "0", "ln(0)")],
            "not-finite-value",
            Some(0),
            "to",
            0,
            0,
        ),
    ];
    for (pieces, code, piece, field, start, end) in cases {
        let pieces: Vec<PieceSource> = pieces.iter().map(|p| piece_of(*p)).collect();
        let (p, i, f, s, e) = problem(ParametricCurve::new(&pieces, &[]).unwrap_err());
        assert_eq!(
            (p.code(), i, f.as_deref(), s, e),
            (code, piece, Some(field), start, end)
        );
    }
    let (p, ..) = problem(ParametricCurve::new(&[], &[]).unwrap_err());
    assert_eq!(p.code(), "piece-count");
    let (p, ..) = problem(
        ParametricCurve::new(&[piece("t", "t", "0", "1")], &[("tt".into(), 1.0)]).unwrap_err(),
    );
    assert_eq!(p.code(), "invalid-parameter-name");
    // The message places the problem for a reader.
    let err = ParametricCurve::new(&[piece("t", "t + q", "0", "1")], &[]).unwrap_err();
    assert_eq!(
        err.to_string(),
        "pieces[0].y, characters 4–5: unknown name \"q\"; use t, pi, e, a function such as sin(t), or a parameter"
    );
    // Every bound of a piece may be an expression; π is exact enough to join.
    let c = curve(&[
        ("cos(t)", "sin(t)", "0", "pi/2"),
        ("cos(t)", "sin(t)", "1.5707963267948966", "pi"),
    ]);
    assert_eq!(c.domain(), (0.0, PI));
}

fn piece_of(p: (&str, &str, &str, &str)) -> PieceSource {
    piece(p.0, p.1, p.2, p.3)
}
