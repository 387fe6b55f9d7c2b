//! JavaScript bindings (wasm-bindgen): the only module that knows about JS.
//!
//! Thin wrappers: flat `Float64Array`s in and out, camelCase names, and every [`crate::Error`]
//! turned into a thrown JS `Error` carrying its message (via `JsError`). No maths here.
//! Nothing here may panic (a panic inside wasm kills the module for the whole page), which
//! clippy enforces for this module tree.
#![deny(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    clippy::indexing_slicing
)]

pub mod bezier;
pub mod bspline;
pub mod rational;

pub use bezier::{JsBezierCurve, JsCompositeBezier};
pub use bspline::JsBSplineCurve;

use wasm_bindgen::prelude::*;

/// The crate version, e.g. `"0.1.0"`.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").into()
}
