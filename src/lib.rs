//! # splinelab
//!
//! Parametric curves and surfaces for teaching — Bézier, B-spline, NURBS, interpolating
//! splines, tensor-product patches — with the constructions (de Casteljau and de Boor
//! triangles, subdivision halves, intersection boxes) returned as data, compiled to
//! WebAssembly for an interactive playground.
//!
//! The algorithm core is plain Rust over `glam`'s `f64` vectors and builds and tests natively;
//! the JavaScript bindings live in `wasm` only, which is built for `wasm32-unknown-unknown`
//! alone (the platform services the core needs — number text, `sin`/`cos` — sit in a leaf
//! module with a plain-Rust fallback). Conventions follow the syllabus: degree `p`,
//! control points `P_0..P_n`, Bézier curves on `t ∈ [0, 1]` (or an explicit `[a, b]`),
//! rational curves evaluated on homogeneous points `(w_i P_i, w_i)` with one division at the
//! end. Invalid input gives an [`Error`] whose message names the bad value; nothing reachable
//! from JavaScript panics.

pub mod bezier;
pub mod bspline;
pub mod curve;
pub mod error;
pub mod expr;
pub mod fit;
pub mod geom;
pub mod interp;
pub mod parametric;
mod platform;
pub mod rational;
pub mod surface;
#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
pub mod wasm;

/// The capability traits ([`curve`]), for `use splinelab::prelude::*;`.
pub mod prelude {
    pub use crate::curve::{ControlPolygon, ParamCurve, ParamCurveDeriv};
}

pub use bezier::BezierCurve;
pub use bspline::BSplineCurve;
pub use error::{Error, Result};
pub use glam::{DMat3, DVec2, DVec3, DVec4};
pub use parametric::ParametricCurve;
pub use surface::BSplineSurface;
