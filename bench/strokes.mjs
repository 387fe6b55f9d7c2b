// Synthetic pen strokes with known ground truth for row (n) of the benchmark (issue 25): the
// same seeded strokes on every run and for every fitter.
//
// A stroke is a path — line and cubic segments, in px on an 800×600 canvas — walked like a pen:
// samples at arc-length steps of 1–6 px (the speed varies smoothly along the stroke and drops
// to ~1 px near a corner, as a hand slows there), a sample exactly on every corner, then seeded
// jitter of 0.25–1 px (one amplitude per stroke) on every sample. The truth kept with it: the
// sample index of each corner (the path's joints where the direction turns; none on smooth
// strokes), whether it is closed, and for glyphs the outline's own segment count.
//
// Classes: smooth (cubic Béziers, sine waves, arcs), corners (polylines turning 45–150°),
// closed (squares, triangles, circles, stars), glyphs ("O", "D", "S", "L", "C" walked like a
// pen), spirals.
//
//   import { strokes } from "./strokes.mjs";
//   for (const s of strokes({ seed: 25 })) s.points; // Float64Array [x0, y0, x1, y1, …]

/** mulberry32: a small seeded generator, the same numbers on every platform. */
export function rng(seed) {
  let a = seed >>> 0;
  const next = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  next.range = (lo, hi) => lo + (hi - lo) * next();
  next.int = (lo, hi) => Math.floor(next.range(lo, hi + 1));
  // A standard normal (Box–Muller).
  next.normal = () => {
    const u = Math.max(next(), 1e-12);
    return Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * next());
  };
  return next;
}

const line = (a, b) => ({ kind: "line", p: [a, b] });
const cubic = (a, b, c, d) => ({ kind: "cubic", p: [a, b, c, d] });

/** Point of a segment at t. */
function at(seg, t) {
  if (seg.kind === "line") {
    const [a, b] = seg.p;
    return [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t];
  }
  const [a, b, c, d] = seg.p;
  const s = 1 - t;
  const w = [s * s * s, 3 * s * s * t, 3 * s * t * t, t * t * t];
  return [
    w[0] * a[0] + w[1] * b[0] + w[2] * c[0] + w[3] * d[0],
    w[0] * a[1] + w[1] * b[1] + w[2] * c[1] + w[3] * d[1],
  ];
}

/** Unit direction leaving (`end` false) or arriving at (`end` true) a segment's end. */
function direction(seg, end) {
  const p = seg.p;
  let a;
  let b;
  if (end) {
    b = p[p.length - 1];
    a =
      p
        .slice(0, -1)
        .reverse()
        .find((q) => q[0] !== b[0] || q[1] !== b[1]) ?? p[0];
  } else {
    a = p[0];
    b = p.slice(1).find((q) => q[0] !== a[0] || q[1] !== a[1]) ?? p[p.length - 1];
  }
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  const l = Math.hypot(dx, dy) || 1;
  return [dx / l, dy / l];
}

/** Turning angle (radians, 0 straight on) between two unit directions. */
const turn = (u, v) => Math.acos(Math.max(-1, Math.min(1, u[0] * v[0] + u[1] * v[1])));

/** Joints of a path that are corners: direction turning by more than 20°. */
function cornerJoints(segs, closed) {
  const joints = [];
  const n = segs.length;
  for (let i = 0; i < (closed ? n : n - 1); i++) {
    const a = direction(segs[i], true);
    const b = direction(segs[(i + 1) % n], false);
    if (turn(a, b) > (20 * Math.PI) / 180) joints.push(i + 1); // the joint after segment i
  }
  return joints;
}

/**
 * Walks a path like a pen (see the module doc): returns the samples and the sample index of
 * each corner joint.
 */
function walk(segs, { closed, jitter, random }) {
  // Dense polyline per segment with cumulative arc length.
  const dense = [];
  let total = 0;
  const jointAt = [0];
  for (const seg of segs) {
    const k = seg.kind === "line" ? 1 : 400;
    for (let j = dense.length ? 1 : 0; j <= k; j++) {
      const p = at(seg, j / k);
      if (dense.length) {
        const q = dense[dense.length - 1];
        total += Math.hypot(p[0] - q.x, p[1] - q.y);
      }
      dense.push({ x: p[0], y: p[1], s: total });
    }
    jointAt.push(total);
  }
  // Corner joints inside the path (a closed path here starts and ends on a straight part).
  const corners = cornerJoints(segs, closed)
    .filter((j) => j < segs.length)
    .map((j) => jointAt[j]);
  const pointAt = (s) => {
    let lo = 0;
    let hi = dense.length - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (dense[mid].s <= s) lo = mid;
      else hi = mid;
    }
    const a = dense[lo];
    const b = dense[hi];
    const f = b.s > a.s ? (s - a.s) / (b.s - a.s) : 0;
    return [a.x + (b.x - a.x) * f, a.y + (b.y - a.y) * f];
  };
  // Speed: a smooth random profile between 1 and 6 px per sample, slowing near corners.
  const phase = random.range(0, 2 * Math.PI);
  const freq = random.range(1.5, 4) / Math.max(total, 1);
  const speed = (s) => {
    let v = 3.5 + 2.5 * Math.sin(phase + 2 * Math.PI * freq * s);
    for (const c of corners) v = Math.min(v, 1 + Math.abs(s - c) / 12);
    return Math.max(1, Math.min(6, v));
  };
  const ss = [0];
  const cornerIdx = [];
  let ci = 0;
  const sortedCorners = [...corners].sort((a, b) => a - b);
  for (let s = 0; ; ) {
    let next = s + speed(s);
    if (ci < sortedCorners.length && next >= sortedCorners[ci] - 0.5) {
      next = sortedCorners[ci];
      ci++;
      if (next <= s) continue;
      cornerIdx.push(ss.length);
    }
    if (next >= total - 0.5) break;
    ss.push(next);
    s = next;
  }
  ss.push(total);
  const out = new Float64Array(ss.length * 2);
  ss.forEach((s, i) => {
    const p = pointAt(s);
    out[2 * i] = p[0] + jitter * random.normal() * 0.5;
    out[2 * i + 1] = p[1] + jitter * random.normal() * 0.5;
  });
  return { points: out, corners: cornerIdx };
}

/** A regular polygon or star's vertices around (cx, cy), the first at angle a0. */
function ring(cx, cy, radii, count, a0) {
  return Array.from({ length: count }, (_, i) => {
    const a = a0 + (2 * Math.PI * i) / count;
    const r = radii[i % radii.length];
    return [cx + r * Math.cos(a), cy + r * Math.sin(a)];
  });
}

/** A closed polygon as lines, starting halfway along the first edge (so every vertex is a corner). */
function polygon(vertices) {
  const n = vertices.length;
  const mid = [0.5 * (vertices[0][0] + vertices[1][0]), 0.5 * (vertices[0][1] + vertices[1][1])];
  const segs = [line(mid, vertices[1])];
  for (let i = 1; i < n; i++) segs.push(line(vertices[i], vertices[(i + 1) % n]));
  segs.push(line(vertices[0], mid));
  return segs;
}

/** A circle (or ellipse) as four cubics, starting at angle 0. */
function ellipse(cx, cy, rx, ry) {
  const k = 0.5522847498;
  const p = (x, y) => [cx + x, cy + y];
  return [
    cubic(p(rx, 0), p(rx, k * ry), p(k * rx, ry), p(0, ry)),
    cubic(p(0, ry), p(-k * rx, ry), p(-rx, k * ry), p(-rx, 0)),
    cubic(p(-rx, 0), p(-rx, -k * ry), p(-k * rx, -ry), p(0, -ry)),
    cubic(p(0, -ry), p(k * rx, -ry), p(rx, -k * ry), p(rx, 0)),
  ];
}

/** An arc of a circle as cubics of at most 90° each. */
function arc(cx, cy, r, a0, a1) {
  const n = Math.ceil(Math.abs(a1 - a0) / (Math.PI / 2));
  const segs = [];
  for (let i = 0; i < n; i++) {
    const s = a0 + ((a1 - a0) * i) / n;
    const e = a0 + ((a1 - a0) * (i + 1)) / n;
    const h = (4 / 3) * Math.tan((e - s) / 4) * r;
    const p0 = [cx + r * Math.cos(s), cy + r * Math.sin(s)];
    const p3 = [cx + r * Math.cos(e), cy + r * Math.sin(e)];
    segs.push(
      cubic(
        p0,
        [p0[0] - h * Math.sin(s), p0[1] + h * Math.cos(s)],
        [p3[0] + h * Math.sin(e), p3[1] - h * Math.cos(e)],
        p3,
      ),
    );
  }
  return segs;
}

/** A sine wave y = y0 + A sin(k x + φ) over [x0, x1], as cubics of a quarter period each. */
function sine(x0, x1, y0, amp, periods, phi) {
  const n = Math.max(2, Math.round(periods * 4));
  const k = (2 * Math.PI * periods) / (x1 - x0);
  const f = (x) => [x, y0 + amp * Math.sin(k * (x - x0) + phi)];
  const df = (x) => amp * k * Math.cos(k * (x - x0) + phi);
  const segs = [];
  for (let i = 0; i < n; i++) {
    const a = x0 + ((x1 - x0) * i) / n;
    const b = x0 + ((x1 - x0) * (i + 1)) / n;
    const h = (b - a) / 3;
    const pa = f(a);
    const pb = f(b);
    segs.push(cubic(pa, [a + h, pa[1] + h * df(a)], [b - h, pb[1] - h * df(b)], pb));
  }
  return segs;
}

/** An Archimedean spiral r = r0 + g θ over `turns`, as cubics of 45° each (Hermite). */
function spiral(cx, cy, r0, g, turns, a0) {
  const n = Math.ceil(turns * 8);
  const total = turns * 2 * Math.PI;
  const f = (t) => {
    const r = r0 + g * t;
    return [cx + r * Math.cos(a0 + t), cy + r * Math.sin(a0 + t)];
  };
  const df = (t) => {
    const r = r0 + g * t;
    return [
      g * Math.cos(a0 + t) - r * Math.sin(a0 + t),
      g * Math.sin(a0 + t) + r * Math.cos(a0 + t),
    ];
  };
  const segs = [];
  for (let i = 0; i < n; i++) {
    const a = (total * i) / n;
    const b = (total * (i + 1)) / n;
    const h = (b - a) / 3;
    const pa = f(a);
    const pb = f(b);
    const da = df(a);
    const db = df(b);
    segs.push(
      cubic(pa, [pa[0] + h * da[0], pa[1] + h * da[1]], [pb[0] - h * db[0], pb[1] - h * db[1]], pb),
    );
  }
  return segs;
}

/** A polyline through random vertices, each turn between 45° and 150°. */
function zigzag(random, count) {
  let x = random.range(150, 250);
  let y = random.range(200, 400);
  let heading = random.range(-0.5, 0.5);
  const pts = [[x, y]];
  for (let i = 0; i < count; i++) {
    const len = random.range(70, 160);
    if (i > 0) {
      const t = (random.range(45, 150) * Math.PI) / 180;
      // Turn towards the canvas centre, so the stroke stays on it.
      const toCentre = Math.atan2(300 - y, 400 - x) - heading;
      const side = Math.sin(toCentre) >= 0 ? 1 : -1;
      heading += side * t;
    }
    x += len * Math.cos(heading);
    y += len * Math.sin(heading);
    pts.push([x, y]);
  }
  return pts.slice(1).map((p, i) => line(pts[i], p));
}

/**
 * Font-like glyph outlines, walked like a pen (one stroke each), with the number of segments
 * the outline itself has: what a fitter that found the designer's curves would return.
 */
function glyphs(x, y, size) {
  const s = size;
  const P = (u, v) => [x + u * s, y + v * s];
  return [
    // "O": an ellipse, four cubics (closed, no corners).
    {
      name: 'glyph "O"',
      closed: true,
      segs: ellipse(x + 0.4 * s, y + 0.5 * s, 0.36 * s, 0.48 * s),
    },
    // "D": the stem (a line) and the bowl (two cubics); corners at the stem's ends.
    {
      name: 'glyph "D"',
      closed: true,
      segs: [
        line(P(0, 0.5), P(0, 1)),
        cubic(P(0, 1), P(0.55, 1), P(0.78, 0.8), P(0.78, 0.5)),
        cubic(P(0.78, 0.5), P(0.78, 0.2), P(0.55, 0), P(0, 0)),
        line(P(0, 0), P(0, 0.5)),
      ],
      segments: 3,
    },
    // "S": the spine, three cubics (open, smooth).
    {
      name: 'glyph "S"',
      closed: false,
      segs: [
        cubic(P(0.7, 0.12), P(0.55, -0.02), P(0.1, -0.02), P(0.1, 0.25)),
        cubic(P(0.1, 0.25), P(0.1, 0.5), P(0.7, 0.45), P(0.7, 0.74)),
        cubic(P(0.7, 0.74), P(0.7, 1.02), P(0.2, 1.02), P(0.05, 0.86)),
      ],
    },
    // "L": two lines, one corner.
    {
      name: 'glyph "L"',
      closed: false,
      segs: [line(P(0.1, 0), P(0.1, 1)), line(P(0.1, 1), P(0.7, 1))],
    },
    // "C": an open arc of three quarter-circle-like cubics.
    {
      name: 'glyph "C"',
      closed: false,
      segs: arc(x + 0.45 * s, y + 0.5 * s, 0.45 * s, -Math.PI / 4, -Math.PI / 4 - 1.5 * Math.PI),
    },
  ].map((g) => ({ ...g, segments: g.segments ?? g.segs.length }));
}

/**
 * The benchmark's strokes: `{ name, cls, points (Float64Array, flat 2D), corners (sample
 * indices), closed, segments (the path's own segment count, for glyphs) }`.
 */
export function strokes({ seed = 25 } = {}) {
  const random = rng(seed);
  const out = [];
  const add = (cls, name, segs, closed, extra = {}) => {
    const jitter = random.range(0.25, 1);
    const { points, corners } = walk(segs, { closed, jitter, random });
    out.push({ cls, name, points, corners, closed, jitter, ...extra });
  };
  // Smooth: cubic Béziers, sine waves, arcs.
  for (let i = 0; i < 4; i++) {
    const p = () => [random.range(100, 700), random.range(100, 500)];
    const a = [random.range(80, 200), random.range(150, 450)];
    const d = [random.range(600, 720), random.range(150, 450)];
    add("smooth", `cubic Bézier ${i + 1}`, [cubic(a, p(), p(), d)], false);
  }
  for (let i = 0; i < 3; i++) {
    add(
      "smooth",
      `sine wave ${i + 1}`,
      sine(80, 720, 300, random.range(40, 120), random.range(1, 2.5), random.range(0, 6)),
      false,
    );
  }
  for (let i = 0; i < 3; i++) {
    const a0 = random.range(0, 2 * Math.PI);
    add(
      "smooth",
      `arc ${i + 1}`,
      arc(400, 300, random.range(80, 220), a0, a0 + random.range(Math.PI / 3, (5 * Math.PI) / 3)),
      false,
    );
  }
  // Corners: polylines.
  for (let i = 0; i < 8; i++)
    add("corners", `polyline ${i + 1}`, zigzag(random, random.int(2, 5)), false);
  // Closed outlines.
  for (let i = 0; i < 2; i++) {
    const r = random.range(120, 220);
    add("closed", `square ${i + 1}`, polygon(ring(400, 300, [r], 4, random.range(0, 1.5))), true);
  }
  for (let i = 0; i < 2; i++) {
    const r = random.range(120, 220);
    add("closed", `triangle ${i + 1}`, polygon(ring(400, 300, [r], 3, random.range(0, 2))), true);
  }
  for (let i = 0; i < 2; i++) {
    const r = random.range(80, 220);
    add("closed", `circle ${i + 1}`, ellipse(400, 300, r, r), true);
  }
  for (let i = 0; i < 2; i++) {
    const r = random.range(160, 240);
    add(
      "closed",
      `star ${i + 1}`,
      polygon(ring(400, 300, [r, 0.5 * r], 10, random.range(0, 1))),
      true,
    );
  }
  // Glyphs.
  for (const g of glyphs(250, 120, 360))
    add("glyph", g.name, g.segs, g.closed, { segments: g.segments });
  // Spirals.
  for (let i = 0; i < 3; i++) {
    add(
      "spiral",
      `spiral ${i + 1}`,
      spiral(
        400,
        300,
        random.range(10, 30),
        random.range(8, 14),
        random.range(2, 3),
        random.range(0, 6),
      ),
      false,
    );
  }
  return out;
}
