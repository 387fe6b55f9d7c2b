//! What the core asks of the platform it runs on: the text of a number in a message, and
//! the elementary functions (`sin`/`cos`, and for the typed expressions `tan` … `pow`). In the browser build (`wasm32-unknown-unknown`) both come from JavaScript, which
//! keeps Rust's float printing (~20 KB) and a second copy of fdlibm (~7 KB) out of the wasm;
//! everywhere else they are plain Rust that gives the same results.
//!
//! A leaf module: it imports nothing from the crate, so the core builds without the JS layer.

#[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
mod js {
    use wasm_bindgen::prelude::*;

    #[wasm_bindgen]
    extern "C" {
        /// JavaScript's `String(x)` for a number.
        #[wasm_bindgen(js_name = String)]
        pub(super) fn js_string(x: f64) -> String;
        /// JavaScript's `Number(text)` for a string.
        #[wasm_bindgen(js_name = Number)]
        pub(super) fn js_number(text: &str) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = sin)]
        pub(super) fn js_sin(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = cos)]
        pub(super) fn js_cos(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = tan)]
        pub(super) fn js_tan(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = asin)]
        pub(super) fn js_asin(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = acos)]
        pub(super) fn js_acos(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = atan)]
        pub(super) fn js_atan(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = sinh)]
        pub(super) fn js_sinh(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = cosh)]
        pub(super) fn js_cosh(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = tanh)]
        pub(super) fn js_tanh(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = exp)]
        pub(super) fn js_exp(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = log)]
        pub(super) fn js_ln(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = log10)]
        pub(super) fn js_log10(x: f64) -> f64;
        #[wasm_bindgen(js_namespace = Math, js_name = pow)]
        pub(super) fn js_pow(x: f64, y: f64) -> f64;
    }
}

/// The test attribute of the crate's own unit tests on wasm (`#[test]` would silently not run
/// there): `#[cfg(target_arch = "wasm32")] use crate::platform::test;` in a test module.
#[cfg(all(test, target_arch = "wasm32"))]
pub(crate) use wasm_bindgen_test::wasm_bindgen_test as test;

/// `x` as JavaScript's `String(x)` prints it: `"0.1"`, `"1e-7"`, `"Infinity"`, `"-0"` → `"0"`.
/// Every number in an error message goes through this, so messages read the same on every
/// target. The browser build asks JavaScript; elsewhere [`js_number_text`] computes it.
pub(crate) fn number_text(x: f64) -> String {
    #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
    {
        js::js_string(x)
    }
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    {
        js_number_text(x)
    }
}

/// The nearest f64 to a decimal written with digits and at most one point (`"6.5"`, `".5"`):
/// JavaScript's `Number(text)` in the browser build (which keeps Rust's decimal parser and its
/// ~10 KB table of powers of five out of the wasm), [`str::parse`] elsewhere; both round
/// correctly. NaN for any other text.
pub(crate) fn parse_decimal(text: &str) -> f64 {
    #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
    {
        js::js_number(text)
    }
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    {
        text.parse().unwrap_or(f64::NAN)
    }
}

/// `(sin x, cos x)`: JavaScript's `Math.sin` and `Math.cos` in the browser build (V8 uses the
/// same fdlibm algorithms as Rust's libm), [`f64::sin_cos`] elsewhere.
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
    {
        (js::js_sin(x), js::js_cos(x))
    }
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    {
        x.sin_cos()
    }
}

/// One elementary function of one argument: JavaScript's `Math.<js>` in the browser build, the
/// std method `<std>` elsewhere (the same fdlibm-family algorithms, within an ulp of each other).
macro_rules! elementary {
    ($(#[$doc:meta])* $name:ident, $js:ident, $std:ident) => {
        $(#[$doc])*
        pub(crate) fn $name(x: f64) -> f64 {
            #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
            {
                js::$js(x)
            }
            #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
            {
                x.$std()
            }
        }
    };
}

elementary!(/// tan x (`Math.tan`).
    tan, js_tan, tan);
elementary!(/// arcsin x ∈ [−π/2, π/2], NaN outside [−1, 1] (`Math.asin`).
    asin, js_asin, asin);
elementary!(/// arccos x ∈ [0, π], NaN outside [−1, 1] (`Math.acos`).
    acos, js_acos, acos);
elementary!(/// arctan x ∈ (−π/2, π/2) (`Math.atan`).
    atan, js_atan, atan);
elementary!(/// sinh x = (eˣ − e⁻ˣ)/2 (`Math.sinh`).
    sinh, js_sinh, sinh);
elementary!(/// cosh x = (eˣ + e⁻ˣ)/2 (`Math.cosh`).
    cosh, js_cosh, cosh);
elementary!(/// tanh x = sinh x / cosh x (`Math.tanh`).
    tanh, js_tanh, tanh);
elementary!(/// eˣ (`Math.exp`).
    exp, js_exp, exp);
elementary!(/// The natural logarithm ln x: NaN for x < 0, −∞ at 0 (`Math.log`).
    ln, js_ln, ln);
elementary!(/// log₁₀ x: NaN for x < 0, −∞ at 0 (`Math.log10`).
    log10, js_log10, log10);

/// xʸ as IEEE 754 `pow` gives it (`Math.pow`, [`f64::powf`]): a negative base with a
/// non-integer exponent is NaN, with an integer exponent it keeps the sign ((−2)³ = −8), and
/// x⁰ = 1 for every x (0⁰ = 1).
pub(crate) fn pow(x: f64, y: f64) -> f64 {
    #[cfg(all(target_arch = "wasm32", target_os = "unknown"))]
    {
        js::js_pow(x, y)
    }
    #[cfg(not(all(target_arch = "wasm32", target_os = "unknown")))]
    {
        x.powf(y)
    }
}

/// JavaScript's `Number.prototype.toString()` (ECMA-262 `Number::toString`, radix 10) in Rust.
///
/// The digits are the shortest that round-trip (Rust's `{:e}` gives them: `d₁.d₂…dₖe(n−1)`);
/// the layout is ECMA's, with `n` the position of the decimal point after the first digit:
/// - `k ≤ n ≤ 21`: the digits then `n − k` zeros (`123456789012345680000`);
/// - `0 < n ≤ 21`: a point after `n` digits (`2.5`);
/// - `−6 < n ≤ 0`: `0.`, `−n` zeros, the digits (`0.0000015`);
/// - otherwise exponential, with the sign always written (`1e-7`, `1.5e+21`).
///
/// NaN, `Infinity`, `-Infinity` as JavaScript spells them, and `-0` prints as `0`.
#[cfg_attr(all(target_arch = "wasm32", target_os = "unknown"), allow(dead_code))]
pub(crate) fn js_number_text(x: f64) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "Infinity" } else { "-Infinity" }.into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let scientific = format!("{:e}", x.abs());
    let (mantissa, exponent) = scientific.split_once('e').unwrap_or((&scientific, "0"));
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    let k = digits.len() as i32;
    let n = exponent.parse::<i32>().unwrap_or(0) + 1;
    let mut out = String::with_capacity(k as usize + 8);
    if x < 0.0 {
        out.push('-');
    }
    if k <= n && n <= 21 {
        out.push_str(&digits);
        out.extend(std::iter::repeat_n('0', (n - k) as usize));
    } else if 0 < n && n <= 21 {
        let (int, frac) = digits.split_at(n as usize);
        out.push_str(int);
        out.push('.');
        out.push_str(frac);
    } else if -6 < n && n <= 0 {
        out.push_str("0.");
        out.extend(std::iter::repeat_n('0', (-n) as usize));
        out.push_str(&digits);
    } else {
        let (first, rest) = digits.split_at(1);
        out.push_str(first);
        if !rest.is_empty() {
            out.push('.');
            out.push_str(rest);
        }
        out.push('e');
        out.push(if n > 0 { '+' } else { '-' });
        out.push_str(&(n - 1).abs().to_string());
    }
    out
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use super::test;
    use super::*;

    /// Values with the text JavaScript's `String(x)` gives them (checked in Node 20).
    const TABLE: &[(f64, &str)] = &[
        (0.1, "0.1"),
        (1e-7, "1e-7"),
        (-1e-7, "-1e-7"),
        (1.5e-6, "0.0000015"),
        (1e-6, "0.000001"),
        (1.5e-7, "1.5e-7"),
        (1e21, "1e+21"),
        (1.5e21, "1.5e+21"),
        (123456789012345680000.0, "123456789012345680000"),
        (1e20, "100000000000000000000"),
        (-0.0, "0"),
        (0.0, "0"),
        (2.5, "2.5"),
        (-2.5, "-2.5"),
        (1.0 / 3.0, "0.3333333333333333"),
        (100.0, "100"),
        (-3.0, "-3"),
        (123.456, "123.456"),
        (1e100, "1e+100"),
        (5e-324, "5e-324"),
        (f64::MAX, "1.7976931348623157e+308"),
        (4294967295.0, "4294967295"),
        (0.000123, "0.000123"),
        (f64::NAN, "NaN"),
        (f64::INFINITY, "Infinity"),
        (f64::NEG_INFINITY, "-Infinity"),
    ];

    #[test]
    fn number_text_matches_javascript_string() {
        for &(x, js) in TABLE {
            assert_eq!(js_number_text(x), js, "String({x:e})");
        }
    }

    #[test]
    fn number_text_agrees_with_the_platform() {
        for &(x, js) in TABLE {
            assert_eq!(number_text(x), js, "String({x:e})");
        }
    }
}
