// Drives boltzone serve's teaching page in Debian's chromium (headless) with playwright-core:
// load the page, wait for the first answer, move the B/A slider, wait for the new plot, read
// R_o from the page and compare it with the API's answer for the query the page sent; save a
// screenshot. Usage: node page.cjs URL SCREENSHOT.png (BOLTZONE_PLAYWRIGHT = path of the
// playwright-core package). Prints one JSON line; exits 1 on any mismatch.
"use strict";
const { chromium } = require(process.env.BOLTZONE_PLAYWRIGHT);
const [url, shot] = process.argv.slice(2);
const flags = [
  "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
  "--disable-background-networking", "--disable-component-update", "--disable-sync",
];
async function main() {
  // playwright gives every launch a fresh temporary profile (--user-data-dir)
  const browser = await chromium.launch({
    executablePath: process.env.BOLTZONE_CHROMIUM || "/usr/bin/chromium",
    headless: true,
    args: flags,
  });
  try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 1100 } });
    const errors = [];
    page.on("pageerror", (e) => errors.push(String(e)));
    await page.goto(url);
    await page.waitForSelector("body[data-state=ready]", { timeout: 60000 });
    const before = await page.textContent("#ro-two");
    const q0 = await page.getAttribute("#ro-two", "data-query");
    const t0 = Date.now();
    await page.$eval("#s-ba", (e) => { e.value = "2.2"; e.dispatchEvent(new Event("input")); });
    await page.waitForFunction(
      (q) => document.body.dataset.state === "ready" && document.getElementById("ro-two").dataset.query !== q,
      q0, { timeout: 60000 });
    const ms = Date.now() - t0;
    const after = await page.textContent("#ro-two");
    const query = await page.getAttribute("#ro-two", "data-query");
    const api = await (await fetch(new URL("/api/joint?" + query, url))).json();
    const svgPaths = await page.$$eval("#plot-p polyline", (l) => l.length);
    await page.screenshot({ path: shot, fullPage: true });
    const ok = after === api.two.r_o.toFixed(5) && before !== after && errors.length === 0 &&
      query.includes("b=0.22") && svgPaths === 1;
    console.log(JSON.stringify({ ok, before, after, api: api.two.r_o, query, ms, errors, svgPaths }));
    if (!ok) process.exitCode = 1;
  } finally {
    await browser.close();
  }
}
main().catch((e) => { console.log(JSON.stringify({ ok: false, error: String(e) })); process.exitCode = 1; });
