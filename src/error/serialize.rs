//! How a few fields of [`Error`] become a thrown JS Error's `params` (serde, in the wasm build
//! only): the fields whose Rust type is not what a page wants to read. The core names these,
//! not the JS layer (src/wasm/error.rs), so it compiles without it.

use super::Error;
use serde::ser::{SerializeStruct, Serializer};
use serde::Serialize;

/// Serializes the cause of an [`Error::InArgument`] as `{ code, params }`.
pub(crate) fn coded<S: Serializer>(source: &Error, serializer: S) -> Result<S::Ok, S::Error> {
    let mut cause = serializer.serialize_struct("Cause", 2)?;
    cause.serialize_field("code", source.code())?;
    cause.serialize_field("params", source)?;
    cause.end()
}

/// Serializes a parametrisation as its exponent α (0 uniform, ½ centripetal, 1 chord).
pub(crate) fn alpha<S: Serializer>(
    kind: &crate::bspline::Parameterization,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    kind.alpha().serialize(serializer)
}

/// Serializes a field by its `Debug` text (a joining rule: "C1").
pub(crate) fn debug<T: std::fmt::Debug, S: Serializer>(
    value: &T,
    serializer: S,
) -> Result<S::Ok, S::Error> {
    format!("{value:?}").serialize(serializer)
}
