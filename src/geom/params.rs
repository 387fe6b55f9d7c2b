//! Parameter lists for dense evaluation: a slice, or equally spaced values.

/// The parameters of a dense evaluation: a caller's slice, or `count` equally spaced values
/// `start + step·i` whose last one is `end` exactly. One type for both keeps one copy of each
/// sampling kernel in the wasm instead of one per parameter source.
#[derive(Clone, Copy, Debug)]
pub enum Params<'a> {
    /// The values of a slice, in order.
    Slice(&'a [f64]),
    /// `start + step·i` for `i < count − 1`, then `end`.
    Uniform {
        /// The first value.
        start: f64,
        /// The spacing.
        step: f64,
        /// The last value (exact).
        end: f64,
        /// How many values.
        count: usize,
    },
}

impl Params<'_> {
    /// `count` equally spaced values from `start` to `end` (both exact; `count = 1` gives
    /// `start`).
    pub fn uniform(start: f64, end: f64, count: usize) -> Self {
        let step = if count > 1 {
            (end - start) / (count - 1) as f64
        } else {
            0.0
        };
        let end = if count > 1 { end } else { start };
        Params::Uniform {
            start,
            step,
            end,
            count,
        }
    }

    /// How many values.
    pub fn len(&self) -> usize {
        match *self {
            Params::Slice(s) => s.len(),
            Params::Uniform { count, .. } => count,
        }
    }

    /// Whether there are no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Value `i` (`i < len()`).
    #[inline(always)]
    pub fn get(&self, i: usize) -> f64 {
        match *self {
            Params::Slice(s) => s[i],
            Params::Uniform {
                start,
                step,
                end,
                count,
            } => {
                if i + 1 == count {
                    end
                } else {
                    start + step * i as f64
                }
            }
        }
    }
}
