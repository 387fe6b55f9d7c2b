//! The JavaScript boundary of section 5's cubic family, in Node: thrown errors name the bad
//! value, the flat layouts (Aitken's levels, tangents, the system object) have the documented
//! sizes, and `setPoint` equals a rebuild.
#![cfg(all(target_arch = "wasm32", target_os = "unknown"))]

mod common;

use common::js_message as message;
use splinelab::wasm::{self, interp, JsCubicSpline};
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test as test;

fn arr(values: &[f64]) -> JsValue {
    js_sys::Float64Array::from(values).into()
}

fn s(text: &str) -> JsValue {
    JsValue::from_str(text)
}

const POINTS: [f64; 10] = [0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 5.0, 1.0, 6.0, 3.0];
const PARAMS: [f64; 5] = [0.0, 0.7, 1.5, 3.1, 3.6];

fn natural() -> JsCubicSpline {
    interp::cubic_spline(
        arr(&POINTS),
        2.0,
        arr(&PARAMS),
        s("natural"),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    )
    .unwrap()
}

/// A numeric array field of a plain JS object.
fn field(object: &JsValue, name: &str) -> Vec<f64> {
    let value = js_sys::Reflect::get(object, &s(name)).unwrap();
    js_sys::Array::from(&value)
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect()
}

fn number(object: &JsValue, name: &str) -> f64 {
    js_sys::Reflect::get(object, &s(name))
        .unwrap()
        .as_f64()
        .unwrap()
}

#[test]
fn errors_name_the_bad_value() {
    let u = JsValue::UNDEFINED;
    assert_eq!(
        message(interp::lagrange(
            arr(&POINTS),
            2.0,
            arr(&[0.0, 1.0, 1.0, 2.0, 3.0])
        )),
        "params must increase strictly: t_2 = 1 is not above t_1 = 1"
    );
    assert_eq!(
        message(interp::lagrange(arr(&POINTS), 2.0, arr(&[0.0, 1.0]))),
        "params must have one value per point (5), got 2"
    );
    let m = message(interp::cubic_spline(
        arr(&POINTS),
        2.0,
        arr(&PARAMS),
        s("free"),
        u.clone(),
        u.clone(),
    ));
    assert!(m.contains("\"free\"") && m.contains("not-a-knot"), "{m}");
    assert_eq!(
        message(interp::cubic_spline(
            arr(&POINTS),
            2.0,
            arr(&PARAMS),
            s("clamped"),
            arr(&[1.0, 0.0]),
            u.clone()
        )),
        "the \"clamped\" end condition needs endTangent, which was not given"
    );
    assert_eq!(
        message(interp::cubic_spline(
            arr(&POINTS),
            2.0,
            arr(&PARAMS),
            s("clamped"),
            arr(&[1.0, 0.0, 2.0]),
            arr(&[1.0, 0.0])
        )),
        "startTangent must have 2 numbers, got 3"
    );
    assert_eq!(
        message(interp::cubic_spline(
            arr(&POINTS),
            2.0,
            arr(&PARAMS),
            s("periodic"),
            u.clone(),
            u.clone()
        )),
        "periodic interpolation needs the last point (point 4) equal to the first"
    );
    assert!(
        message(interp::catmull_rom(arr(&POINTS), 2.0, Some(1.5), None))
            .contains("alpha = 1.5 is outside [0, 1]")
    );
    assert_eq!(
        message(interp::hermite_spline(
            arr(&POINTS),
            2.0,
            arr(&PARAMS),
            arr(&[0.0; 8])
        )),
        "tangents must have 10 numbers, got 8"
    );
    assert_eq!(
        message(interp::bessel_spline(arr(&[0.0, 0.0]), 2.0, arr(&[0.0]))),
        "a Bessel spline needs at least 2 data points, got 1"
    );
    // Points are checked before params, params before the end condition.
    let m = message(interp::cubic_spline(
        arr(&[0.0, 0.0, f64::NAN, 1.0]),
        2.0,
        arr(&[1.0, 0.0]),
        s("free"),
        u.clone(),
        u.clone(),
    ));
    assert!(m.contains("coordinate 2 is NaN"), "{m}");
    let m = message(interp::cubic_spline(
        arr(&POINTS),
        2.0,
        arr(&[0.0, 2.0, 1.0, 3.0, 4.0]),
        s("free"),
        u.clone(),
        u,
    ));
    assert!(m.starts_with("params must increase"), "{m}");
    let c = natural();
    assert_eq!(
        message(c.evaluate(4.0)),
        "t = 4 is outside the domain [0, 3.6]"
    );
    let mut c = natural();
    assert_eq!(
        message(c.set_tangent(0.0, arr(&[1.0, 0.0]))),
        "setTangent works on splines built by hermiteSpline; this one was built by cubicSpline"
    );
}

#[test]
fn flat_layouts() {
    let lagrange = interp::lagrange(arr(&POINTS), 2.0, arr(&PARAMS)).unwrap();
    // Five points: levels of 5, 4, 3, 2, 1 points, 2 numbers each.
    let tri = lagrange.aitken(1.0).unwrap();
    assert_eq!(tri.len(), 15 * 2);
    assert_eq!(&tri[..10], &POINTS);
    let apex = lagrange.evaluate(1.0).unwrap();
    for (a, b) in tri[28..].iter().zip(&apex) {
        assert!((a - b).abs() < 1e-13, "apex {a} vs P(t) {b}");
    }
    assert_eq!(lagrange.basis(1.0).unwrap().len(), 5);
    assert_eq!(lagrange.sample_uniform(7.0).unwrap().len(), 14);
    assert_eq!(lagrange.domain(), vec![0.0, 3.6]);
    let c = natural();
    assert_eq!(c.tangents().len(), 10);
    assert_eq!(c.params(), PARAMS.to_vec());
    assert_eq!(c.points(), POINTS.to_vec());
    assert_eq!(c.piece_count(), 4);
    assert_eq!(
        c.sample_derivatives(arr(&[0.0, 1.0, 2.0]), 2.0)
            .unwrap()
            .len(),
        6
    );
    assert_eq!(c.derivative(1.0, 7.0).unwrap(), vec![0.0, 0.0]);
    assert_eq!(c.to_bezier().unwrap().piece_count(), 4);
    assert_eq!(c.to_bspline().unwrap().control_points().len(), (4 + 3) * 2);
    let cr = interp::catmull_rom(arr(&POINTS), 2.0, None, Some(true)).unwrap();
    assert_eq!(cr.piece_count(), 5);
    assert_eq!(cr.points().len(), 12);
    assert!(cr.closed());
    assert_eq!(
        cr.to_bspline().unwrap().control_points().len(),
        (2 * 5 + 2) * 2
    );
    // Params given as a kind or an α compute them as parameterize does.
    let by_kind = interp::bessel_spline(arr(&POINTS), 2.0, s("chord")).unwrap();
    let chord = wasm::bspline::parameterize(arr(&POINTS), 2.0, s("chord")).unwrap();
    assert_eq!(by_kind.params(), chord);
    let by_alpha = wasm::bspline::parameterize(arr(&POINTS), 2.0, JsValue::from_f64(1.0)).unwrap();
    assert_eq!(by_alpha, chord);
    let uniform = wasm::bspline::parameterize(
        arr(&[0.0, 0.0, 0.0, 0.0, 1.0, 1.0]),
        2.0,
        JsValue::from_f64(0.0),
    )
    .unwrap();
    assert_eq!(uniform, vec![0.0, 1.0, 2.0]);
}

#[test]
fn system_shape() {
    let system = natural().system().unwrap();
    assert_eq!(number(&system, "size"), 5.0);
    assert_eq!(field(&system, "diagonal").len(), 5);
    assert_eq!(field(&system, "lower").len(), 4);
    assert_eq!(field(&system, "upper").len(), 4);
    assert_eq!(field(&system, "rhs").len(), 10);
    assert_eq!(field(&system, "solution"), natural().tangents());
    assert!(field(&system, "corners").is_empty());
    // Natural end rows: 2m_0 + m_1 = 3 s_0.
    assert_eq!(field(&system, "diagonal")[0], 2.0);
    assert_eq!(field(&system, "upper")[0], 1.0);
    let mut closed = POINTS.to_vec();
    closed[8] = 0.0;
    closed[9] = 0.0;
    let u = JsValue::UNDEFINED;
    let periodic =
        interp::cubic_spline(arr(&closed), 2.0, arr(&PARAMS), s("periodic"), u.clone(), u).unwrap();
    let system = periodic.system().unwrap();
    assert_eq!(number(&system, "size"), 4.0);
    assert_eq!(field(&system, "corners").len(), 2);
    assert_eq!(field(&system, "rhs").len(), 8);
    let cr = interp::catmull_rom(arr(&POINTS), 2.0, None, None).unwrap();
    assert!(message(cr.system()).contains("system() works on splines built by cubicSpline"));
}

#[test]
fn set_point_equals_a_rebuild() {
    let moved = [2.5, -1.0];
    let mut points = POINTS.to_vec();
    points[4] = moved[0];
    points[5] = moved[1];
    let u = JsValue::UNDEFINED;
    let mut c = natural();
    c.set_point(2.0, arr(&moved)).unwrap();
    let rebuilt =
        interp::cubic_spline(arr(&points), 2.0, arr(&PARAMS), s("natural"), u.clone(), u).unwrap();
    assert_eq!(
        c.sample_uniform(50.0).unwrap(),
        rebuilt.sample_uniform(50.0).unwrap()
    );
    assert_eq!(c.tangents(), rebuilt.tangents());
    let mut cr = interp::catmull_rom(arr(&POINTS), 2.0, Some(0.5), None).unwrap();
    cr.set_point(2.0, arr(&moved)).unwrap();
    let rebuilt = interp::catmull_rom(arr(&points), 2.0, Some(0.5), None).unwrap();
    assert_eq!(cr.params(), rebuilt.params());
    assert_eq!(
        cr.sample_uniform(50.0).unwrap(),
        rebuilt.sample_uniform(50.0).unwrap()
    );
    let tangents = [1.0, 0.0, 0.0, 1.0, 2.0, 1.0, 1.0, -1.0, 0.5, 2.0];
    let mut h = interp::hermite_spline(arr(&POINTS), 2.0, arr(&PARAMS), arr(&tangents)).unwrap();
    h.set_tangent(1.0, arr(&[3.0, 3.0])).unwrap();
    let mut changed = tangents;
    changed[2] = 3.0;
    changed[3] = 3.0;
    assert_eq!(h.tangents(), changed.to_vec());
    assert!(message(h.set_point(5.0, arr(&moved))).contains("index 5 is out of range"));
}

#[test]
fn defaults_and_spacings() {
    // end defaults to "natural".
    let c = interp::cubic_spline(
        arr(&POINTS),
        2.0,
        arr(&PARAMS),
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
        JsValue::UNDEFINED,
    )
    .unwrap();
    assert_eq!(c.tangents(), natural().tangents());
    // A Lagrange curve on a spacing recomputes its params when a point moves.
    let mut l = interp::lagrange(arr(&POINTS), 2.0, s("chord")).unwrap();
    l.set_point(4.0, arr(&[9.0, 3.0])).unwrap();
    let mut moved = POINTS.to_vec();
    moved[8] = 9.0;
    let rebuilt = interp::lagrange(arr(&moved), 2.0, s("chord")).unwrap();
    assert_eq!(l.params(), rebuilt.params());
    assert_eq!(
        l.sample_uniform(9.0).unwrap(),
        rebuilt.sample_uniform(9.0).unwrap()
    );
    // cardinalSpline's tension defaults to 0; catmullRom's alpha to 0.5.
    let card = interp::cardinal_spline(arr(&POINTS), 2.0, arr(&PARAMS), None).unwrap();
    let card0 = interp::cardinal_spline(arr(&POINTS), 2.0, arr(&PARAMS), Some(0.0)).unwrap();
    assert_eq!(card.tangents(), card0.tangents());
    let cr = interp::catmull_rom(arr(&POINTS), 2.0, None, None).unwrap();
    let centripetal = wasm::bspline::parameterize(arr(&POINTS), 2.0, s("centripetal")).unwrap();
    assert_eq!(cr.params(), centripetal);
    assert_eq!(cr.kind(), "catmullRom");
}

#[test]
fn hermite_basis_and_bezier_form() {
    assert_eq!(
        interp::hermite_basis_js(0.5, None).unwrap(),
        vec![0.5, 0.5, 0.125, -0.125]
    );
    assert_eq!(
        interp::hermite_basis_js(0.0, Some(1.0)).unwrap(),
        vec![0.0, 0.0, 1.0, 0.0]
    );
    assert!(message(interp::hermite_basis_js(f64::NAN, None)).contains("s is NaN"));
    let q = interp::hermite_bezier(
        arr(&[0.0, 0.0]),
        arr(&[3.0, 3.0]),
        arr(&[4.0, 1.0]),
        arr(&[6.0, -3.0]),
        Some(2.0),
    )
    .unwrap();
    assert_eq!(q, vec![0.0, 0.0, 2.0, 2.0, 0.0, 3.0, 4.0, 1.0]);
    assert_eq!(
        message(interp::hermite_bezier(
            arr(&[0.0, 0.0]),
            arr(&[3.0]),
            arr(&[4.0, 1.0]),
            arr(&[6.0, -3.0]),
            None
        )),
        "m0 must have 2 numbers, got 1"
    );
}
