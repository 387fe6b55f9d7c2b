//! `interpolateSurfaceParams` at the JavaScript boundary, in Node: `{ u, v }` Float64Arrays, the
//! default kind "chord", hand-computed values on an uneven grid, and clear errors.
#![cfg(all(target_arch = "wasm32", target_os = "unknown"))]

mod common;

use common::{float64_field as field, js_message as message};
use splinelab::wasm;
use wasm_bindgen::JsValue;
use wasm_bindgen_test::wasm_bindgen_test as test;

/// A 3 × 3 grid: rows at x = 0, 1, 3, columns at y = 0, 2, 6, flat (z = 0).
fn grid() -> JsValue {
    let values: Vec<f64> = [0.0, 1.0, 3.0]
        .iter()
        .flat_map(|&x| [0.0, 2.0, 6.0].into_iter().flat_map(move |y| [x, y, 0.0]))
        .collect();
    js_sys::Float64Array::from(&values[..]).into()
}

#[test]
fn params_by_kind_with_chord_the_default() {
    // Chord: every column has steps 1, 2 → 0, 1/3, 1; every row 2, 4 → 0, 1/3, 1.
    let chord = wasm::interpolate_surface_params(grid(), 3.0, 3.0, JsValue::UNDEFINED).unwrap();
    for key in ["u", "v"] {
        let values = field(&chord, key);
        assert_eq!(values.len(), 3);
        assert!((values[1] - 1.0 / 3.0).abs() < 1e-15, "{key}: {values:?}");
        assert_eq!((values[0], values[2]), (0.0, 1.0), "{key}: {values:?}");
    }
    let uniform = wasm::interpolate_surface_params(grid(), 3.0, 3.0, "uniform".into()).unwrap();
    assert_eq!(field(&uniform, "u"), vec![0.0, 0.5, 1.0]);
}

#[test]
fn params_refuse_bad_input_clearly() {
    let wrong = message(wasm::interpolate_surface_params(
        grid(),
        3.0,
        4.0,
        JsValue::UNDEFINED,
    ));
    assert!(wrong.contains('3') && wrong.contains('4'), "{wrong}");
    let kind = message(wasm::interpolate_surface_params(
        grid(),
        3.0,
        3.0,
        "arc".into(),
    ));
    assert!(kind.contains("arc"), "{kind}");
}
