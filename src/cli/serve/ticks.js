// Round axis ticks for the teaching page (inlined into page.html by the server; tested alone in
// Node by tests/figures/browser/ticks.cjs). niceTicks(lo, hi, most) returns the ticks of the
// smallest step m·10^k (m in 1, 2, 5) whose ticks, from the multiple at or below lo to the one at
// or above hi, number at most `most` (clamped to 7..10): then they number at least 4, since the
// step before (at most 2.5 times smaller) gave more than `most`. Each tick is n·m·10^k for an
// integer n, computed as one product or one division by an exact power of ten (no running sum),
// and labelled with the fewest digits that step needs ("0.3", never "0.30000000000000004").
"use strict";
function niceTicks(lo, hi, most) {
  most = Math.max(7, Math.min(10, Math.floor(most) || 10));
  if (!isFinite(lo) || !isFinite(hi)) return { ticks: [], labels: [], step: NaN };
  if (!(hi > lo)) {
    const w = Math.abs(lo) / 10 || 1;
    lo -= w;
    hi += w;
  }
  let k = Math.floor(Math.log10((hi - lo) / most)) - 1;
  for (;;) {
    for (const m of [1, 2, 5]) {
      // the tick n·m·10^k, and its label with max(0, -k) decimals at most
      const at = (n) => (k >= 0 ? n * m * Math.pow(10, k) : (n * m) / Math.pow(10, -k));
      let n0 = Math.floor(lo / at(1)), n1 = Math.ceil(hi / at(1));
      if (at(n0) > lo) n0 -= 1;
      if (at(n1) < hi) n1 += 1;
      if (n1 - n0 + 1 > most) continue;
      const ticks = [], labels = [];
      for (let n = n0; n <= n1; n++) {
        const v = at(n) + 0; // + 0: no negative zero
        ticks.push(v);
        labels.push(k >= 0 || -k > 100 ? String(v) : v.toFixed(-k).replace(/\.?0+$/, "").replace(/^-0$/, "0"));
      }
      return { ticks, labels, step: at(1) };
    }
    k += 1;
  }
}
if (typeof module !== "undefined") module.exports = { niceTicks };
