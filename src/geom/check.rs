//! Input checks shared by every family: weights, output lengths, flat coordinates, `dim`.

use super::{Point, MAX_RESULT_BYTES, MAX_SAMPLES, MAX_SAMPLE_WORK};
use crate::error::{check_coordinate, check_finite, Error, Result};

/// Validates a weight list: count, finite, > 0.
pub fn check_weights(w: &[f64], expected: usize) -> Result<()> {
    if w.len() != expected {
        return Err(Error::WeightCount {
            expected,
            got: w.len(),
        });
    }
    check_all_finite(w, "weight")?;
    if let Some((index, &value)) = w.iter().enumerate().find(|(_, &wi)| wi <= 0.0) {
        return Err(Error::NonPositiveWeight { index, value });
    }
    Ok(())
}

/// Caps `count` samples of each of `functions` functions (a `basisCurves` table,
/// `functions · count` values) at [`MAX_SAMPLES`] values, naming the `count` the caller gave
/// and the largest one allowed (a product would overflow a 32-bit count in wasm first).
pub fn check_table_count(count: usize, functions: usize) -> Result<()> {
    let max = MAX_SAMPLES / functions.max(1);
    if count > max {
        return Err(Error::TooLarge {
            what: "basis-sample-count",
            value: count,
            max,
        });
    }
    Ok(())
}

/// The number of values of a result of `counts` multiplied together (points × coordinates,
/// rows × columns × 3…), each `value_bytes` long, checked before anything is allocated: every
/// product by `checked_mul` (a wasm32 `usize` overflows at 4 GiB), the total at most
/// [`MAX_RESULT_BYTES`]; otherwise [`Error::ResultTooLarge`] naming `what` and the counts.
pub fn check_result_bytes(
    what: &'static str,
    counts: &[usize],
    value_bytes: usize,
) -> Result<usize> {
    let values = counts.iter().try_fold(1usize, |a, &c| a.checked_mul(c));
    match values {
        Some(v)
            if v.checked_mul(value_bytes)
                .is_some_and(|b| b <= MAX_RESULT_BYTES) =>
        {
            Ok(v)
        }
        _ => Err(Error::ResultTooLarge {
            what,
            counts: counts.to_vec(),
            value_bytes,
            max_bytes: MAX_RESULT_BYTES,
        }),
    }
}

/// [`check_result_bytes`] for a result of `f64` values (8 bytes each).
pub fn result_len(what: &'static str, counts: &[usize]) -> Result<usize> {
    check_result_bytes(what, counts, 8)
}

/// The work budget: `count` items of `units` each within [`MAX_SAMPLE_WORK`], otherwise
/// [`Error::TooLarge`] naming `what`, the count given and the largest count allowed.
pub fn check_work(what: &'static str, count: usize, units: usize) -> Result<()> {
    let max = MAX_SAMPLE_WORK / units.max(1);
    if count > max {
        return Err(Error::TooLarge {
            what,
            value: count,
            max,
        });
    }
    Ok(())
}

/// Checks an output buffer holds `count` points of `dim` coordinates of a curve of degree
/// `degree`, and caps `count`: at [`MAX_SAMPLES`] points, [`MAX_RESULT_BYTES`] bytes and the
/// work budget `count·(degree + 1)² ≤` [`MAX_SAMPLE_WORK`].
pub fn check_out_len(len: usize, count: usize, dim: usize, degree: usize) -> Result<()> {
    if count > MAX_SAMPLES {
        return Err(Error::TooLarge {
            what: "sample-count",
            value: count,
            max: MAX_SAMPLES,
        });
    }
    check_work("sample-work", count, (degree.min(1 << 12) + 1).pow(2))?;
    result_len("samples-result", &[count, dim])?;
    if len != count * dim {
        return Err(Error::BufferLength {
            len,
            count,
            needed: count * dim,
        });
    }
    Ok(())
}

/// Splits a flat coordinate array into points of dimension `P::DIM`, validating count and
/// finiteness ("coordinate 5 is NaN").
#[inline(never)]
pub fn points_from_flat<P: Point>(coords: &[f64]) -> Result<Vec<P>> {
    check_flat(coords, P::DIM)?;
    Ok(coords.chunks_exact(P::DIM).map(P::from_slice).collect())
}

/// The checks of [`points_from_flat`] for points of dimension `dim` (≥ 1): the coordinate
/// count a multiple of `dim`, every coordinate finite ("coordinate 5 is NaN") and at most
/// [`super::MAX_COORDINATE`] in magnitude.
pub fn check_flat(coords: &[f64], dim: usize) -> Result<()> {
    if !coords.len().is_multiple_of(dim) {
        return Err(Error::CoordinateCount {
            count: coords.len(),
            dim,
        });
    }
    check_all_coordinates(coords, "coordinate")
}

/// Checks every value of `values` as a coordinate: finite, then at most
/// [`super::MAX_COORDINATE`] in magnitude ([`Error::NotFinite`], [`Error::CoordinateTooLarge`]
/// naming `what` and the index of the first that is not).
pub fn check_all_coordinates(values: &[f64], what: &'static str) -> Result<()> {
    for (i, &v) in values.iter().enumerate() {
        check_coordinate(what, Some(i), v)?;
    }
    Ok(())
}

/// Checks every value of `values` is finite; the error names `what` and the index.
pub fn check_all_finite(values: &[f64], what: &'static str) -> Result<()> {
    for (i, &v) in values.iter().enumerate() {
        check_finite(what, Some(i), v)?;
    }
    Ok(())
}

/// Validates `dim` (2 or 3).
pub fn check_dim(dim: usize) -> Result<usize> {
    if dim == 2 || dim == 3 {
        Ok(dim)
    } else {
        Err(Error::InvalidDimension { dim })
    }
}

/// Checks the in-place move of control point `i` (of `count`) to `p`: the index, then every
/// coordinate finite ([`Error::IndexOutOfRange`], [`Error::NotFinite`]).
pub(crate) fn check_point_edit<P: Point>(i: usize, count: usize, p: P) -> Result<()> {
    if i >= count {
        return Err(Error::IndexOutOfRange { index: i, count });
    }
    for k in 0..P::DIM {
        check_coordinate("new-point-coordinate", Some(k), p.coord(k))?;
    }
    Ok(())
}

/// Checks setting weight `i` (of `count`) to `w`: the index, then `w` finite and > 0
/// ([`Error::IndexOutOfRange`], [`Error::NotFinite`], [`Error::NonPositiveWeight`]).
pub(crate) fn check_weight_edit(i: usize, count: usize, w: f64) -> Result<()> {
    if i >= count {
        return Err(Error::IndexOutOfRange { index: i, count });
    }
    check_finite("weight", Some(i), w)?;
    if w <= 0.0 {
        return Err(Error::NonPositiveWeight { index: i, value: w });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;
    use glam::DVec2;

    #[test]
    fn flat_points_are_validated() {
        assert!(points_from_flat::<DVec2>(&[1.0, 2.0, 3.0]).is_err());
        let e = points_from_flat::<DVec2>(&[1.0, f64::NAN]).unwrap_err();
        assert!(e.to_string().contains("coordinate 1 is NaN"), "{e}");
    }
}
