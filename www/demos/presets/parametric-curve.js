/**
 * The examples of the parametric-curve demo (issue 24), in the order of its buttons: the notes'
 * circle first. Each is `{ name, x, y, z?, from? (default "0"), to, params?, t, bezier? }`: the
 * texts the core parses, the parameters' starting values, where the point starts and whether the
 * Bézier form is shown. The button's words are `parametricCurve.preset.<name>`.
 */
export const PRESETS = Object.freeze([
  { name: "circle", x: "cos(t)", y: "sin(t)", to: "2pi", t: 1 },
  { name: "ellipse", x: "a cos(t)", y: "b sin(t)", to: "2pi", params: { a: 2, b: 1 }, t: 1 },
  { name: "lissajous", x: "sin(a t)", y: "sin(b t)", to: "2pi", params: { a: 3, b: 2 }, t: 0.5 },
  { name: "cycloid", x: "t - sin(t)", y: "1 - cos(t)", to: "4pi", t: 2 },
  { name: "cardioid", x: "2cos(t) - cos(2t)", y: "2sin(t) - sin(2t)", to: "2pi", t: 1 },
  { name: "astroid", x: "cos(t)^3", y: "sin(t)^3", to: "2pi", t: 0.5 },
  { name: "spiral", x: "t cos(t)", y: "t sin(t)", to: "4pi", t: 8 },
  { name: "helix", x: "cos(t)", y: "sin(t)", z: "t/5", to: "4pi", t: 2 },
  { name: "tan", x: "t", y: "tan(t)", from: "-pi", to: "pi", t: 0.5 },
  {
    name: "polynomial",
    x: "6.5t^5 - 7.2t^3 + 3t^2 - 2.1t - 5",
    y: "t",
    to: "1",
    t: 0.5,
    bezier: true,
  },
]);
