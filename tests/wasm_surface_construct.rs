//! Issue 14's surface additions at the JavaScript boundary, in Node: the layouts of
//! `deCasteljau` and `matrixForm`, iso-curves of the right class, curvature on a mesh's
//! Float32Array uvs, and `revolve`/`extrude`/`ruled`/`interpolateSurface` taking curve objects
//! of either class, with clear errors for bad input.
#![cfg(all(target_arch = "wasm32", target_os = "unknown"))]

mod common;

use common::{float64_field as field, js_message as message};
use splinelab::wasm::{self, JsBSplineCurve, JsBSplineSurface, JsBezierCurve, JsBezierSurface};
use std::f64::consts::TAU;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test as test;

fn arr(values: &[f64]) -> JsValue {
    js_sys::Float64Array::from(values).into()
}

/// A bicubic patch `P_ij = (i, j, h_ij)`.
fn bicubic(weights: JsValue) -> JsBezierSurface {
    let h = [
        0.0, 1.0, -1.0, 0.5, 2.0, -1.5, 1.0, 0.0, 0.5, 2.5, -2.0, 1.0, 1.0, 0.0, 1.5, -0.5,
    ];
    let points: Vec<f64> = (0..16)
        .flat_map(|k| [(k / 4) as f64, (k % 4) as f64, h[k]])
        .collect();
    JsBezierSurface::new(arr(&points), 4.0, 4.0, weights).unwrap()
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

#[test]
fn de_casteljau_returns_rows_and_column_or_columns_and_row() {
    let patch = bicubic(JsValue::UNDEFINED);
    let point = patch.evaluate(0.3, 0.8).unwrap();
    let rows = patch.de_casteljau(0.3, 0.8, JsValue::UNDEFINED).unwrap();
    let (first, column) = (field(&rows, "rows"), field(&rows, "column"));
    assert_eq!((first.len(), column.len()), (4 * 10 * 3, 10 * 3));
    assert_eq!(first[..12], patch.control_points()[..12]);
    assert!(close(&column[27..], &point, 1e-12));
    let cols = patch.de_casteljau(0.3, 0.8, "columns".into()).unwrap();
    let (first, row) = (field(&cols, "columns"), field(&cols, "row"));
    assert_eq!((first.len(), row.len()), (4 * 10 * 3, 10 * 3));
    assert!(close(&row[27..], &point, 1e-12));
    assert!(js_sys::Reflect::get(&cols, &"rows".into())
        .unwrap()
        .is_undefined());
    assert!(message(patch.de_casteljau(0.3, 0.8, "diagonal".into()))
        .contains("order must be one of \"rows\", \"columns\", got \"diagonal\""));
    assert!(message(patch.de_casteljau(1.5, 0.8, JsValue::UNDEFINED)).contains("u = 1.5"));
}

#[test]
fn matrix_form_has_the_notes_basis() {
    let patch = bicubic(JsValue::UNDEFINED);
    let form = patch.matrix_form().unwrap();
    let m = [
        -1.0, 3.0, -3.0, 1.0, 3.0, -6.0, 3.0, 0.0, -3.0, 3.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0,
    ];
    assert_eq!(field(&form, "basisU"), m);
    assert_eq!(field(&form, "basisV"), m);
    let a = field(&form, "coefficients");
    assert_eq!(a.len(), 48);
    // S(1, 1) = Σ A (all powers 1) = P_33; S(0, 0) = A_33 = P_00.
    let sum: Vec<f64> = (0..3).map(|c| a.iter().skip(c).step_by(3).sum()).collect();
    assert!(close(&sum, &patch.evaluate(1.0, 1.0).unwrap(), 1e-12));
    assert_eq!(a[45..], patch.control_points()[..3]);
    let mut weights = [1.0; 16];
    weights[5] = 3.0;
    let rational = bicubic(arr(&weights));
    assert!(message(rational.matrix_form()).contains("matrixForm works on polynomial patches"));
}

#[test]
fn iso_curves_are_bezier_or_bspline_curves() {
    let patch = bicubic(JsValue::UNDEFINED);
    let c: JsBezierCurve = patch.iso_curve_u(0.25).unwrap();
    assert_eq!((c.dim(), c.degree(), c.rational()), (3, 3, false));
    assert!(close(
        &c.evaluate(0.6).unwrap(),
        &patch.evaluate(0.25, 0.6).unwrap(),
        1e-12
    ));
    let c = patch.iso_curve_v(0.6).unwrap();
    assert!(close(
        &c.evaluate(0.25).unwrap(),
        &patch.evaluate(0.25, 0.6).unwrap(),
        1e-12
    ));
    let knots = arr(&[0.0, 0.0, 1.0, 2.0, 2.0]);
    let points: Vec<f64> = (0..9)
        .flat_map(|k| [(k / 3) as f64, (k % 3) as f64, (k * k % 5) as f64])
        .collect();
    let s = JsBSplineSurface::new(
        arr(&points),
        3.0,
        3.0,
        1.0,
        1.0,
        knots.clone(),
        knots,
        arr(&[1.0, 2.0, 1.0, 1.0, 1.0, 3.0, 1.0, 1.0, 1.0]),
    )
    .unwrap();
    let c: JsBSplineCurve = s.iso_curve_u(1.5).unwrap();
    assert!(c.rational());
    assert_eq!(c.domain(), vec![0.0, 2.0]);
    assert!(close(
        &c.evaluate(0.7).unwrap(),
        &s.evaluate(1.5, 0.7).unwrap(),
        1e-12
    ));
    assert!(message(s.iso_curve_v(3.0)).contains("v = 3"));
}

#[test]
fn curvatures_take_a_meshs_float32_uvs() {
    // The unit sphere as a revolved half circle: K = 1, |H| = 1; the poles give NaN.
    let half = wasm::rational::ellipse_arc(
        arr(&[0.0, 0.0, 0.0]),
        arr(&[1.0, 0.0, 0.0]),
        arr(&[0.0, 0.0, 1.0]),
        -TAU / 4.0,
        TAU / 2.0,
    )
    .unwrap();
    let sphere = wasm::revolve(half.into(), arr(&[0.0; 3]), arr(&[0.0, 0.0, 1.0]), None).unwrap();
    let uvs = js_sys::Float32Array::from(&[0.3f32, 0.7, 0.1, 0.0, 1.0, 0.45][..]);
    let kh = sphere.curvatures(uvs.into()).unwrap();
    assert_eq!(kh.len(), 6);
    assert!((kh[0] - 1.0).abs() < 1e-6 && (kh[1].abs() - 1.0).abs() < 1e-6);
    assert!(kh[2].is_nan() && kh[3].is_nan());
    let [k, h] = sphere.curvature(0.5, 0.5).unwrap()[..] else {
        panic!()
    };
    assert!((k - 1.0).abs() < 1e-12 && (h.abs() - 1.0).abs() < 1e-12);
    assert!(message(sphere.curvature(0.5, 0.0)).contains("no normal at (u, v) = (0.5, 0)"));
    assert!(message(sphere.curvatures(arr(&[0.5]))).contains("coordinate count 1"));
}

#[test]
fn revolve_takes_either_curve_class() {
    let (big_r, r) = (2.0, 0.5);
    let circle = wasm::rational::ellipse_arc(
        arr(&[big_r, 0.0, 0.0]),
        arr(&[r, 0.0, 0.0]),
        arr(&[0.0, 0.0, r]),
        0.0,
        TAU,
    )
    .unwrap();
    let torus = wasm::revolve(circle.into(), arr(&[0.0; 3]), arr(&[0.0, 0.0, 2.0]), None).unwrap();
    assert_eq!(
        (
            torus.rows(),
            torus.cols(),
            torus.degree_u(),
            torus.rational()
        ),
        (9, 9, 2, true)
    );
    let grid = torus
        .sample_grid(arr(&[0.0, 0.13, 0.5, 0.77]), arr(&[0.0, 0.3, 0.9]))
        .unwrap();
    for p in grid.chunks(3) {
        let d = ((p[0].hypot(p[1]) - big_r).powi(2) + p[2] * p[2]).sqrt();
        assert!((d - r).abs() < 1e-12, "off the torus by {}", d - r);
    }
    // A quadratic Bézier profile, a quarter turn: one arc, v on the profile's [0, 1].
    let bezier = JsBezierCurve::new(
        arr(&[1.0, 0.0, 0.0, 2.0, 0.0, 1.0, 1.0, 0.0, 2.0]),
        3.0,
        JsValue::UNDEFINED,
    )
    .unwrap();
    let vase = wasm::revolve(
        bezier.clone_curve().into(),
        arr(&[0.0; 3]),
        arr(&[0.0, 0.0, 1.0]),
        Some(TAU / 4.0),
    )
    .unwrap();
    assert_eq!((vase.rows(), vase.cols(), vase.degree_v()), (3, 3, 2));
    assert_eq!(vase.knots_v(), vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]);
    assert!(close(
        &vase.evaluate(1.0, 0.5).unwrap(),
        &[0.0, 1.5, 1.0],
        1e-12
    ));
    // The curve passed in is still usable (read, not taken).
    assert_eq!(bezier.degree(), 2);
    let plane = JsBezierCurve::new(arr(&[0.0, 0.0, 1.0, 1.0]), 2.0, JsValue::UNDEFINED).unwrap();
    let z = || arr(&[0.0, 0.0, 1.0]);
    assert!(
        message(wasm::revolve(plane.into(), arr(&[0.0; 3]), z(), None)).contains(
            "profile: revolve builds a 3D surface and needs a 3D curve; this curve has dim = 2"
        )
    );
    assert!(message(wasm::revolve(
        bezier.clone_curve().into(),
        arr(&[0.0; 3]),
        arr(&[0.0; 3]),
        None
    ))
    .contains("axisDirection must not be the zero vector"));
    assert!(message(wasm::revolve(
        bezier.clone_curve().into(),
        arr(&[0.0; 3]),
        z(),
        Some(7.0)
    ))
    .contains("at most one full turn"));
    assert!(message(wasm::revolve(
        bezier.clone_curve().into(),
        arr(&[0.0; 2]),
        z(),
        None
    ))
    .contains("axisPoint must have 3 numbers"));
    assert!(
        message(wasm::revolve(JsValue::from(3.0), arr(&[0.0; 3]), z(), None))
            .contains("profile must be a BSplineCurve or BezierCurve, got number")
    );
}

#[test]
fn extrude_ruled_and_interpolate_surface_from_js() {
    let line = JsBezierCurve::new(
        arr(&[0.0, 0.0, 0.0, 2.0, 1.0, 0.0]),
        3.0,
        JsValue::UNDEFINED,
    )
    .unwrap();
    let s = wasm::extrude(line.clone_curve().into(), arr(&[0.0, 0.0, 3.0])).unwrap();
    assert!(close(
        &s.evaluate(0.5, 0.5).unwrap(),
        &[1.0, 0.5, 1.5],
        1e-15
    ));
    let knots = arr(&[0.0, 0.0, 0.0, 2.0, 4.0, 4.0, 4.0]);
    let b = JsBSplineCurve::new(
        arr(&[0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 2.0, 0.0, 1.0, 3.0, 1.0, 1.0]),
        3.0,
        2.0,
        knots,
        JsValue::UNDEFINED,
    )
    .unwrap();
    let r = wasm::ruled(line.into(), b.clone_curve().into()).unwrap();
    assert_eq!(
        (r.degree_u(), r.degree_v(), r.domain_u()),
        (2, 1, vec![0.0, 1.0])
    );
    let expect: Vec<f64> = [1.0, 0.5, 0.0]
        .iter()
        .zip(b.evaluate(2.0).unwrap())
        .map(|(a, b)| 0.75 * a + 0.25 * b)
        .collect();
    assert!(close(&r.evaluate(0.5, 0.25).unwrap(), &expect, 1e-12));
    assert!(message(wasm::ruled(b.clone_curve().into(), JsValue::NULL))
        .contains("curveB must be a BSplineCurve or BezierCurve, got null"));
    // A 4 × 3 grid, chord by default.
    let points: Vec<f64> = (0..12)
        .flat_map(|k| {
            [
                (k / 3) as f64,
                (k % 3) as f64 * 1.5,
                ((k * 7) % 5) as f64 * 0.3,
            ]
        })
        .collect();
    let s =
        wasm::interpolate_surface(arr(&points), 4.0, 3.0, 3.0, 2.0, JsValue::UNDEFINED).unwrap();
    assert_eq!((s.rows(), s.cols(), s.domain_u()), (4, 3, vec![0.0, 1.0]));
    assert!(close(&s.evaluate(0.0, 0.0).unwrap(), &points[..3], 1e-12));
    assert!(close(&s.evaluate(1.0, 1.0).unwrap(), &points[33..], 1e-12));
    assert!(message(wasm::interpolate_surface(
        arr(&points),
        4.0,
        4.0,
        3.0,
        2.0,
        JsValue::UNDEFINED
    ))
    .contains("rows·cols·3 = 4·4·3 = 48 coordinates, got 36"));
    assert!(message(wasm::interpolate_surface(
        arr(&points),
        4.0,
        3.0,
        3.0,
        3.0,
        JsValue::UNDEFINED
    ))
    .contains("degreeV: "));
    assert!(message(wasm::interpolate_surface(
        arr(&points),
        4.0,
        3.0,
        3.0,
        2.0,
        "arc".into()
    ))
    .contains("kind must be one of"));
    // The grid's errors come before the option's.
    let wrong_grid = wasm::interpolate_surface(arr(&points), 4.0, 4.0, 3.0, 2.0, "arc".into());
    assert!(message(wrong_grid).contains("rows·cols·3"));
}
