// Drives boltzone serve's teaching page in Debian's chromium (headless) with playwright-core, at
// 1280 and at 400 px width. At each width: the first frame after the load event already shows
// the opening joint (state ready, the plot drawn) without any API request (the server embedded
// the answer), and its R_o is the API's answer for the query of the sliders; the layout: no
// horizontal scroll (document scrollWidth <= innerWidth), no two text labels' boxes overlapping
// (tick labels, axis titles, legend entries), every SVG inside the viewport and every SVG text
// inside its SVG, the tick labels round, the controls beside the plots at 1280 px and above them
// at 400 px. At 1280 px also: the B/A slider moved (R_o and the query follow, equal to the API),
// then the units switched to mm-MPa-N (the query asks for them, R_o is the API's in mm, the axes
// say mm and MPa), and the layout checked again. Saves a full-page screenshot per width.
// Usage: node page.cjs URL DIR (BOLTZONE_PLAYWRIGHT = path of the playwright-core package).
// Prints one JSON line; exits 1 on any failure.
"use strict";
const path = require("path");
const { chromium } = require(process.env.BOLTZONE_PLAYWRIGHT);
const [url, dir] = process.argv.slice(2);
const flags = [
  "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
  "--disable-background-networking", "--disable-component-update", "--disable-sync",
];
const failures = [];
const expect = (ok, what, detail) => { if (!ok) failures.push({ what, detail }); };

// the layout as the browser laid it out
function layout() {
  const rect = (e) => e.getBoundingClientRect();
  const labels = [...document.querySelectorAll("svg text, .legend span")]
    .map((e) => ({ text: e.textContent, r: rect(e) })).filter((b) => b.r.width > 0);
  const overlaps = [];
  for (let i = 0; i < labels.length; i++) {
    for (let j = i + 1; j < labels.length; j++) {
      const a = labels[i].r, b = labels[j].r;
      const dx = Math.min(a.right, b.right) - Math.max(a.left, b.left);
      const dy = Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top);
      if (dx > 0.5 && dy > 0.5) overlaps.push([labels[i].text, labels[j].text]);
    }
  }
  const svgs = [...document.querySelectorAll("svg")];
  const outside = svgs.filter((s) => rect(s).left < 0 || rect(s).right > innerWidth || rect(s).width < 150).map((s) => s.id);
  const strays = [];
  for (const s of svgs) {
    const o = rect(s);
    for (const t of s.querySelectorAll("text")) {
      const r = rect(t);
      if (r.left < o.left || r.right > o.right || r.top < o.top || r.bottom > o.bottom) strays.push(s.id + ": " + t.textContent);
    }
  }
  const ticks = [...document.querySelectorAll("svg text.tick")].map((e) => e.textContent);
  const unround = ticks.filter((t) => !/^-?\d+(\.\d*[1-9])?$/.test(t) || /0000|9999/.test(t));
  const first = svgs[0] || document.body;
  const controls = rect(document.querySelector(".controls") || document.body);
  const plots = rect(first.closest(".plots") || first.parentElement);
  return {
    scrollWidth: document.documentElement.scrollWidth, innerWidth, labels: labels.length, overlaps,
    outside, strays, ticks: ticks.length, unround,
    stacked: controls.bottom <= plots.top, beside: controls.right <= plots.left,
  };
}

function checkLayout(l, width, when) {
  const at = width + " px " + when;
  expect(l.scrollWidth <= l.innerWidth, at + ": horizontal scroll", [l.scrollWidth, l.innerWidth]);
  expect(l.overlaps.length === 0, at + ": overlapping labels", l.overlaps);
  expect(l.outside.length === 0, at + ": SVG outside the viewport", l.outside);
  expect(l.strays.length === 0, at + ": text outside its SVG", l.strays);
  expect(l.ticks >= 16 && l.unround.length === 0, at + ": tick labels", l.unround);
  expect(width < 700 ? l.stacked : l.beside, at + ": controls " + (width < 700 ? "above" : "beside") + " the plots", l);
}

// the page's R_o and query, and the API's R_o for that query
async function against(page) {
  const shown = await page.textContent("#ro-two");
  const query = await page.getAttribute("#ro-two", "data-query");
  const api = await (await fetch(new URL("/api/joint?" + query, url))).json();
  return { shown, query, api: api.two.r_o, error: api.two.r_o_error, same: shown === api.two.r_o.toPrecision(5) };
}

const ready = (page, q) => page.waitForFunction(
  (q) => document.body.dataset.state === "ready" && document.getElementById("ro-two").dataset.query !== q,
  q, { timeout: 120000 });

async function main() {
  const browser = await chromium.launch({
    executablePath: process.env.BOLTZONE_CHROMIUM || "/usr/bin/chromium",
    headless: true,
    args: flags,
  });
  const report = {};
  try {
    for (const width of [1280, 400]) {
      const context = await browser.newContext({ viewport: { width, height: 900 } });
      const page = await context.newPage();
      const errors = [], requests = [];
      page.on("pageerror", (e) => errors.push(String(e)));
      page.on("request", (r) => { if (r.url().includes("/api/")) requests.push(r.url()); });
      await page.goto(url, { waitUntil: "load" });
      const first = await page.evaluate(() => ({
        state: document.body.dataset.state,
        status: document.getElementById("status").textContent,
        lines: document.querySelectorAll("#plot-p polyline").length,
      }));
      const r = { first, requests: requests.length };
      expect(first.state === "ready" && first.lines === 1 && !first.status.includes("computing"),
        width + " px: the first frame shows the plot", first);
      expect(requests.length === 0, width + " px: the first frame asked the API", requests);
      r.opening = await against(page);
      expect(r.opening.same, width + " px: the embedded R_o is the API's", r.opening);
      r.layout = await page.evaluate(layout);
      checkLayout(r.layout, width, "at load");
      if (width === 1280) {
        let q = await page.getAttribute("#ro-two", "data-query");
        const t0 = Date.now();
        await page.$eval("#s-ba", (e) => { e.value = "2.2"; e.dispatchEvent(new Event("input")); });
        await ready(page, q);
        r.slider = await against(page);
        r.slider.ms = Date.now() - t0;
        expect(r.slider.same && r.slider.query.includes("b=0.220000000000") && r.slider.shown !== r.opening.shown,
          "slider: the page follows with the API's R_o", r.slider);
        q = r.slider.query;
        await page.selectOption("#units", "mm-MPa-N");
        await ready(page, q);
        r.mm = await against(page);
        r.mm.titles = await page.$$eval("svg text.title", (l) => l.map((e) => e.textContent));
        r.mm.head = await page.textContent("#numbers thead");
        expect(r.mm.same && r.mm.query.includes("units=mm-MPa-N") && r.mm.query.includes("a=2.54&"),
          "units: the page asks in mm and shows the API's R_o", r.mm);
        expect(r.mm.titles.includes("r [mm]") && r.mm.titles.some((t) => t.startsWith("p [MPa]")) && r.mm.head.includes("[mm]"),
          "units: the axes and the table say mm and MPa", r.mm);
        // 25.4 mm per inch: the same joint, scaled, within the two R_o's error bars
        const ratio = r.mm.api / r.slider.api, bar = r.mm.error / r.mm.api + r.slider.error / r.slider.api;
        expect(Math.abs(ratio / 25.4 - 1) <= bar, "units: R_o in mm is 25.4 times R_o in inches", [ratio, bar]);
        r.layout_mm = await page.evaluate(layout);
        checkLayout(r.layout_mm, width, "in mm");
      }
      expect(errors.length === 0, width + " px: script errors", errors);
      await page.screenshot({ path: path.join(dir, "page-" + width + ".png"), fullPage: true });
      report[width] = r;
      await context.close();
    }
  } finally {
    await browser.close();
  }
  const ok = failures.length === 0;
  console.log(JSON.stringify({ ok, failures, report }));
  if (!ok) process.exitCode = 1;
}
main().catch((e) => { console.log(JSON.stringify({ ok: false, error: String(e), failures })); process.exitCode = 1; });
