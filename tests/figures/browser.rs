//! The teaching page in a real browser: Debian's chromium, headless, driven by Node's
//! playwright-core (`tests/figures/browser/page.cjs`; the package pinned by the
//! `package-lock.json` beside it, installed by `.ci/run` into `target/ci-node`), and by a plain
//! `chromium --headless --dump-dom/--screenshot` (no virtual-time budget: what the page shows
//! right after its load event); the tick chooser alone in Node (`browser/ticks.cjs`).
//! Screenshots are kept in `target/figures-browser/`. Without chromium, node or the package a
//! test prints a note and passes, unless `BOLTZONE_BROWSER=1` (`.ci/run` sets it) demands them.

use crate::server::Server;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The repository root.
fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Whether `BOLTZONE_BROWSER=1` demands the browser tools.
fn required() -> bool {
    std::env::var("BOLTZONE_BROWSER").is_ok_and(|v| v == "1")
}

/// Whether node runs here.
fn node() -> bool {
    Command::new("node").arg("--version").output().is_ok()
}

/// Chromium's path (`BOLTZONE_CHROMIUM`, else Debian's), or None (with a note, or a failure
/// under `BOLTZONE_BROWSER=1`) where it is missing.
fn chromium() -> Option<String> {
    let chromium = std::env::var("BOLTZONE_CHROMIUM").unwrap_or("/usr/bin/chromium".into());
    if Path::new(&chromium).is_file() {
        return Some(chromium);
    }
    assert!(
        !required(),
        "BOLTZONE_BROWSER=1 but chromium ({chromium}) is missing"
    );
    eprintln!("note: browser test skipped (no chromium; run .ci/run)");
    None
}

/// A fresh directory for this test's files under `target/figures-browser`.
fn out_dir(name: &str) -> PathBuf {
    let dir = root().join("target/figures-browser").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `cmd` to its end or for at most `limit` (then kills it): (success, stdout, stderr).
fn run(cmd: &mut Command, limit: Duration) -> (bool, String, String) {
    let mut child = cmd
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > limit {
            let _ = child.kill();
            break;
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    let out = child.wait_with_output().unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (out.status.success(), text(&out.stdout), text(&out.stderr))
}

/// The tick chooser of the page's axes over 20,036 ranges (random and chosen): ticks covering
/// the range, steps of 1, 2 or 5 × 10^k, 4 to 10 ticks, labels printed shortest
/// (`browser/ticks.cjs` says how each is checked).
#[test]
fn tick_chooser_over_random_ranges() {
    if !node() {
        assert!(!required(), "BOLTZONE_BROWSER=1 but node is missing");
        eprintln!("note: tick chooser test skipped (no node)");
        return;
    }
    let (ok, stdout, stderr) = run(
        Command::new("node")
            .arg(root().join("tests/figures/browser/ticks.cjs"))
            .arg(root().join("src/cli/serve/ticks.js")),
        Duration::from_secs(60),
    );
    eprintln!("ticks: {stdout}");
    assert!(ok && stdout.contains("\"ok\":true"), "{stdout}\n{stderr}");
}

/// The page at 1280 and 400 px in playwright (`browser/page.cjs`): first frame without an API
/// request, no horizontal scroll, no overlapping labels, SVGs in the viewport, round ticks,
/// controls stacked at 400 px; the slider and the units selector answered with the API's
/// numbers.
#[test]
fn page_at_400_and_1280_px() {
    let package = root().join("target/ci-node/node_modules/playwright-core");
    let Some(chromium) = chromium() else { return };
    if !(package.is_dir() && node()) {
        assert!(
            !required(),
            "BOLTZONE_BROWSER=1 but node or {} is missing",
            package.display()
        );
        eprintln!("note: browser test skipped (no node or playwright-core; run .ci/run)");
        return;
    }
    let server = Server::start();
    let dir = out_dir("page");
    let (ok, stdout, stderr) = run(
        Command::new("node")
            .arg(root().join("tests/figures/browser/page.cjs"))
            .arg(format!("http://127.0.0.1:{}/", server.port))
            .arg(&dir)
            .env("BOLTZONE_PLAYWRIGHT", &package)
            .env("BOLTZONE_CHROMIUM", &chromium),
        Duration::from_secs(400),
    );
    eprintln!("browser: {stdout}");
    assert!(ok && stdout.contains("\"ok\":true"), "{stdout}\n{stderr}");
    for width in [400, 1280] {
        let shot = dir.join(format!("page-{width}.png"));
        assert!(
            std::fs::metadata(&shot).map_or(0, |m| m.len()) > 10_000,
            "{} missing or too small",
            shot.display()
        );
    }
}

/// The text of the element whose start tag holds `id="ID"` in the serialized `dom` (up to the
/// next tag), or of its first `until`-ended stretch when `until` is given.
fn element<'a>(dom: &'a str, id: &str, until: Option<&str>) -> &'a str {
    let at = dom
        .find(&format!("id=\"{id}\""))
        .unwrap_or_else(|| panic!("no #{id}"));
    let rest = &dom[at..];
    let body = &rest[rest.find('>').unwrap() + 1..];
    let end = until.map_or_else(|| body.find('<'), |u| body.find(u));
    &body[..end.unwrap()]
}

/// A plain headless chromium (no virtual-time budget, no script driving it) at 1280 and at 400
/// px: the DOM right after the load event holds the drawn plot, the status is ready (not
/// "computing…"), and the R_o shown is the API's for the opening joint; the screenshots are
/// kept.
#[test]
fn plain_headless_chromium_paints_the_plot_first() {
    let Some(chromium) = chromium() else { return };
    let server = Server::start();
    let url = format!("http://127.0.0.1:{}/", server.port);
    let dir = out_dir("plain");
    let (status, body) = server.get("/api/joint?a=0.1&b=0.31&d=0.1&c=1.5&nu=0.3");
    assert_eq!(status, 200, "{body}");
    let api: serde_json::Value = serde_json::from_str(&body).unwrap();
    let r_o = api["two"]["r_o"].as_f64().unwrap();
    for width in [1280, 400] {
        let profile = dir.join(format!("profile-{width}"));
        let chrome = |extra: &[String]| {
            let mut cmd = Command::new(&chromium);
            cmd.args([
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--no-first-run",
            ])
            .arg(format!("--user-data-dir={}", profile.display()))
            .arg(format!("--window-size={width},1100"))
            .args(extra)
            .arg(&url);
            run(&mut cmd, Duration::from_secs(120))
        };
        let (ok, dom, stderr) = chrome(&["--dump-dom".into()]);
        assert!(ok, "chromium --dump-dom failed: {stderr}");
        assert!(
            dom.contains("data-state=\"ready\""),
            "{width} px: the page is not ready at its load event"
        );
        let status = element(&dom, "status", None);
        assert!(
            status.starts_with("ready") && !status.contains("computing"),
            "{width} px: status '{status}'"
        );
        assert!(
            element(&dom, "plot-p", Some("</svg>")).contains("<polyline"),
            "{width} px: no pressure curve drawn"
        );
        let shown: f64 = element(&dom, "ro-two", None).parse().unwrap();
        let api_shown: f64 = format!("{r_o:.4e}").parse().unwrap();
        assert_eq!(shown, api_shown, "{width} px: R_o shown vs the API's");
        let shot = dir.join(format!("page-{width}.png"));
        let (ok, _, stderr) = chrome(&[format!("--screenshot={}", shot.display())]);
        assert!(ok, "chromium --screenshot failed: {stderr}");
        assert!(
            std::fs::metadata(&shot).map_or(0, |m| m.len()) > 10_000,
            "{width} px: screenshot missing or too small"
        );
    }
}
