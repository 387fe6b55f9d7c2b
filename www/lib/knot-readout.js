/**
 * A knot vector U = [u₀, …, u_m] as text: the values in order, repeated knots repeated (their
 * multiplicity is how often a value occurs), each as `knotText` writes it ("0, 0, 0, 1, 1.5,
 * 2"); and a readout (panel.js) that says it in a sentence and carries the list on
 * `data-knots` ("0,0,0,1,1.5,2") for tests and scripts; the names of a stack of equal knots.
 */
import { readout } from "./panel.js";
import { knotText } from "./knot-ruler.js";
import { subscript } from "./format.js";

/** "0, 0, 0, 1, 2" (any iterable of knots; `separator` between them). */
export function knotListText(values, separator = ", ") {
  return Array.from(values, knotText).join(separator);
}

/**
 * A readout `name` with `text(state, data)`; `knots(state, data)` → the vector on `data-knots`
 * (null: empty).
 */
export function knotVectorReadout(name, text, knots) {
  return readout(name, text, {
    data: (s, d) => {
      const values = knots(s, d);
      return { knots: values ? knotListText(values, ",") : "" };
    },
  });
}

/** "u₅ = u₆ = u₇": the names of the equal knots u_a … u_b (a stack of multiplicity b − a + 1). */
export function knotNames(a, b) {
  const list = [];
  for (let i = a; i <= b; i++) list.push(`u${subscript(i)}`);
  return list.join(" = ");
}
