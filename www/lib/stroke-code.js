/**
 * A drawn stroke as short text for links and files (the sketch demo): the samples rounded to a
 * grid of step 10^e (model units), the first point absolute and every other one as the
 * difference from the one before, each integer zigzag-mapped (0, −1, 1, −2 … → 0, 1, 2, 3 …)
 * and written in base64url characters carrying 5 bits each plus a continuation bit:
 *
 *   "e~payload",  e.g. "-3~gAwB…"
 *
 * A pointer moves a few pixels between samples, so most differences take one or two
 * characters. Decoding checks everything a link or file may get wrong (characters, the
 * exponent, an unfinished number, the number of points) and throws the given message.
 */

const ALPHABET = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
const VALUE = new Map([...ALPHABET].map((c, i) => [c, i]));
/** Bits of a number per character, and the continuation bit. */
const BITS = 5;
const MORE = 1 << BITS;
/** Grid exponents accepted: 10⁻⁶ … 10³ model units. */
export const MIN_EXPONENT = -6;
export const MAX_EXPONENT = 3;
/** Largest magnitude of a rounded coordinate (keeps numbers exact in doubles). */
const MAX_INTEGER = 2 ** 40;

/** The grid exponent e for a view of `scale` px per unit: 10^e at most a quarter pixel. */
export function gridExponent(scale) {
  const e = Math.floor(Math.log10(0.25 / scale));
  return Math.min(MAX_EXPONENT, Math.max(MIN_EXPONENT, e));
}

function writeInt(out, n) {
  let z = n < 0 ? -2 * n - 1 : 2 * n;
  do {
    const low = z % MORE;
    z = Math.floor(z / MORE);
    out.push(ALPHABET[z > 0 ? low + MORE : low]);
  } while (z > 0);
}

/** `flat` [x0, y0, x1, y1, …] (model units) as "e~payload" on the grid 10^e. */
export function encodeStroke(flat, exponent) {
  const step = 10 ** exponent;
  const out = [];
  let px = 0;
  let py = 0;
  for (let k = 0; k + 1 < flat.length; k += 2) {
    const x = Math.round(flat[k] / step);
    const y = Math.round(flat[k + 1] / step);
    writeInt(out, x - px);
    writeInt(out, y - py);
    px = x;
    py = y;
  }
  return `${exponent}~${out.join("")}`;
}

/**
 * The flat samples of an encoded stroke (a Float64Array). Throws `new Error(message)` when the
 * text is no stroke code or holds fewer than `min` or more than `max` points.
 */
export function decodeStroke(text, { min = 2, max = 10000, message = "bad stroke" } = {}) {
  const fail = () => {
    throw new Error(message);
  };
  if (typeof text !== "string") fail();
  const m = /^(-?\d{1,2})~([A-Za-z0-9_-]*)$/.exec(text);
  if (!m) fail();
  const exponent = Number(m[1]);
  if (exponent < MIN_EXPONENT || exponent > MAX_EXPONENT) fail();
  const step = 10 ** exponent;
  const payload = m[2];
  const ints = [];
  let z = 0;
  let factor = 1;
  for (const c of payload) {
    const v = VALUE.get(c);
    z += (v % MORE) * factor;
    if (v >= MORE) {
      factor *= MORE;
      if (factor > MAX_INTEGER) fail();
      continue;
    }
    ints.push(z % 2 === 0 ? z / 2 : -(z + 1) / 2);
    if (ints.length > 2 * max) fail();
    z = 0;
    factor = 1;
  }
  if (factor !== 1 || ints.length % 2 !== 0 || ints.length < 2 * min) fail();
  const flat = new Float64Array(ints.length);
  let x = 0;
  let y = 0;
  for (let k = 0; k < ints.length; k += 2) {
    x += ints[k];
    y += ints[k + 1];
    if (Math.abs(x) > MAX_INTEGER || Math.abs(y) > MAX_INTEGER) fail();
    flat[k] = Number((x * step).toPrecision(12));
    flat[k + 1] = Number((y * step).toPrecision(12));
  }
  return flat;
}
