//! JavaScript bindings (wasm-bindgen): the only module that knows about JS.
//!
//! Thin wrappers: flat `Float64Array`s in and out, camelCase names, and every [`crate::Error`]
//! turned into a thrown JS `Error` carrying its English message, its `code` and its `params`
//! ([`ApiError`], `error.rs`). No maths here.
//! Nothing here may panic (a panic inside wasm kills the module for the whole page), which
//! clippy enforces for this module tree.
// A build without a family's bindings (bench/wasm-size.mjs) leaves helpers only it uses.
#![cfg_attr(
    not(all(feature = "typed-curves", feature = "sketching")),
    allow(dead_code)
)]
#![deny(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    clippy::indexing_slicing
)]

#[macro_use]
mod class;

pub mod bezier;
pub mod bspline;
pub(crate) mod error;
#[cfg(feature = "sketching")]
pub mod fit;
pub mod interp;
#[cfg(feature = "typed-curves")]
pub mod parametric;
pub mod rational;
mod scratch;
pub mod surface;
mod surface_build;
mod surface_mesh;
mod surface_teaching;

pub use bezier::{JsBezierCurve, JsCompositeBezier};
pub use bspline::JsBSplineCurve;
pub use error::ApiError;
#[cfg(feature = "sketching")]
pub use fit::{
    fit_bspline, fit_bspline_report, fit_curve, fit_curve_report, oversketch, oversketch_report,
};
pub use interp::{JsCubicSpline, JsLagrangeCurve};
#[cfg(feature = "typed-curves")]
pub use parametric::{expression_names, parametric_curve, JsParametricCurve};
pub use surface::{JsBSplineSurface, JsBezierSurface};
pub use surface_build::{extrude, interpolate_surface, interpolate_surface_params, revolve, ruled};

use crate::error::Error;
use js_sys::Float64Array;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// A `Float64Array` viewing `buffer` where it lies in the wasm memory (no copy). It stays
/// valid while `buffer` is neither moved nor freed and the memory does not grow (growing
/// detaches every view: its length becomes 0).
pub(crate) fn memory_view(buffer: &[f64]) -> Result<Float64Array, ApiError> {
    let memory: js_sys::WebAssembly::Memory = wasm_bindgen::memory()
        .dyn_into()
        .map_err(|_| ApiError::new("the wasm memory is not a WebAssembly.Memory"))?;
    let offset = u32::try_from(buffer.as_ptr() as usize)
        .map_err(|_| ApiError::new("the buffer lies outside 32-bit wasm memory"))?;
    let length = u32::try_from(buffer.len())
        .map_err(|_| ApiError::new("the buffer is too long for a Float64Array view"))?;
    Ok(Float64Array::new_with_byte_offset_and_length(
        &memory.buffer(),
        offset,
        length,
    ))
}

/// What an array argument must be, for [`numbers`].
pub(crate) const NUMBERS: &str = "numbers";

/// An object `{ key: Float64Array, … }`.
pub(crate) fn object_of(entries: &[(&str, &[f64])]) -> Result<JsValue, ApiError> {
    let object = js_sys::Object::new();
    for (key, values) in entries {
        js_sys::Reflect::set(
            &object,
            &JsValue::from_str(key),
            &js_sys::Float64Array::from(*values).into(),
        )
        .map_err(|_| ApiError::new("could not build the result object"))?;
    }
    Ok(object.into())
}

/// `object[key] = value` on a fresh plain object (which cannot refuse it: no setters, not
/// frozen). Out of line: one copy for every result object.
#[inline(never)]
pub(crate) fn set_key(object: &js_sys::Object, key: &str, value: &JsValue) {
    let _ = js_sys::Reflect::set(object, &JsValue::from_str(key), value);
}

/// A plain object `{ key: number, … }`.
pub(crate) fn js_object(entries: &[(&str, f64)]) -> js_sys::Object {
    let object = js_sys::Object::new();
    for &(key, value) in entries {
        set_key(&object, key, &value.into());
    }
    object
}

/// The entries of an options object: `undefined`/`null` give none; anything but a plain
/// object is an [`Error::ArgumentType`]; a key outside `allowed` an [`Error::UnknownOption`]
/// naming it (`listed` is the list the message shows).
pub(crate) fn option_entries(
    options: &JsValue,
    (allowed, listed): (&[&str], &'static str),
) -> Result<Vec<(String, JsValue)>, ApiError> {
    if options.is_undefined() || options.is_null() {
        return Ok(Vec::new());
    }
    let object = match options.dyn_ref::<js_sys::Object>() {
        Some(o) if options.is_object() && !js_sys::Array::is_array(options) => o,
        _ => {
            return Err(Error::ArgumentType {
                name: "options",
                expected: "object",
                got: type_name(options),
            }
            .into())
        }
    };
    let mut out = Vec::new();
    for key in js_sys::Object::keys(object).iter() {
        let key = key.as_string().unwrap_or_default();
        if !allowed.contains(&key.as_str()) {
            return Err(Error::UnknownOption {
                name: "options",
                value: key,
                expected: listed,
            }
            .into());
        }
        let value = js_sys::Reflect::get(object, &JsValue::from_str(&key))
            .map_err(|_| ApiError::new("options: a key could not be read"))?;
        out.push((key, value));
    }
    Ok(out)
}

/// An array-of-numbers argument, taken as a `JsValue`: a `Float64Array` is copied once, a plain
/// array or another typed array is converted (`new Float64Array(value)`, as the glue for a
/// `&[f64]` would). Anything else — `null`, `undefined`, a number, a string, an object — is an
/// error naming the argument: the glue would have failed with a `TypeError` naming nothing, or
/// silently read a number or object as an empty array (which, repeated, even crashed Node 20).
#[inline(never)]
pub(crate) fn numbers(name: &'static str, value: &JsValue) -> Result<Vec<f64>, ApiError> {
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
) -> Result<Option<Vec<f64>>, ApiError> {
    if value.is_undefined() || value.is_null() {
        Ok(None)
    } else {
        numbers(name, value).map(Some)
    }
}

/// A boolean option: `undefined`/`null` give `None`, a non-boolean is an
/// [`Error::ArgumentType`] naming it.
pub(crate) fn bool_option(name: &'static str, value: &JsValue) -> Result<Option<bool>, ApiError> {
    if value.is_undefined() || value.is_null() {
        return Ok(None);
    }
    value.as_bool().map(Some).ok_or_else(|| {
        Error::ArgumentType {
            name,
            expected: "boolean",
            got: type_name(value),
        }
        .into()
    })
}

/// `typeof value`, with `null` and arrays told apart (for messages).
pub(crate) fn type_name(value: &JsValue) -> String {
    if value.is_null() {
        "null".into()
    } else if js_sys::Array::is_array(value) {
        "array".into()
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
) -> Result<String, ApiError> {
    if let Some(s) = value.as_string() {
        return Ok(s);
    }
    match default {
        Some(d) if value.is_undefined() || value.is_null() => Ok(d.into()),
        _ => Err(Error::ArgumentType {
            name,
            expected: "string",
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
pub(crate) fn whole(what: &'static str, value: f64) -> Result<usize, ApiError> {
    whole_at(what, None, value)
}

/// As [`whole`], for element `index` of a list argument (`degrees[1]`).
pub(crate) fn whole_at(
    what: &'static str,
    index: Option<usize>,
    value: f64,
) -> Result<usize, ApiError> {
    if (0.0..=f64::from(u32::MAX)).contains(&value) && value.fract() == 0.0 {
        Ok(value as usize)
    } else {
        Err(Error::NotWholeNumber { what, index, value }.into())
    }
}

/// The crate version, e.g. `"0.1.0"`.
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").into()
}
