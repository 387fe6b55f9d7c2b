//! The JavaScript boundary of the typed curves, in Node: a bad text throws an Error whose
//! `code` and plain-object `params` place it (piece, field, characters), results have the
//! documented shapes (plot runs, joints, frame, TeX), and `toBezier` hands over a BezierCurve.
#![cfg(all(target_arch = "wasm32", target_os = "unknown"))]

mod common;

use splinelab::wasm::parametric::{expression_names, parametric_curve, JsParametricCurve};
use wasm_bindgen::{JsCast, JsValue};
use wasm_bindgen_test::wasm_bindgen_test as test;

fn get(object: &JsValue, key: &str) -> JsValue {
    js_sys::Reflect::get(object, &JsValue::from_str(key)).unwrap()
}

/// `pieces` as a JS array of `{ x, y, from, to }`.
fn pieces(list: &[(&str, &str, &str, &str)]) -> JsValue {
    let array = js_sys::Array::new();
    for (x, y, from, to) in list {
        let o = js_sys::Object::new();
        for (k, v) in [("x", x), ("y", y), ("from", from), ("to", to)] {
            js_sys::Reflect::set(&o, &k.into(), &JsValue::from_str(v)).unwrap();
        }
        array.push(&o);
    }
    array.into()
}

fn curve(list: &[(&str, &str, &str, &str)]) -> JsParametricCurve {
    parametric_curve(pieces(list), JsValue::UNDEFINED).unwrap()
}

#[test]
fn a_typing_error_is_placed_for_the_page() {
    let e: JsValue = common::js_error(parametric_curve(
        pieces(&[("t", "t", "0", "1"), ("t", "2 + q t", "1", "2")]),
        JsValue::UNDEFINED,
    ))
    .into();
    assert_eq!(get(&e, "code"), "unknown-name");
    let params = get(&e, "params");
    // A plain object (not a Map), as every other error's params.
    assert!(params.is_object() && !params.is_instance_of::<js_sys::Map>());
    assert_eq!(get(&params, "piece").as_f64(), Some(1.0));
    assert_eq!(get(&params, "field"), "y");
    assert_eq!(get(&params, "start").as_f64(), Some(4.0));
    assert_eq!(get(&params, "end").as_f64(), Some(5.0));
    assert_eq!(get(&params, "name"), "q");
    let message = js_sys::Error::from(e).message();
    assert!(String::from(message).starts_with("pieces[1].y, characters 4–5: unknown name \"q\""));
    // Parameters declared make the same text valid; every other name is refused.
    let params = js_sys::Object::new();
    js_sys::Reflect::set(&params, &"q".into(), &JsValue::from_f64(3.0)).unwrap();
    let c = parametric_curve(pieces(&[("t", "2 + q t", "0", "1")]), params.into()).unwrap();
    assert_eq!(c.evaluate(0.5).unwrap(), vec![0.5, 3.5]);
    // A field that is not text, and a missing one.
    let o = js_sys::Object::new();
    js_sys::Reflect::set(&o, &"x".into(), &JsValue::from_str("t")).unwrap();
    let e: JsValue = common::js_error(parametric_curve(
        js_sys::Array::of1(&o).into(),
        JsValue::UNDEFINED,
    ))
    .into();
    assert_eq!(get(&e, "code"), "missing-field");
    assert_eq!(get(&get(&e, "params"), "field"), "y");
}

#[test]
fn results_have_the_documented_shapes() {
    let c = curve(&[("t", "tan(t)", "0", "pi")]);
    let box_ = js_sys::Float64Array::from(&[0.0, -5.0, 4.0, 5.0][..]);
    let plot = c.plot(0.01, box_.into()).unwrap();
    let points = common::float64_field(&plot, "points");
    let ts = common::float64_field(&plot, "ts");
    assert_eq!(points.len(), 2 * ts.len());
    assert_eq!(
        ts.iter().filter(|t| t.is_nan()).count(),
        1,
        "one break at the pole"
    );
    assert_eq!(get(&plot, "complete"), JsValue::TRUE);
    assert!(c.plot(0.0, JsValue::UNDEFINED).is_err());

    let pw = curve(&[("1 - t^2", "t", "0", "1"), ("t^2 - 2t + 1", "t", "1", "2")]);
    let joints = pw.joints().unwrap();
    assert_eq!(joints.length(), 1);
    let j = joints.get(0);
    assert_eq!(get(&j, "c").as_f64(), Some(0.0));
    assert_eq!(get(&j, "exact"), JsValue::TRUE);
    assert_eq!(get(&j, "order").as_f64(), Some(1.0));
    assert_eq!(common::float64_field(&j, "left"), vec![-2.0, 1.0]);
    assert_eq!(common::float64_field(&j, "right"), vec![0.0, 1.0]);

    let tex = curve(&[("cos(t)", "sin(t)", "0", "2pi")]).tex(0.0).unwrap();
    assert_eq!(get(&get(&tex, "x"), "d1"), "-\\sin t");
    assert_eq!(get(&tex, "to"), "2\\pi");
    assert!(curve(&[("t", "t", "0", "1")]).tex(1.0).is_err());

    let frame = curve(&[("cos(t)", "sin(t)", "0", "2pi")])
        .frame(0.0)
        .unwrap();
    assert_eq!(get(&frame, "curvature").as_f64(), Some(1.0));
    assert_eq!(common::float64_field(&frame, "tangent").len(), 2);
}

#[test]
fn a_polynomial_piece_becomes_a_bezier_curve() {
    let c = curve(&[("6.5t^5 - 7.2t^3 + 3t^2 - 2.1t - 5", "t", "0", "1")]);
    assert!(c.is_polynomial(0.0).unwrap());
    let fractions = c.bezier_fractions(0.0).unwrap().unwrap();
    assert_eq!(fractions[2], "-271/50");
    let bezier = c.to_bezier(0.0).unwrap();
    assert_eq!(bezier.degree(), 5);
    assert!(curve(&[("cos(t)", "t", "0", "1")]).to_bezier(0.0).is_err());
    assert!(c.to_bezier(1.5).is_err());
    assert_eq!(
        expression_names(JsValue::from_str("a cos(t) + b_1 t + ω a")).unwrap(),
        vec!["a", "b_1", "ω"]
    );
    assert!(expression_names(JsValue::from_f64(1.0)).is_err());
}
