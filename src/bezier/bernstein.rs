//! The Bernstein polynomials as checked values and as plotted curves (syllabus §1).

use super::bernstein;
use crate::error::{check_in_range, Error, Result};
use crate::geom::{MAX_DEGREE, MAX_SAMPLES};

/// `B_i^n(t) = C(n, i) t^i (1 − t)^(n − i)`, with the arguments checked: the checked twin of
/// [`bernstein`] for input from outside (the JS `bernstein(n, i, t)`).
///
/// # Errors
/// [`Error::TooLarge`] for `n > MAX_DEGREE`, [`Error::IndexOutOfRange`] for `i > n`,
/// [`Error::NotFinite`] or [`Error::ParameterOutOfRange`] for `t` outside `[0, 1]`.
///
/// ```
/// assert_eq!(splinelab::bezier::try_bernstein(2, 1, 0.5).unwrap(), 0.5);
/// assert!(splinelab::bezier::try_bernstein(2, 3, 0.5).is_err());
/// ```
pub fn try_bernstein(n: usize, i: usize, t: f64) -> Result<f64> {
    check_basis_degree(n, i)?;
    check_in_range("t", t, (0.0, 1.0))?;
    Ok(bernstein(n, i, t))
}

/// Every Bernstein polynomial of degree `n` at `count` equally spaced `t_k = k/(count − 1)` in
/// `[0, 1]` (the last exactly 1, so `count = 1` samples `t = 1` only), function-major: value `k`
/// of `B_i^n` at index `i·count + k`, `(n + 1)·count` numbers in all — the curves a basis plot
/// draws. O(n·count).
///
/// # Errors
/// [`Error::TooLarge`] for `n > MAX_DEGREE` or more than `MAX_SAMPLES` values in all.
///
/// ```
/// let b = splinelab::bezier::bernstein_basis(1, 3).unwrap();
/// assert_eq!(b, vec![1.0, 0.5, 0.0, 0.0, 0.5, 1.0]); // 1 − t, then t
/// ```
pub fn bernstein_basis(n: usize, count: usize) -> Result<Vec<f64>> {
    check_basis_degree(n, 0)?;
    let max = MAX_SAMPLES / (n + 1);
    if count > max {
        return Err(Error::TooLarge {
            what: "count",
            value: count,
            max,
        });
    }
    let step = if count > 1 {
        1.0 / (count - 1) as f64
    } else {
        0.0
    };
    Ok((0..=n)
        .flat_map(|i| {
            (0..count)
                .map(move |k| bernstein(n, i, if k + 1 == count { 1.0 } else { k as f64 * step }))
        })
        .collect())
}

/// `n <= MAX_DEGREE` and `i <= n`.
fn check_basis_degree(n: usize, i: usize) -> Result<()> {
    if n > MAX_DEGREE {
        return Err(Error::TooLarge {
            what: "n",
            value: n,
            max: MAX_DEGREE,
        });
    }
    if i > n {
        return Err(Error::IndexOutOfRange {
            index: i,
            count: n + 1,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    #[cfg(target_arch = "wasm32")]
    use crate::platform::test;

    #[test]
    fn basis_columns_sum_to_one() {
        let (n, count) = (4, 9);
        let b = bernstein_basis(n, count).unwrap();
        assert_eq!(b.len(), (n + 1) * count);
        for k in 0..count {
            let sum: f64 = (0..=n).map(|i| b[i * count + k]).sum();
            assert!((sum - 1.0).abs() < 1e-15, "column {k} sums to {sum}");
        }
        // B_0^4(0) = 1 and B_4^4(1) = 1 exactly.
        assert_eq!(b[0], 1.0);
        assert_eq!(b[(n + 1) * count - 1], 1.0);
    }

    #[test]
    fn checked_arguments() {
        assert_eq!(try_bernstein(3, 1, 0.5).unwrap(), 0.375);
        assert_eq!(
            try_bernstein(3, 4, 0.5).unwrap_err().code(),
            "index-out-of-range"
        );
        assert_eq!(
            try_bernstein(3, 1, 1.5).unwrap_err().code(),
            "parameter-out-of-range"
        );
        assert_eq!(
            bernstein_basis(MAX_DEGREE + 1, 2).unwrap_err().code(),
            "too-large"
        );
        assert_eq!(
            bernstein_basis(0, MAX_SAMPLES + 1).unwrap_err().code(),
            "too-large"
        );
        assert_eq!(bernstein_basis(2, 1).unwrap(), vec![0.0, 0.0, 1.0]);
    }
}
