// Seeded fuzzing of the demo states that links and JSON files bring, run in the page by
// run.mjs: every demo's default state mutated at random (fields dropped or set to NaN,
// ±Infinity, huge, negative, fractional, strings, null, objects; arrays doubled or cut) is
// either refused by validation with a plain `Error`, or accepted and then mounted without any
// other kind of exception. Self-contained: page.evaluate sends its source to the browser.

/** `rounds` mutated states per demo; returns the counts and the first bad cases. */
export async function fuzzStates({ seedValue, rounds }) {
  const { demos, loadDemo } = await import("./demos/index.js");
  const { validateState, mountDemo } = await import("./lib/shell.js");
  const { loadWasm } = await import("./lib/wasm.js");
  const { prepareFigure } = await import("./lib/three-loader.js");
  const sl = await loadWasm();
  let seed = seedValue;
  const rnd = () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed / 2147483648;
  };
  const pick = (a) => a[Math.floor(rnd() * a.length)];
  const weird = () =>
    pick([
      NaN,
      Infinity,
      -1,
      0,
      1e308,
      -1e308,
      2.5,
      1e-300,
      "x",
      null,
      true,
      [],
      {},
      [1],
      [[1, 2]],
      1e6,
      3,
      12,
      40,
      0.5,
    ]);
  function mutate(v) {
    if (rnd() < 0.15) return weird();
    if (Array.isArray(v)) {
      let a = v.map((x) => (rnd() < 0.3 ? mutate(x) : x));
      if (rnd() < 0.2) a = a.concat(a); // longer
      if (rnd() < 0.2) a = a.slice(0, Math.floor(rnd() * a.length));
      return a;
    }
    if (v && typeof v === "object") {
      const o = {};
      for (const [k, x] of Object.entries(v)) if (rnd() > 0.05) o[k] = rnd() < 0.4 ? mutate(x) : x;
      return o;
    }
    if (typeof v === "number") return rnd() < 0.5 ? v * (1 + (rnd() - 0.5) * 4) : weird();
    return v;
  }
  const bad = [];
  let accepted = 0,
    refused = 0;
  for (const entry of demos) {
    const demo = await loadDemo(entry.id);
    await prepareFigure(demo); // three.js for a 3D demo
    for (let k = 0; k < rounds; k++) {
      const candidate = mutate(structuredClone(demo.defaultState));
      let state;
      try {
        state = validateState(demo, structuredClone(candidate));
      } catch (e) {
        refused++;
        if (!(e instanceof Error) || e.constructor !== Error)
          bad.push([
            demo.id,
            "validate",
            e.constructor.name,
            e.message,
            JSON.stringify(candidate).slice(0, 200),
          ]);
        continue;
      }
      accepted++;
      const holder = document.createElement("div");
      document.body.append(holder);
      try {
        const c = mountDemo(holder, demo, { sl, state, mode: "embed", shareUrl: () => "" });
        c.destroy();
      } catch (e) {
        if (!(e instanceof Error) || e.constructor !== Error)
          bad.push([
            demo.id,
            "mount",
            e.constructor.name,
            e.message,
            JSON.stringify(candidate).slice(0, 200),
          ]);
      }
      holder.remove();
    }
  }
  return { accepted, refused, bad: bad.slice(0, 5).map((b) => b.join(" | ")) };
}
