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

/// Runs `$body` with `$c` bound to the curve of either dimension of a `Curve` enum (`D2`,
/// `D3`; see [`curve_enum!`]).
macro_rules! with_curve {
    ($curve:expr, $c:ident => $body:expr) => {
        match $curve {
            Curve::D2($c) => $body,
            Curve::D3($c) => $body,
        }
    };
}

/// Maps a curve of either dimension to a curve of the same dimension.
macro_rules! map_curve {
    ($curve:expr, $c:ident => $body:expr) => {
        match $curve {
            Curve::D2($c) => Curve::D2($body),
            Curve::D3($c) => Curve::D3($body),
        }
    };
}

/// Defines `enum Curve { D2(Ty<DVec2>), D3(Ty<DVec3>) }`, the 2D or 3D core curve behind one JS
/// class, and implements [`ClassCurve`] for it.
macro_rules! curve_enum {
    ($ty:ident) => {
        /// A 2D or 3D curve behind one JS class.
        #[derive(Clone)]
        enum Curve {
            D2($ty<DVec2>),
            D3($ty<DVec3>),
        }

        impl_class_curve!();
    };
}

/// Implements [`ClassCurve`] for the `Curve` enum (`D2`, `D3`) of the module it is invoked in.
macro_rules! impl_class_curve {
    () => {
        impl super::ClassCurve for Curve {
            fn dim(&self) -> usize {
                match self {
                    Curve::D2(_) => 2,
                    Curve::D3(_) => 3,
                }
            }

            fn sample_into(&self, params: &[f64], out: &mut [f64]) -> Result<(), Error> {
                with_curve!(self, c => c.sample_into(params, out))
            }

            fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<(), Error> {
                with_curve!(self, c => c.sample_uniform_into(count, out))
            }

            fn set_control_point(&mut self, i: usize, coords: &[f64]) -> Result<(), Error> {
                with_curve!(self, c => c.set_control_point(i, $crate::wasm::bezier::point_from(coords)?))
            }

            fn set_weight(&mut self, i: usize, w: f64) -> Result<(), Error> {
                with_curve!(self, c => c.set_weight(i, w))
            }
        }
    };
}

pub mod bezier;
pub mod bspline;
pub mod rational;
pub mod surface;

pub use bezier::{JsBezierCurve, JsCompositeBezier};
pub use bspline::JsBSplineCurve;
pub use surface::{JsBSplineSurface, JsBezierSurface};

use crate::error::Error;
use js_sys::Float64Array;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// A `Float64Array` viewing `buffer` where it lies in the wasm memory (no copy). It stays
/// valid while `buffer` is neither moved nor freed and the memory does not grow (growing
/// detaches every view: its length becomes 0).
pub(crate) fn memory_view(buffer: &[f64]) -> Result<Float64Array, JsError> {
    let memory: js_sys::WebAssembly::Memory = wasm_bindgen::memory()
        .dyn_into()
        .map_err(|_| JsError::new("the wasm memory is not a WebAssembly.Memory"))?;
    let offset = u32::try_from(buffer.as_ptr() as usize)
        .map_err(|_| JsError::new("the buffer lies outside 32-bit wasm memory"))?;
    let length = u32::try_from(buffer.len())
        .map_err(|_| JsError::new("the buffer is too long for a Float64Array view"))?;
    Ok(Float64Array::new_with_byte_offset_and_length(
        &memory.buffer(),
        offset,
        length,
    ))
}

/// A curve of either dimension behind a JS class: what the method bodies shared by
/// `BezierCurve` and `BSplineCurve` need (sampling and the in-place edits of a drag).
pub(crate) trait ClassCurve {
    /// 2 or 3.
    fn dim(&self) -> usize;
    /// The points at `params`, flat, into `out` (`params.len() · dim` numbers).
    fn sample_into(&self, params: &[f64], out: &mut [f64]) -> Result<(), Error>;
    /// `count` points at equally spaced parameters over the domain, flat, into `out`.
    fn sample_uniform_into(&self, count: usize, out: &mut [f64]) -> Result<(), Error>;
    /// Moves control point i to the point with coordinates `coords` (dim numbers), in place.
    fn set_control_point(&mut self, i: usize, coords: &[f64]) -> Result<(), Error>;
    /// Sets weight i (> 0) in place.
    fn set_weight(&mut self, i: usize, w: f64) -> Result<(), Error>;
}

/// `setControlPoint(i, point)`: the drag path, in place.
pub(crate) fn set_control_point(
    curve: &mut impl ClassCurve,
    i: f64,
    point: &JsValue,
) -> Result<(), JsError> {
    let point = numbers("point", point)?;
    curve.set_control_point(whole("i", i)?, &point)?;
    Ok(())
}

/// `setWeight(i, w)`, in place.
pub(crate) fn set_weight(curve: &mut impl ClassCurve, i: f64, w: f64) -> Result<(), JsError> {
    curve.set_weight(whole("i", i)?, w)?;
    Ok(())
}

/// `sample(params)`: a new array of `params.length · dim` numbers.
pub(crate) fn sample(curve: &impl ClassCurve, params: &[f64]) -> Result<Vec<f64>, JsError> {
    let mut out = vec![0.0; params.len().saturating_mul(curve.dim())];
    curve.sample_into(params, &mut out)?;
    Ok(out)
}

/// `sampleUniform(count)`: a new array of `count · dim` numbers.
pub(crate) fn sample_uniform(curve: &impl ClassCurve, count: usize) -> Result<Vec<f64>, JsError> {
    check_count(count)?;
    let mut out = vec![0.0; count * curve.dim()];
    curve.sample_uniform_into(count, &mut out)?;
    Ok(out)
}

/// `sampleView(params)`: `sample(params)` written into `buffer` (the curve's own) and returned
/// as a view of it (see [`memory_view`]). On an error the buffer keeps its allocation.
pub(crate) fn sample_view(
    curve: &impl ClassCurve,
    buffer: &mut Vec<f64>,
    params: &[f64],
) -> Result<Float64Array, JsError> {
    buffer.resize(params.len().saturating_mul(curve.dim()), 0.0);
    curve.sample_into(params, buffer)?;
    memory_view(buffer)
}

/// `sampleUniformView(count)`: `sampleUniform(count)` into `buffer`, as [`sample_view`].
pub(crate) fn sample_uniform_view(
    curve: &impl ClassCurve,
    buffer: &mut Vec<f64>,
    count: usize,
) -> Result<Float64Array, JsError> {
    check_count(count)?;
    buffer.resize(count * curve.dim(), 0.0);
    curve.sample_uniform_into(count, buffer)?;
    memory_view(buffer)
}

/// What an array argument must be, for [`numbers`].
pub(crate) const NUMBERS: &str = "an array of numbers (Float64Array or number[])";

/// An array-of-numbers argument, taken as a `JsValue`: a `Float64Array` is copied once, a plain
/// array or another typed array is converted (`new Float64Array(value)`, as the glue for a
/// `&[f64]` would). Anything else — `null`, `undefined`, a number, a string, an object — is an
/// error naming the argument: the glue would have failed with a `TypeError` naming nothing, or
/// silently read a number or object as an empty array (which, repeated, even crashed Node 20).
#[inline(never)]
pub(crate) fn numbers(name: &'static str, value: &JsValue) -> Result<Vec<f64>, JsError> {
    if let Some(array) = value.dyn_ref::<Float64Array>() {
        return Ok(array.to_vec());
    }
    if js_sys::Array::is_array(value) || js_sys::ArrayBuffer::is_view(value) {
        return Ok(Float64Array::new(value).to_vec());
    }
    Err(Error::ArgumentType {
        name,
        expected: NUMBERS,
        got: type_name(value),
    }
    .into())
}

/// An optional array-of-numbers argument: `null` or `undefined` give `None`, anything else is
/// read by [`numbers`].
pub(crate) fn optional_numbers(
    name: &'static str,
    value: &JsValue,
) -> Result<Option<Vec<f64>>, JsError> {
    if value.is_undefined() || value.is_null() {
        Ok(None)
    } else {
        numbers(name, value).map(Some)
    }
}

/// `typeof value`, with `null` told apart (for messages).
fn type_name(value: &JsValue) -> String {
    if value.is_null() {
        "null".into()
    } else {
        value.js_typeof().as_string().unwrap_or_default()
    }
}

/// A string argument, taken as a `JsValue`: wasm-bindgen's glue for a `&str` fails on a
/// non-string with a `TypeError` naming nothing, and on some (a number, `{}`) it even reads
/// out of bounds of the wasm memory. `null` or `undefined` give `default` when there is one.
#[inline(never)]
pub(crate) fn string_arg(
    name: &'static str,
    value: &JsValue,
    default: Option<&'static str>,
) -> Result<String, JsError> {
    if let Some(s) = value.as_string() {
        return Ok(s);
    }
    match default {
        Some(d) if value.is_undefined() || value.is_null() => Ok(d.into()),
        _ => Err(Error::ArgumentType {
            name,
            expected: "a string",
            got: type_name(value),
        }
        .into()),
    }
}

/// A whole number ≥ 0 from JavaScript: a count, index, degree, order or dimension. The API
/// takes these as `f64` and converts them here, because wasm-bindgen's own conversion to
/// `usize` (`>>> 0`) would silently turn 2.5 into 2, −1 into 4294967295 and NaN or a missing
/// argument into 0.
#[inline(never)]
pub(crate) fn whole(what: &str, value: f64) -> Result<usize, JsError> {
    if (0.0..=f64::from(u32::MAX)).contains(&value) && value.fract() == 0.0 {
        Ok(value as usize)
    } else {
        Err(Error::NotWholeNumber {
            what: what.into(),
            value,
        }
        .into())
    }
}

/// Rejects a sample count above [`crate::geom::MAX_SAMPLES`].
pub(crate) fn check_count(count: usize) -> Result<(), Error> {
    if count > crate::geom::MAX_SAMPLES {
        return Err(Error::TooLarge {
            what: "count",
            value: count,
            max: crate::geom::MAX_SAMPLES,
        });
    }
    Ok(())
}

/// The crate version, e.g. `"0.1.0"`.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").into()
}
