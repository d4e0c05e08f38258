// The teaching page's tick chooser (src/cli/serve/ticks.js) over many random ranges, in Node:
// the ticks cover the range, their step is 1, 2 or 5 times a power of ten, there are 4 to 10 of
// them (at most the number asked), each is a whole multiple of the step, and each label is the
// number printed shortest (JavaScript's own String(x), the shortest round-trip form) with no more
// decimals than the step has. Usage: node ticks.cjs PATH/ticks.js. Prints one JSON line; exits 1
// on the first failure.
"use strict";
const { niceTicks } = require(process.argv[2]);

// a seeded generator (mulberry32): the same ranges every run
let seed = 0x2545f491;
function rand() {
  seed = (seed + 0x6d2b79f5) | 0;
  let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
  t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
}

const fail = (why, c) => {
  console.log(JSON.stringify({ ok: false, why, case: c }));
  process.exit(1);
};
let n = 0, counts = {};
function check(lo, hi, most) {
  const c = { lo, hi, most };
  const t = niceTicks(lo, hi, most);
  c.t = t;
  const cap = Math.max(7, Math.min(10, Math.floor(most) || 10));
  const len = t.ticks.length;
  if (len < 4 || len > cap) fail("count", c);
  if (t.labels.length !== len) fail("labels", c);
  if (t.ticks[0] > lo || t.ticks[len - 1] < hi) fail("cover", c);
  const k = Math.floor(Math.log10(t.step) + 1e-9);
  const m = t.step / Math.pow(10, k);
  if (![1, 2, 5].some((x) => Math.abs(m - x) < 1e-9 * x)) fail("step " + m, c);
  for (let i = 0; i < len; i++) {
    const v = t.ticks[i], q = v / t.step;
    if (Math.abs(q - Math.round(q)) > 1e-6) fail("multiple", c);
    if (i > 0 && Math.abs(v - t.ticks[i - 1] - t.step) > 1e-9 * Math.max(Math.abs(v), t.step)) fail("spacing", c);
    const label = t.labels[i];
    if (Number(label) !== v) fail("label value " + label, c);
    const shortest = String(v);
    if (!shortest.includes("e") && label !== shortest) fail("not shortest " + label + " vs " + shortest, c);
    const decimals = (label.split(".")[1] || "").length;
    if (!label.includes("e") && decimals > Math.max(0, -k)) fail("decimals " + label, c);
  }
  counts[len] = (counts[len] || 0) + 1;
  n += 1;
}
for (let i = 0; i < 20000; i++) {
  const e = -9 + 18 * rand();
  const scale = Math.pow(10, e);
  const kind = i % 4;
  let lo, hi;
  if (kind === 0) { lo = 0; hi = scale * (0.1 + 9.9 * rand()); }             // 0..x, as the page's r axis
  else if (kind === 1) { lo = -scale * rand(); hi = scale * rand(); }         // across zero, as σ_z
  else if (kind === 2) { lo = scale * (rand() - 0.5); hi = lo + scale * Math.pow(10, -6 * rand()); } // narrow
  else { lo = -scale * (1 + rand()); hi = -scale * rand(); }                  // negative only
  check(lo, hi, 7 + 4 * rand());
}
// the page's own kinds of range, degenerate ranges and the classic float traps
for (const [lo, hi] of [[0, 1], [0, 0.3], [0.1, 0.3], [0, 0.7999], [-3.2, 0.45], [0, 0], [1, 1],
  [-2, -2], [0.1 + 0.2, 0.7], [0, 25.4 * 0.031], [0, 0.00254 * 7.3], [-1e-9, 1e-9]]) {
  for (const most of [7, 8, 10]) check(lo, hi, most);
}
console.log(JSON.stringify({ ok: true, ranges: n, counts }));
