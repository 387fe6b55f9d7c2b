// Expression texts for the fuzz of the typed curves (parametricCurve, expressionNames): mostly
// well-formed formulas from the grammar (so calls reach evaluation, joints and plotting), then
// the same mutated character by character, deep nesting, huge numbers, over-long texts and
// characters from outside the language. Every call must still return or throw a coded Error.

const FUNCTIONS = ["sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp"];
const MORE = ["ln", "log", "sqrt", "abs", "floor", "ceil", "sign"];
const ALPHABET = "t0123456789.+-*/^() abcepisnqxyzω_π−·×|,#=e";

/** A random well-formed expression of about `depth` levels, in t and the names `names`. */
export function formula(r, depth = 3, names = ["a", "b"]) {
  const { int, pick, chance, rnd } = r;
  const leaf = () => {
    const k = int(0, 5);
    if (k === 0) return String(int(0, 20));
    if (k === 1) return (rnd() * 10).toFixed(int(1, 3));
    if (k === 2) return pick(["pi", "π", "e"]);
    if (k === 3 && names.length) return pick(names);
    return "t";
  };
  if (depth <= 0 || chance(0.25)) return leaf();
  const a = () => formula(r, depth - 1, names);
  switch (int(0, 8)) {
    case 0:
      return `${a()} + ${a()}`;
    case 1:
      return `${a()} - ${a()}`;
    case 2:
      return `${a()}*${a()}`;
    case 3:
      return `(${a()})/(${a()})`;
    case 4:
      return `(${a()})^${pick(["2", "3", "-1", "0.5", "(t)"])}`;
    case 5:
      return `${int(2, 9)}${pick(["t", "(t+1)", "pi", " sin(t)"])}`;
    case 6:
      return `-${a()}`;
    case 7:
      return `${pick(FUNCTIONS)}(${a()})`;
    default:
      return `${pick(MORE)}(${a()})`;
  }
}

/** A formula with a few characters inserted, deleted or replaced. */
function mutated(r) {
  const { int, pick } = r;
  const chars = [...formula(r)];
  for (let k = int(1, 4); k > 0; k--) {
    const at = int(0, chars.length);
    const op = int(0, 2);
    if (op === 0) chars.splice(at, 0, pick([...ALPHABET]));
    else if (op === 1) chars.splice(at, 1);
    else chars[at] = pick([...ALPHABET]);
  }
  return chars.join("");
}

/** An expression text: well-formed, mutated, or hostile. */
export function expression(r) {
  const { chance, int, pick } = r;
  if (chance(0.75)) return formula(r);
  if (chance(0.5)) return mutated(r);
  switch (int(0, 6)) {
    case 0:
      return `${"(".repeat(int(60, 100000))}t`;
    case 1:
      return `${"-".repeat(int(60, 100000))}t`;
    case 2:
      return "9".repeat(int(300, 2000));
    case 3:
      return `${"t+".repeat(int(400, 5000))}t`;
    case 4:
      return `sin(1/${formula(r, 1)})`;
    case 5:
      return pick(["", " ", "\u{1F600}", "t\u0000", "2^3^4^5^6^7", "t^t^t^t", "e^2t", "1/2t"]);
    default:
      return `${"sin(".repeat(int(10, 80))}t${")".repeat(int(0, 80))}`;
  }
}

/** An interval bound: mostly a number or a constant expression. */
function bound(r, at) {
  const { chance, pick } = r;
  if (chance(0.8)) return String(at);
  return chance(0.7) ? pick(["pi", "2pi", "pi/2", "e", "a"]) : expression(r);
}

/** A `pieces` argument: 1–4 joined pieces (sometimes z, sometimes broken). */
export function pieces(r) {
  const { chance, int } = r;
  const n = chance(0.95) ? int(1, 4) : int(0, 70);
  const z = chance(0.2);
  const out = [];
  for (let i = 0; i < n; i++) {
    const piece = { x: expression(r), y: expression(r), from: bound(r, i), to: bound(r, i + 1) };
    if (z || chance(0.02)) piece.z = expression(r);
    if (chance(0.01)) delete piece.y;
    out.push(piece);
  }
  return out;
}

/** A `parameters` argument: mostly a and b (the names formula() uses), sometimes more names,
 * invalid names or values. */
export function parameters(r) {
  const { chance, pick, rnd } = r;
  if (chance(0.05)) return undefined;
  const out = { a: 0.5 + rnd() * 2, b: (rnd() - 0.5) * 4 };
  if (chance(0.2)) out.ω = rnd();
  if (chance(0.05)) out[pick(["tt", "e", "t", "pi", "sin", "", "a_"])] = 1;
  if (chance(0.05)) out.a = pick([Number.NaN, Infinity, "2", null]);
  return out;
}
