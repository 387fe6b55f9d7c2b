//! One test per `Error` variant: a public call that produces it, its stable code, and a
//! message that names the bad values. Variants only the JavaScript layer raises are tested
//! through `splinelab::wasm` at the end (wasm only). Runs natively and in Node.

mod common;

use common::*;
use splinelab::bezier::{self, BezierCurve, CompositeCurve, JoinRule};
use splinelab::bspline::{self, BSplineCurve, KnotKind, KnotVector, Parameterization};
use splinelab::geom::MAX_DEGREE;
use splinelab::interp::{self, EndCondition};
use splinelab::rational;
use splinelab::{BSplineSurface, DMat3, DVec2, DVec3, Error};
#[cfg(target_arch = "wasm32")]
use wasm_bindgen_test::wasm_bindgen_test as test;

/// Asserts `result` failed with `code` and a message containing every one of `parts`; returns
/// the error for further checks.
#[track_caller]
fn fails<T: std::fmt::Debug>(result: splinelab::Result<T>, code: &str, parts: &[&str]) -> Error {
    let e = result.expect_err("expected an error");
    let message = e.to_string();
    assert_eq!(e.code(), code, "code of {message:?}");
    for part in parts {
        assert!(message.contains(part), "message {message:?} lacks {part:?}");
    }
    e
}

/// The syllabus' cubic `(0,0) (2,2) (6,4) (8,2)`.
fn cubic() -> BezierCurve<DVec2> {
    BezierCurve::new(
        pts2(&[(0.0, 0.0), (2.0, 2.0), (6.0, 4.0), (8.0, 2.0)]),
        None,
    )
    .unwrap()
}

/// A rational quadratic with weights 1, 2, 1.
fn rational_quadratic() -> BezierCurve<DVec2> {
    BezierCurve::new(
        pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)]),
        Some(&[1.0, 2.0, 1.0]),
    )
    .unwrap()
}

/// A line segment from `a` to `b`.
fn line(a: (f64, f64), b: (f64, f64)) -> BezierCurve<DVec2> {
    BezierCurve::new(pts2(&[a, b]), None).unwrap()
}

/// A clamped cubic B-spline with five control points and one interior knot 0.5.
fn clamped_cubic() -> BSplineCurve<DVec2> {
    BSplineCurve::new(
        pts2(&[(0.0, 0.0), (1.0, 2.0), (3.0, 3.0), (5.0, 1.0), (6.0, 0.0)]),
        3,
        vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0],
        None,
    )
    .unwrap()
}

/// A 2 × 2 bilinear patch through the corners given row by row.
fn patch(corners: [[f64; 3]; 4]) -> BSplineSurface {
    BSplineSurface::bezier(&corners.concat(), 2, 2, None).unwrap()
}

fn unit_patch() -> BSplineSurface {
    patch([
        [0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 1.0],
    ])
}

#[test]
fn invalid_dimension() {
    fails(
        splinelab::geom::check_dim(4),
        "invalid-dimension",
        &["dim must be 2 or 3, got 4"],
    );
}

#[test]
fn coordinate_count() {
    fails(
        BezierCurve::<DVec2>::from_flat(&[0.0, 0.0, 1.0], None),
        "coordinate-count",
        &["coordinate count 3", "dim = 2"],
    );
}

#[test]
fn not_finite() {
    fails(
        BezierCurve::<DVec2>::from_flat(&[0.0, f64::INFINITY, 1.0, 1.0], None),
        "not-finite",
        &[&format!("coordinate 1 is {INFINITY_TEXT}")],
    );
}

#[test]
fn coordinate_too_large() {
    let e = fails(
        BezierCurve::<DVec2>::from_flat(&[0.0, 0.0, 1e200, 1.0], None),
        "coordinate-too-large",
        &["coordinate 2 is 1e+200", "at most 1e+120 in magnitude"],
    );
    assert_eq!(
        e,
        Error::CoordinateTooLarge {
            what: "coordinate",
            index: Some(2),
            value: 1e200,
            max: 1e120
        }
    );
}

#[test]
fn too_few_points() {
    fails(
        BezierCurve::new(pts2(&[(1.0, 2.0)]), None),
        "too-few-points",
        &["at least 2 control points, got 1"],
    );
}

#[test]
fn weight_count() {
    fails(
        BezierCurve::new(pts2(&[(0.0, 0.0), (1.0, 1.0)]), Some(&[1.0])),
        "weight-count",
        &["(2), got 1"],
    );
}

#[test]
fn all_weights_zero() {
    fails(
        rational::rational_poles(
            &pts2(&[(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)]),
            &[0.0, 0.0, 0.0],
            8,
        ),
        "all-weights-zero",
        &["all 3 weights are 0"],
    );
}

#[test]
fn non_positive_weight() {
    fails(
        BezierCurve::new(pts2(&[(0.0, 0.0), (1.0, 1.0)]), Some(&[1.0, -0.5])),
        "non-positive-weight",
        &["weight 1 is -0.5"],
    );
}

#[test]
fn parameter_out_of_range() {
    fails(
        cubic().evaluate(1.5),
        "parameter-out-of-range",
        &["t = 1.5 is outside the domain [0, 1]"],
    );
}

#[test]
fn index_out_of_range() {
    fails(
        cubic().set_control_point(5, DVec2::ZERO),
        "index-out-of-range",
        &["index 5", "4 points (0..=3)"],
    );
}

#[test]
fn invalid_tolerance() {
    fails(
        cubic().flatten(0.0),
        "invalid-tolerance",
        &["tolerance 0 is not usable", "finite number > 0"],
    );
}

#[test]
fn tolerance_too_small() {
    fails(
        cubic().flatten(1e-20),
        "tolerance-too-small",
        &["tolerance 1e-20", "1e-10 × the curve's size"],
    );
}

#[test]
fn flattening_stalled() {
    // A guard against a subdivision that stops making progress: no input is known to reach it
    // (the relative floor of `tolerance-too-small` comes first, even for coordinates near
    // 1e153 or weights of 1e±300), so the message is checked on the value itself.
    let e = Error::FlatteningStalled { value: 1e-3 };
    assert_eq!(e.code(), "flattening-stalled");
    assert_eq!(
        e.to_string(),
        "tolerance 0.001 is not usable: no piece of the curve is flat enough at this precision"
    );
}

#[test]
fn invalid_interval() {
    fails(
        cubic().with_interval(2.0, 1.0),
        "invalid-interval",
        &["interval [2, 1] is empty"],
    );
}

#[test]
fn unknown_option() {
    fails(
        KnotKind::parse("even"),
        "unknown-option",
        &["kind must be one of", "got \"even\""],
    );
}

#[test]
fn in_argument_keeps_its_cause() {
    let e = fails(
        BSplineSurface::from_flat(
            &[0.0; 12],
            2,
            2,
            1,
            1,
            vec![0.0, 0.0, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
            None,
        ),
        "in-argument",
        &["knotsU: knot vector must have", "got 3"],
    );
    let source = std::error::Error::source(&e).expect("a source");
    assert_eq!(
        source.to_string(),
        "knot vector must have n+p+2 = 1 + 1 + 2 = 4 values, got 3"
    );
    let grid = unit_patch().sample_grid_into(&[0.5, 2.0], &[0.5], &mut Vec::new());
    fails(grid, "in-argument", &["us[1]: u = 2 is outside"]);
}

#[test]
fn knot_count() {
    fails(
        KnotVector::new(vec![0.0; 8], 3, 5),
        "knot-count",
        &["n+p+2 = 4 + 3 + 2 = 9 values, got 8"],
    );
}

#[test]
fn knot_order() {
    fails(
        KnotVector::new(vec![0.0, 0.0, 2.0, 1.0], 1, 2),
        "knot-order",
        &["u_3 = 1 comes after u_2 = 2"],
    );
}

#[test]
fn empty_domain() {
    fails(
        KnotVector::new(vec![0.0, 1.0, 1.0, 2.0], 1, 2),
        "empty-domain",
        &["[u_1, u_2] = [1, 1] is empty"],
    );
}

#[test]
fn knot_multiplicity() {
    fails(
        KnotVector::new(vec![0.0, 0.0, 0.0, 1.0, 1.0], 1, 3),
        "knot-multiplicity",
        &["knot 0 appears 3 times (u_0..u_2)", "at most p+1 = 2"],
    );
}

#[test]
fn insertion_multiplicity() {
    fails(
        clamped_cubic().insert_knot(0.5, 4),
        "insertion-multiplicity",
        &["knot 0.5 4 time(s)", "multiplicity 5", "p+1 = 4"],
    );
    fails(
        unit_patch().insert_knot_v(0.25, 3),
        "insertion-multiplicity",
        &["knot v = 0.25 3 time(s)", "multiplicity 3"],
    );
}

#[test]
fn degree_zero() {
    fails(
        BSplineCurve::new(
            pts2(&[(0.0, 0.0), (1.0, 1.0)]),
            0,
            vec![0.0, 1.0, 2.0],
            None,
        ),
        "degree-zero",
        &["degree must be at least 1, got 0"],
    );
}

#[test]
fn too_few_points_for_degree() {
    fails(
        BSplineCurve::new(
            pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)]),
            3,
            vec![0.0; 7],
            None,
        ),
        "too-few-points-for-degree",
        &["degree 3 needs at least p+1 = 4 control points, got 3"],
    );
}

#[test]
fn too_large() {
    let points = vec![DVec2::ZERO; MAX_DEGREE + 2];
    let knots = vec![0.0; 2 * MAX_DEGREE + 4];
    fails(
        BSplineCurve::new(points, MAX_DEGREE + 1, knots, None),
        "too-large",
        &[&format!(
            "degree = {} is too large; at most {MAX_DEGREE}",
            MAX_DEGREE + 1
        )],
    );
}

#[test]
fn coincident_points() {
    let p = DVec2::new(1.0, 1.0);
    fails(
        bspline::parameterize(&[p, p, DVec2::ZERO], Parameterization::Chord),
        "coincident-points",
        &["points 0 and 1 coincide", "Chord spacing"],
    );
}

#[test]
fn phantom_even_degree() {
    fails(
        bspline::phantom_points(&pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)]), 2),
        "phantom-even-degree",
        &["degree 2 is even"],
    );
}

#[test]
fn not_a_span() {
    fails(
        clamped_cubic().segment_matrix(0, true),
        "not-a-span",
        &["span 0 is not a non-empty span", "(valid: [3, 4])"],
    );
}

#[test]
fn rational_join() {
    fails(
        bezier::join(&rational_quadratic(), &cubic(), JoinRule::C1, true),
        "rational-join",
        &["polynomial Bézier pieces"],
    );
}

#[test]
fn join_degree() {
    let a = line((0.0, 0.0), (1.0, 1.0));
    let b = line((1.0, 1.0), (2.0, 0.0));
    fails(
        bezier::join(&a, &b, JoinRule::C2, true),
        "join-degree",
        &["rule C2", "degrees 1 and 1 are too low"],
    );
}

#[test]
fn no_joint_tangent() {
    let left = BezierCurve::new(pts2(&[(0.0, 0.0), (1.0, 1.0), (1.0, 1.0)]), None).unwrap();
    fails(
        bezier::join(&left, &cubic(), JoinRule::G1, true),
        "no-joint-tangent",
        &["G1 needs a tangent at the joint"],
    );
}

#[test]
fn breakpoint_count() {
    let pieces = vec![line((0.0, 0.0), (1.0, 1.0)), line((1.0, 1.0), (2.0, 0.0))];
    fails(
        CompositeCurve::new(pieces, &[0.0, 1.0]),
        "breakpoint-count",
        &["2 pieces need 3 breakpoints, got 2"],
    );
}

#[test]
fn degenerate_line() {
    let p = DVec2::new(1.5, -2.0);
    fails(
        cubic().intersect_line(p, p, 1e-9),
        "degenerate-line",
        &["got (1.5, -2) twice"],
    );
}

#[test]
fn curve_batch_length() {
    fails(
        bezier::arc_lengths::<DVec2>(&[0.0; 10], 3, None),
        "curve-batch-length",
        &["10 coordinates", "degree 3", "= 8 numbers each"],
    );
}

#[test]
fn rational_hodograph() {
    fails(
        rational_quadratic().hodograph(),
        "rational-hodograph",
        &["hodograph of a rational curve"],
    );
}

#[test]
fn mapped_weight() {
    let flip = DMat3::from_diagonal(DVec3::new(1.0, 1.0, -2.0));
    fails(
        rational::projective_map_bezier(&cubic(), &flip),
        "mapped-weight",
        &["control point 0 to weight -2"],
    );
}

#[test]
fn singular_map() {
    fails(
        rational::projective_map_bezier(&cubic(), &DMat3::ZERO),
        "singular-map",
        &["singular (determinant 0)"],
    );
}

#[test]
fn degenerate_triangle() {
    let p = DVec2::new(1.0, 1.0);
    fails(
        rational::circle_arc_from_triangle(p, p, DVec2::ZERO),
        "degenerate-triangle",
        &["proper triangle P0 P1 P2"],
    );
}

#[test]
fn not_isosceles() {
    fails(
        rational::circle_arc_from_triangle(
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 2.0),
        ),
        "not-isosceles",
        &["|P0P1| = 1 but |P1P2| = 2"],
    );
}

#[test]
fn invalid_sweep() {
    fails(
        rational::ellipse_arc(DVec2::ZERO, DVec2::X, DVec2::Y, 0.0, 7.0),
        "invalid-sweep",
        &["one full turn (2π), got 7"],
    );
}

#[test]
fn parallel_axes() {
    fails(
        rational::ellipse_arc(DVec2::ZERO, DVec2::X, 2.0 * DVec2::X, 0.0, 1.0),
        "parallel-axes",
        &["axes of an ellipse must not be parallel"],
    );
}

#[test]
fn not_positive() {
    fails(
        rational::circular_arc(DVec2::ZERO, -1.0, 0.0, 1.0),
        "not-positive",
        &["r must be > 0, got -1"],
    );
    fails(
        rational::ellipse(DVec2::ZERO, 1.0, 0.0, 0.0),
        "not-positive",
        &["ry must be > 0, got 0"],
    );
}

#[test]
fn buffer_length() {
    fails(
        cubic().sample_into(&[0.5], &mut [0.0; 3]),
        "buffer-length",
        &["output buffer has 3 values, 1 points need 2"],
    );
}

#[test]
fn net_coordinate_count() {
    fails(
        BSplineSurface::from_flat(
            &[0.0; 10],
            2,
            2,
            1,
            1,
            vec![0.0, 0.0, 1.0, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
            None,
        ),
        "net-coordinate-count",
        &["rows·cols·3 = 2·2·3 = 12 coordinates, got 10"],
    );
}

#[test]
fn patch_too_small() {
    fails(
        BSplineSurface::bezier(&[0.0; 9], 1, 3, None),
        "patch-too-small",
        &["at least 2 rows and 2 columns", "got 1 × 3"],
    );
}

#[test]
fn net_index_out_of_range() {
    fails(
        unit_patch().set_control_point(5, 0, DVec3::ZERO),
        "net-index-out-of-range",
        &["(i, j) = (5, 0)", "2 × 2 points (i in 0..=1, j in 0..=1)"],
    );
}

#[test]
fn no_normal() {
    // Every row of the net is one point: S_v = 0 everywhere.
    let flat = patch([
        [0.0, 0.0, 0.0],
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
    ]);
    fails(
        flat.normal(0.5, 0.25),
        "no-normal",
        &["no normal at (u, v) = (0.5, 0.25)"],
    );
}

#[test]
fn empty_tessellation() {
    fails(
        unit_patch().tessellate(0, 4),
        "empty-tessellation",
        &["got nu = 0, nv = 4"],
    );
}

#[test]
fn codes_are_kebab_case() {
    let e = KnotVector::new(vec![0.0; 3], 1, 2).unwrap_err();
    assert!(e
        .code()
        .chars()
        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'));
}

// ---- Section 5's cubic family (core-cubic) ----

fn cubic_data() -> Vec<DVec2> {
    pts2(&[(0.0, 0.0), (1.0, 2.0), (3.0, 3.0), (5.0, 1.0)])
}

#[test]
fn cubic_param_count() {
    fails(
        interp::LagrangeCurve::new(cubic_data(), &[0.0, 1.0]),
        "param-count",
        &["params must have one value per point (4), got 2"],
    );
}

#[test]
fn cubic_params_not_increasing() {
    fails(
        interp::CubicSpline::interpolate(
            cubic_data(),
            vec![0.0, 1.0, 0.5, 2.0],
            EndCondition::Natural,
        ),
        "params-not-increasing",
        &["t_2 = 0.5 is not above t_1 = 1"],
    );
}

#[test]
fn cubic_missing_argument() {
    fails(
        EndCondition::<DVec2>::parse("clamped", None, Some(DVec2::X)),
        "missing-argument",
        &["the \"clamped\" end condition needs startTangent"],
    );
}

#[test]
fn cubic_argument_length() {
    fails(
        interp::CubicSpline::hermite(cubic_data(), vec![0.0, 1.0, 2.0, 3.0], vec![DVec2::X; 3]),
        "argument-length",
        &["tangents must have 8 numbers, got 6"],
    );
}

#[test]
fn cubic_not_closed() {
    fails(
        interp::CubicSpline::interpolate(
            cubic_data(),
            vec![0.0, 1.0, 2.0, 3.0],
            EndCondition::Periodic,
        ),
        "not-closed",
        &["last point (point 3) equal to the first"],
    );
}

#[test]
fn cubic_alpha_out_of_range() {
    fails(
        interp::CubicSpline::catmull_rom(cubic_data(), -0.5, false),
        "alpha-out-of-range",
        &["alpha = -0.5 is outside [0, 1]"],
    );
    fails(
        Parameterization::from_alpha(f64::NAN),
        "alpha-out-of-range",
        &["alpha = NaN"],
    );
}

#[test]
fn cubic_too_few_data_points() {
    fails(
        interp::CubicSpline::interpolate(
            pts2(&[(0.0, 0.0), (0.0, 0.0)]),
            vec![0.0, 1.0],
            EndCondition::Periodic,
        ),
        "too-few-data-points",
        &["a cubic spline needs at least 3 data points, got 2"],
    );
    fails(
        interp::LagrangeCurve::new(pts2(&[(0.0, 0.0)]), &[0.0]),
        "too-few-data-points",
        &["a Lagrange curve needs at least 2 data points, got 1"],
    );
}

#[test]
fn cubic_singular_system() {
    fails(
        interp::solve_tridiagonal(&[1.0], &[1.0, 1.0], &[1.0], &[0.0, 1.0], "the test system"),
        "singular-system",
        &["the test system is singular: elimination met a zero pivot in row 1"],
    );
}

#[test]
fn cubic_spline_kind() {
    let mut c = interp::CubicSpline::bessel(cubic_data(), vec![0.0, 1.0, 2.0, 3.0]).unwrap();
    fails(
        c.set_tangent(0, DVec2::X),
        "spline-kind",
        &["setTangent works on splines built by hermiteSpline; this one was built by besselSpline"],
    );
}

#[test]
fn cubic_coincident_points_alpha() {
    fails(
        bspline::parameterize(
            &cubic_data()[..1].repeat(2),
            Parameterization::from_alpha(0.3).unwrap(),
        ),
        "coincident-points",
        &["points 0 and 1 coincide; alpha = 0.3 spacing"],
    );
}

#[test]
fn cubic_lagrange_too_large() {
    let points = vec![DVec2::ZERO; interp::MAX_LAGRANGE_POINTS + 1];
    let params: Vec<f64> = (0..points.len()).map(|i| i as f64).collect();
    fails(
        interp::LagrangeCurve::new(points, &params),
        "too-large",
        &["66"],
    );
}

// --- Global B-spline interpolation and least squares (interp::global, interp::least_squares).

/// Five points at 0..4 for the interpolation variants.
fn interp_data() -> (Vec<DVec2>, Vec<f64>) {
    (
        pts2(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (3.0, 1.0), (4.0, 0.0)]),
        vec![0.0, 1.0, 2.0, 3.0, 4.0],
    )
}

#[test]
fn control_count_out_of_range() {
    let (points, params) = interp_data();
    fails(
        splinelab::interp::approximate_bspline(&points, 3, 6, &params, None),
        "control-count-out-of-range",
        &["count = 6 control points", "[4, 5]"],
    );
}

#[test]
fn schoenberg_whitney() {
    let (points, params) = interp_data();
    let options = splinelab::interp::InterpolationOptions {
        knots: Some(vec![0.0, 0.0, 0.0, 0.25, 0.5, 4.0, 4.0, 4.0]),
        ..Default::default()
    };
    fails(
        splinelab::interp::interpolate_bspline(&points, 2, &params, &options),
        "schoenberg-whitney",
        &["singular", "t_1 = 1", "(u_1, u_4) = (0, 0.5)", "N_1,2"],
    );
}

#[test]
fn conflicting_options() {
    let (mut points, params) = interp_data();
    points[4] = points[0];
    let options = splinelab::interp::InterpolationOptions {
        closed: true,
        start_derivative: Some(DVec2::new(1.0, 0.0)),
        ..Default::default()
    };
    fails(
        splinelab::interp::interpolate_bspline(&points, 2, &params, &options),
        "conflicting-options",
        &["startDerivative cannot be combined with closed"],
    );
}

#[test]
fn knots_not_clamped() {
    let (points, params) = interp_data();
    let knots = [0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0, 4.0];
    fails(
        splinelab::interp::approximate_bspline(&points, 2, 5, &params, Some(&knots)),
        "knots-not-clamped",
        &["first p+1 = 3 knots must equal 0"],
    );
}

// Issue 14: surfaces built from curves and grids (revolve, interpolate_surface, matrix form).

/// The unit circle in the xz plane about (2, 0, 0): a torus profile.
fn torus_profile() -> BSplineCurve<DVec3> {
    rational::ellipse_arc(
        DVec3::new(2.0, 0.0, 0.0),
        DVec3::X,
        DVec3::Z,
        0.0,
        std::f64::consts::TAU,
    )
    .unwrap()
}

#[test]
fn zero_direction() {
    fails(
        splinelab::surface::revolve(&torus_profile(), DVec3::ZERO, DVec3::ZERO, 1.0),
        "zero-direction",
        &["axisDirection must not be the zero vector"],
    );
}

#[test]
fn needs_3d() {
    fails(
        splinelab::surface::revolve(&clamped_cubic(), DVec3::ZERO, DVec3::Z, 1.0),
        "needs-3d",
        &["revolve builds a 3D surface and needs a 3D curve; this curve has dim = 2"],
    );
}

#[test]
fn revolution_angle_out_of_range() {
    for angle in [0.0, -1.0, 6.3] {
        fails(
            splinelab::surface::revolve(&torus_profile(), DVec3::ZERO, DVec3::Z, angle),
            "invalid-sweep",
            &["at most one full turn (2π)"],
        );
    }
}

#[test]
fn surface_grid_size_mismatch() {
    fails(
        splinelab::surface::interpolate_surface(&[0.0; 30], 4, 3, 2, 2, Parameterization::Chord),
        "net-coordinate-count",
        &["rows·cols·3 = 4·3·3 = 36 coordinates, got 30"],
    );
}

#[test]
fn surface_degree_too_high_for_the_grid() {
    let coords: Vec<f64> = (0..12)
        .flat_map(|k| [(k / 3) as f64, (k % 3) as f64, 0.0])
        .collect();
    let e = fails(
        splinelab::surface::interpolate_surface(&coords, 4, 3, 3, 3, Parameterization::Chord),
        "in-argument",
        &["degreeV: ", "needs at least 4 data points, got 3"],
    );
    let source = std::error::Error::source(&e).expect("a source");
    assert!(source.to_string().contains("needs at least 4"));
}

#[test]
fn needs_polynomial() {
    let weights = [1.0, 2.0, 1.0, 1.0];
    let patch = BSplineSurface::bezier(&unit_patch_coords(), 2, 2, Some(&weights)).unwrap();
    fails(
        patch.matrix_form(),
        "needs-polynomial",
        &["matrixForm works on polynomial patches"],
    );
}

/// The corners of [`unit_patch`], flat.
fn unit_patch_coords() -> Vec<f64> {
    [
        [0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 1.0],
    ]
    .concat()
}

// ---- Surface meshes and line intersection (issue 14) ----------------------------------------

/// A curved bicubic patch: a bump over the unit square.
fn bump_patch() -> BSplineSurface {
    let coords: Vec<f64> = (0..16)
        .flat_map(|k| {
            let (i, j) = (k / 4, k % 4);
            let z = if (1..3).contains(&i) && (1..3).contains(&j) {
                1.0
            } else {
                0.0
            };
            [i as f64 / 3.0, j as f64 / 3.0, z]
        })
        .collect();
    BSplineSurface::bezier(&coords, 4, 4, None).unwrap()
}

#[test]
fn adaptive_tolerance_not_positive() {
    fails(
        bump_patch().tessellate_adaptive(0.0),
        "invalid-tolerance",
        &["tolerance 0 is not usable", "> 0"],
    );
    fails(
        bump_patch().tessellate_adaptive(-0.1),
        "invalid-tolerance",
        &["tolerance -0.1"],
    );
    fails(
        bump_patch().intersect_line(DVec3::ZERO, DVec3::Z, 0.0),
        "invalid-tolerance",
        &["tolerance 0"],
    );
}

#[test]
fn adaptive_tolerance_nan() {
    fails(
        bump_patch().tessellate_adaptive(f64::NAN),
        "invalid-tolerance",
        &["tolerance NaN"],
    );
    fails(
        bump_patch().intersect_line(DVec3::ZERO, DVec3::Z, f64::NAN),
        "invalid-tolerance",
        &["tolerance NaN"],
    );
    fails(
        bump_patch().intersect_line(DVec3::new(0.0, f64::NAN, 0.0), DVec3::Z, 1e-6),
        "in-argument",
        &["origin: coordinate 1"],
    );
}

#[test]
fn intersect_line_zero_direction() {
    let e = fails(
        bump_patch().intersect_line(DVec3::ZERO, DVec3::ZERO, 1e-6),
        "in-argument",
        &["direction: its length must be > 0, got 0"],
    );
    let source = std::error::Error::source(&e).expect("a source");
    assert_eq!(source.to_string(), "its length must be > 0, got 0");
}

#[test]
fn adaptive_mesh_too_large() {
    // 260 × 260 bilinear patches: more patches than MAX_ADAPTIVE_VERTICES = 2^16 vertices.
    let n = 261;
    let coords: Vec<f64> = (0..n * n)
        .flat_map(|k| [(k / n) as f64, (k % n) as f64, 0.0])
        .collect();
    let knots: Vec<f64> = (0..n + 2).map(|k| k.clamp(1, n) as f64).collect();
    let many = BSplineSurface::from_flat(&coords, n, n, 1, 1, knots.clone(), knots, None).unwrap();
    fails(
        many.tessellate_adaptive(1.0),
        "too-large",
        &["adaptive mesh vertices", "67600", "65536"],
    );
    // A tolerance far below rounding: still not flat at the depth cap.
    fails(
        bump_patch().tessellate_adaptive(1e-300),
        "too-large",
        &["adaptive subdivision depth", "25", "at most 24"],
    );
}

// ---- Work budgets (issue 15): the error names what the caller gave, before any work ----------

#[test]
fn basis_curves_count_too_large_names_the_count() {
    // 20 000 control points × 10^6 samples: 2·10^10 values, more than a 32-bit count holds. The
    // message names the count given and the largest allowed (2^22 / 20 000 = 209).
    let n = 20_000;
    let points = pts2(&(0..n).map(|i| (i as f64, 0.0)).collect::<Vec<_>>());
    let knots: Vec<f64> = (0..n + 4).map(|i| i.clamp(3, n) as f64).collect();
    let curve = BSplineCurve::new(points.clone(), 3, knots, None).unwrap();
    fails(
        curve.basis_curves(1_000_000),
        "too-large",
        &["count", "= 1000000", "at most 209"],
    );
    let params: Vec<f64> = (0..40).map(f64::from).collect();
    let lagrange = interp::LagrangeCurve::new(points[..40].to_vec(), &params).unwrap();
    fails(
        lagrange.basis_curves(1_000_000),
        "too-large",
        &["count", "= 1000000", "at most 104857"],
    );
}

#[test]
fn dense_sampling_work_is_priced_by_the_degree() {
    // One point of a degree-p curve costs O(p²): count·(p + 1)² ≤ 2^28. A degree-64 Bézier
    // curve gets 2^28 / 65² = 63 535 points (2^22 of them took 19 s in wasm); the error names
    // the count given and that largest one, before any point is computed.
    let points: Vec<DVec2> = (0..=64)
        .map(|i| DVec2::new(i as f64, (i % 3) as f64))
        .collect();
    let bezier = BezierCurve::new(points.clone(), None).unwrap();
    fails(
        bezier.sample_uniform_into(100_000, &mut []),
        "too-large",
        &["sample count for this degree", "= 100000", "at most 63535"],
    );
    let ts = vec![0.5; 63_536];
    fails(
        bezier.sample_into(&ts, &mut []),
        "too-large",
        &["at most 63535"],
    );
    // 63 535 is within the budget: the next failure is the (deliberately empty) buffer.
    fails(
        bezier.sample_uniform_into(63_535, &mut []),
        "buffer-length",
        &[],
    );
    let knots: Vec<f64> = (0..65 + 65).map(|i| i.clamp(64, 65) as f64).collect();
    let bspline = BSplineCurve::new(points, 64, knots, None).unwrap();
    fails(
        bspline.sample_uniform_into(63_536, &mut []),
        "too-large",
        &["at most 63535"],
    );
    // A derivative of order k costs k + 1 basis rows and the quotient rule:
    // 2^28 / (65²·3 + 16·3² + 64) = 20 836 for k = 2.
    fails(
        bspline.sample_derivatives_into(&ts[..20_837], 2, &mut []),
        "too-large",
        &["at most 20836"],
    );
    // Degrees up to 7 meet the 2^22-point cap first: 2^28 / 8² = 2^22.
    use splinelab::geom::check_out_len;
    fails(check_out_len(0, 1 << 22, 2, 7), "buffer-length", &[]);
    fails(
        check_out_len(0, 3_314_018, 2, 8),
        "too-large",
        &["at most 3314017"],
    );
}

#[test]
fn surface_work_is_priced_by_the_degrees() {
    // A degree-(64, 64) patch: a mesh vertex costs 2·65² + 128 = 8578 units, a curvature
    // 8·(3·65² + 32) = 101 656 (100 000 curvatures of it took 6.7 s in wasm).
    let n = 65;
    let coords: Vec<f64> = (0..n * n)
        .flat_map(|k| [(k / n) as f64, (k % n) as f64, ((k * 7) % 5) as f64])
        .collect();
    let patch = BSplineSurface::bezier(&coords, n, n, None).unwrap();
    fails(
        patch.tessellate(200, 200),
        "too-large",
        &[
            "tessellation vertices",
            "for this degree",
            "= 40401",
            "at most 31293",
        ],
    );
    assert!(patch.tessellate(100, 100).is_ok());
    let uvs = vec![0.5; 2 * 2641];
    let mut out = Vec::new();
    fails(
        patch.curvatures_into(&uvs, &mut out),
        "too-large",
        &["curvature points for this degree", "= 2641", "at most 2640"],
    );
    assert!(out.capacity() == 0, "refused before allocating");
    patch.curvatures_into(&uvs[..2 * 2640], &mut out).unwrap();
    assert_eq!(out.len(), 2 * 2640);
    // A bicubic meets the vertex cap (2^20) first.
    fails(
        bump_patch().tessellate(1024, 1024),
        "too-large",
        &[
            "tessellation vertices (nu + 1)(nv + 1) = 1050625",
            "at most 1048576",
        ],
    );
}

#[test]
fn from_polynomial_refuses_the_degree_before_converting() {
    let coefficients = pts2(&vec![(1.0, 1.0); 2000]);
    fails(
        bezier::from_polynomial(&coefficients, 0.0, 1.0),
        "too-large",
        &["degree = 1999", "at most 64"],
    );
}

#[test]
fn result_too_large_names_the_counts() {
    // sampleGrid 5000 × 5000 on a surface: 5000 × 5000 × 3 numbers, 600 MB, refused before
    // anything is allocated (it used to be allocated, or abort the page when memory ran out).
    let us: Vec<f64> = (0..5000).map(|i| i as f64 / 4999.0).collect();
    let mut out = Vec::new();
    fails(
        bump_patch().sample_grid_into(&us, &us, &mut out),
        "result-too-large",
        &[
            "sampleGrid: us.length × vs.length × 3 coordinates",
            "= 5000 × 5000 × 3 values of 8 bytes = 600000000 bytes",
            "at most 268435456 bytes (256 MiB)",
        ],
    );
    assert!(out.capacity() == 0, "nothing was allocated");
    // 12 million points of a curve: over MAX_SAMPLES (2^22) points, refused before the result
    // is allocated (at 2^24 points a cubic took 2–4 s in wasm, mostly memory).
    let curve = BezierCurve::new(vec![DVec3::ZERO, DVec3::ONE], None).unwrap();
    fails(
        curve.sample_uniform_into(12_000_000, &mut []),
        "too-large",
        &["sample count = 12000000", "at most 4194304"],
    );
    // Counts whose product overflows a usize are refused the same way (checked_mul), naming
    // the counts rather than a wrapped or saturated product.
    fails(
        splinelab::geom::result_len("a table", &[usize::MAX, 2]),
        "result-too-large",
        &[&format!("a table = {} × 2 values", usize::MAX)],
    );
    // At the cap exactly: allowed.
    assert_eq!(
        splinelab::geom::result_len("a table", &[splinelab::geom::MAX_RESULT_BYTES / 8]),
        Ok(1 << 25)
    );
}

#[test]
fn insertion_count_near_usize_max_is_refused_not_wrapped() {
    // `s + times` used to wrap round for times near usize::MAX (JavaScript's insertKnot(u,
    // 4294967295) on wasm32), pass the multiplicity check and start billions of insertions.
    let times = usize::MAX;
    fails(
        clamped_cubic().insert_knot(0.5, times),
        "insertion-multiplicity",
        &[&format!("knot 0.5 {times} time(s)"), "p+1 = 4"],
    );
    fails(
        unit_patch().insert_knot_u(0.25, times),
        "insertion-multiplicity",
        &[&format!("knot u = 0.25 {times} time(s)")],
    );
    fails(
        unit_patch().insert_knot_v(0.25, times - 1),
        "insertion-multiplicity",
        &[&format!("knot v = 0.25 {} time(s)", times - 1)],
    );
}

/// The variants only the JavaScript layer raises, through the exported functions.
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
mod js {
    use splinelab::wasm::ApiError;
    use splinelab::wasm::{self, JsBezierCurve, JsCompositeBezier};
    use wasm_bindgen::JsValue;
    use wasm_bindgen_test::wasm_bindgen_test as test;

    /// Asserts the export threw a JS `Error` whose message contains every one of `parts`.
    #[track_caller]
    fn fails<T>(result: Result<T, ApiError>, parts: &[&str]) {
        let message = super::js_message(result);
        for part in parts {
            assert!(message.contains(part), "message {message:?} lacks {part:?}");
        }
    }

    fn arr(values: &[f64]) -> JsValue {
        js_sys::Float64Array::from(values).into()
    }

    fn curve(coords: &[f64], dim: f64) -> JsBezierCurve {
        JsBezierCurve::new(arr(coords), dim, JsValue::UNDEFINED).unwrap()
    }

    fn cubic() -> JsBezierCurve {
        curve(&[0.0, 0.0, 2.0, 2.0, 6.0, 4.0, 8.0, 2.0], 2.0)
    }

    #[test]
    fn too_large_from_javascript_counts() {
        // sampleUniform(12e6) of a 3D curve (288 MB of numbers): over MAX_SAMPLES = 2^22 points,
        // refused before allocating, in both forms.
        let mut c = curve(&[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 3.0);
        let cap = ["count = 12000000 is too large; at most 4194304 is allowed"];
        fails(c.sample_uniform(12e6), &cap);
        fails(c.sample_uniform_view(12e6), &cap);
    }

    #[test]
    fn point_dimension() {
        fails(
            cubic().set_control_point(0.0, arr(&[1.0, 2.0, 3.0])),
            &["a point needs 2 coordinates, got 3"],
        );
    }

    #[test]
    fn degree_out_of_range() {
        fails(
            wasm::bspline::uniform_segment_matrix(0.0),
            &["degree must be 1..=", "got 0"],
        );
    }

    #[test]
    fn matrix_size() {
        fails(
            cubic().projective_map(arr(&[1.0, 0.0, 0.0])),
            &["3×3 matrix (9 numbers, row by row), got 3"],
        );
    }

    #[test]
    fn arc_point_count() {
        fails(
            wasm::rational::circular_arc_bezier(arr(&[0.0, 0.0, 1.0, 1.0])),
            &["3 control points (6 numbers), got 2"],
        );
    }

    #[test]
    fn axis_lengths() {
        fails(
            wasm::rational::ellipse_arc(
                arr(&[0.0, 0.0]),
                arr(&[1.0, 0.0, 0.0]),
                arr(&[0.0, 1.0]),
                0.0,
                1.0,
            ),
            &["same length, got 2, 3, 2"],
        );
    }

    #[test]
    fn not_positive() {
        fails(
            wasm::rational::circle(0.0, 0.0, -1.0),
            &["r must be > 0, got -1"],
        );
    }

    #[test]
    fn dimension_mismatch() {
        let c3 = curve(&[0.0; 6], 3.0);
        fails(
            wasm::bezier::join_bezier(&cubic(), &c3, JsValue::from("C1"), JsValue::UNDEFINED),
            &["same dim, got 2 and 3"],
        );
    }

    #[test]
    fn piece_point_count() {
        fails(
            JsCompositeBezier::new(
                arr(&[0.0, 0.0, 1.0, 1.0]),
                2.0,
                arr(&[3.0]),
                JsValue::UNDEFINED,
            ),
            &["degrees [3] need 4 control points", "got 2"],
        );
    }

    #[test]
    fn argument_type() {
        fails(
            JsBezierCurve::new(JsValue::NULL, 2.0, JsValue::UNDEFINED),
            &["points must be an array of numbers", "got null"],
        );
    }

    #[test]
    fn not_whole_number() {
        fails(
            JsBezierCurve::new(arr(&[0.0; 4]), 2.5, JsValue::UNDEFINED),
            &["dim must be a whole number", "got 2.5"],
        );
    }

    #[test]
    fn needs_2d() {
        fails(
            curve(&[0.0; 6], 3.0).intersect_line(0.0, 0.0, 1.0, 0.0, 1e-9),
            &["works on 2D curves; this curve has dim = 3"],
        );
    }
}

/// Subjects inside messages (`what`, `expected`, `needed_by`, `reason`, …) are keys of
/// `error::PHRASES` or identifiers, never English text, so a page translates them by key
/// (www/lib/core-errors.js): every such literal in the source is one word (or a list of option
/// words), and every hyphenated
/// one is a key with an English phrase.
#[cfg(not(target_arch = "wasm32"))]
#[test]
fn subjects_are_keys_or_identifiers() {
    use splinelab::error::{phrase, PHRASES};
    let keys: Vec<&str> = PHRASES.iter().map(|(k, _)| *k).collect();
    let mut sorted = keys.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(keys, sorted, "PHRASES sorted by key, each key once");
    assert_eq!(phrase("bezier-curve"), "a Bézier curve");
    assert_eq!(
        phrase("knotsU"),
        "knotsU",
        "an identifier is its own phrase"
    );

    let field = subject_fields();
    let mut checked = 0;
    for path in rust_files(std::path::Path::new("src")) {
        let text = std::fs::read_to_string(&path).unwrap();
        for line in text.lines() {
            let line = line.trim();
            for name in &field {
                let Some(rest) = line.strip_prefix(name) else {
                    continue;
                };
                let Some(literal) = rest.strip_prefix('"').and_then(|r| r.split('"').next()) else {
                    continue;
                };
                checked += 1;
                // One word, or a list of option words ("0, 1").
                assert!(
                    literal.split(", ").all(|word| !word.contains(' ')),
                    "{}: {name}\"{literal}\" is English text; add a key to error/phrase.rs",
                    path.display()
                );
                if literal.contains('-') {
                    assert!(
                        keys.contains(&literal),
                        "{}: no phrase for key {literal:?}",
                        path.display()
                    );
                }
            }
        }
    }
    assert!(
        checked > 40,
        "only {checked} subject literals found: the scan is broken"
    );
}

/// The field prefixes that hold a subject, as they appear in a struct literal.
#[cfg(not(target_arch = "wasm32"))]
fn subject_fields() -> Vec<&'static str> {
    vec![
        "what: ",
        "expected: ",
        "needed_by: ",
        "reason: ",
        "check_finite(",
        "check_all_finite(values, ",
    ]
}

#[cfg(not(target_arch = "wasm32"))]
fn rust_files(dir: &std::path::Path) -> Vec<std::path::PathBuf> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            out.extend(rust_files(&path));
        } else if path.extension().is_some_and(|e| e == "rs") && !path.starts_with("src/error") {
            out.push(path);
        }
    }
    out
}
