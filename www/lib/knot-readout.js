/**
 * A knot vector U = [u₀, …, u_m] as text: the values in order, repeated knots repeated (their
 * multiplicity is how often a value occurs), each as `knotText` writes it ("0, 0, 0, 1, 1.5,
 * 2"; "0; 0; 0; 1; 1,5; 2" with a decimal comma), or as TeX; and a readout (panel.js) that says
 * it in a sentence and carries the list on `data-knots` ("0,0,0,1,1.5,2", always with a point)
 * for tests and scripts; the names of a stack of equal knots.
 */
import { readout } from "./panel.js";
import { knotMachine, knotText } from "./knot-ruler.js";
import { listSeparator, subscript, texListSeparator } from "./format.js";

/** "0, 0, 0, 1, 2" (any iterable of knots; `separator` between them, default `listSeparator()`). */
export function knotListText(values, separator = listSeparator()) {
  return Array.from(values, (u) => knotText(u)).join(separator);
}

/** The knots as TeX: "0, 0, 1.5" or "0; 0; 1{,}5". */
export function knotListTex(values) {
  return Array.from(values, (u) => knotText(u, true)).join(texListSeparator(" "));
}

/**
 * A readout `name` with `text(state, data)`; `knots(state, data)` → the vector on `data-knots`
 * (null: empty).
 */
export function knotVectorReadout(name, text, knots) {
  return readout(name, text, {
    data: (s, d) => {
      const values = knots(s, d);
      return { knots: values ? Array.from(values, knotMachine).join(",") : "" };
    },
  });
}

/** "u₅ = u₆ = u₇": the names of the equal knots u_a … u_b (a stack of multiplicity b − a + 1). */
export function knotNames(a, b) {
  const list = [];
  for (let i = a; i <= b; i++) list.push(`u${subscript(i)}`);
  return list.join(" = ");
}
