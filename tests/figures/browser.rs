//! The teaching page in a real browser: Debian's chromium, headless, driven by Node's
//! playwright-core (`tests/figures/browser/page.cjs`; the package pinned by the
//! `package-lock.json` beside it, installed by `.ci/run` into `target/ci-node`). Loads the page,
//! moves the B/A slider, waits for the new plot, reads R_o from the page and compares it with
//! the API's answer for the same query; the screenshot is kept as
//! `target/figures-browser/page.png`. Without chromium or the package the test prints a note
//! and passes, unless `BOLTZONE_BROWSER=1` (`.ci/run` sets it) demands the browser.

use crate::server::Server;
use std::path::Path;
use std::process::Command;

#[test]
fn page_answers_a_slider_with_the_api_numbers() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let package = root.join("target/ci-node/node_modules/playwright-core");
    let chromium = std::env::var("BOLTZONE_CHROMIUM").unwrap_or("/usr/bin/chromium".into());
    let required = std::env::var("BOLTZONE_BROWSER").is_ok_and(|v| v == "1");
    let node = Command::new("node").arg("--version").output().is_ok();
    if !(package.is_dir() && Path::new(&chromium).is_file() && node) {
        assert!(
            !required,
            "BOLTZONE_BROWSER=1 but chromium ({chromium}), node or {} is missing",
            package.display()
        );
        eprintln!("note: browser test skipped (no chromium, node or playwright-core; run .ci/run)");
        return;
    }
    let server = Server::start();
    let dir = root.join("target/figures-browser");
    std::fs::create_dir_all(&dir).unwrap();
    let shot = dir.join("page.png");
    let _ = std::fs::remove_file(&shot);
    let out = Command::new("node")
        .arg(root.join("tests/figures/browser/page.cjs"))
        .arg(format!("http://127.0.0.1:{}/", server.port))
        .arg(&shot)
        .env("BOLTZONE_PLAYWRIGHT", &package)
        .env("BOLTZONE_CHROMIUM", &chromium)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    eprintln!("browser: {stdout}");
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        std::fs::metadata(&shot).unwrap().len() > 10_000,
        "screenshot too small"
    );
}
