//! `boltzone serve [--port P] [--bind ADDR] [--units U]`: the teaching page and its JSON API over
//! HTTP/1.1 on std::net (bound to 127.0.0.1 by default; `--port 0` takes a free port and prints
//! it).
//!
//! Routes: `GET /` the page (`page.html` with the tick chooser `ticks.js` inlined, built into
//! the binary: vanilla JavaScript and SVG, no network at run time), `GET /api/joint?…` the
//! joint ([`api`], a contract), `GET /api/health`. `--units` is the page's opening unit system
//! (a selector on the page changes it). The page's opening joint ([`api::opening`]) is answered
//! once, in a thread started with the server, and embedded in the page as JSON, so that the
//! page's first frame draws it without a request (a plain headless screenshot shows the plot);
//! the first `GET /` waits for that answer.
//! One thread per connection, at most [`MAX_CONNECTIONS`] at once (beyond: 503), requests read
//! with a timeout and a size limit, every answer `Connection: close`. A bad query is answered
//! 400 naming the field; a solver failure 500; a panic inside a request is caught and answered
//! 500: the server survives every request. Successful answers are kept by joint
//! ([`CACHE_ENTRIES`], first in first out): a slider moved back and forth asks again.
//!
//! # Accuracy
//!
//! `tests/figures/server.rs` (`api_gives_the_cli_numbers`: the contract against the CLI; bad
//! fields; survival; the embedded opening answer equal to the API's) and
//! `tests/figures/browser.rs` (the page in chromium at 400 and 1280 px; the first paint of a
//! plain headless chromium; the tick chooser over random ranges in Node).
//!
//! # Cost
//!
//! `tests/figures/load.rs` (`api_load_2000_requests_8_concurrent`, ignored; 2,000 requests over
//! 20 s from 8 clients: latency percentiles, memory before and after).

pub mod api;

use super::exit::{usage, Status};
use std::collections::{HashMap, VecDeque};
use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, OnceLock};
use std::time::Duration;

/// Connections served at once; more are answered 503.
pub const MAX_CONNECTIONS: usize = 64;
/// Answers kept (first in, first out): a slider moved back and forth asks the same joints.
pub const CACHE_ENTRIES: usize = 512;
/// Largest request head read (bytes).
const MAX_REQUEST: usize = 16 * 1024;

/// The teaching page (its markers `/*TICKS*/` and `BOOT_JSON` filled by [`page`]).
const PAGE: &str = include_str!("page.html");
/// The axes' tick chooser, inlined into the page (and tested alone in Node).
const TICKS: &str = include_str!("ticks.js");

/// Arguments of `boltzone serve`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// TCP port (0: any free port, printed on start).
    #[arg(long, default_value_t = 8080)]
    port: u16,
    /// Address to bind (127.0.0.1: this machine only).
    #[arg(long, default_value = "127.0.0.1")]
    bind: String,
    /// The page's opening unit system.
    #[command(flatten)]
    units: super::args::Units,
}

/// The page as served: the tick chooser inlined and the boot JSON (the opening unit system, the
/// page's hole radius and unit symbols per system, the opening joint's answer or null) embedded,
/// `<` escaped so that no text inside it closes the script element.
fn page(units: boltzone::scene::UnitSystem, cache: &Cache) -> String {
    use boltzone::scene::UnitSystem;
    let q = api::opening(units);
    let (status, _, body) = joint_of(q, cache);
    let answer: serde_json::Value = match status {
        200 => serde_json::from_slice(&body).unwrap_or_default(),
        _ => serde_json::Value::Null,
    };
    let systems: serde_json::Map<_, _> =
        [UnitSystem::InPsiLbf, UnitSystem::MmMpaN, UnitSystem::MPaN]
            .into_iter()
            .map(|u| {
                let (l, s, f) = u.symbols();
                let v =
                    serde_json::json!({"hole": api::hole(u), "length": l, "stress": s, "force": f});
                (u.name().to_string(), v)
            })
            .collect();
    let boot = serde_json::json!({"units": units.name(), "systems": systems, "answer": answer});
    PAGE.replace("/*TICKS*/", TICKS)
        .replace("BOOT_JSON", &boot.to_string().replace('<', "\\u003c"))
}

/// Runs the server until the process is stopped.
pub fn run(args: Args) -> anyhow::Result<Status> {
    let listener = match TcpListener::bind((args.bind.as_str(), args.port)) {
        Ok(l) => l,
        Err(e) => {
            return usage(
                "--port",
                args.port,
                &format!("cannot listen on {}: {e}", args.bind),
            )
        }
    };
    let addr = listener.local_addr()?;
    println!(
        "boltzone serve: http://{addr}/ (API: /api/joint?a=0.1&b=0.31&d=0.1&c=1.54); Ctrl-C stops"
    );
    std::io::stdout().flush()?;
    let busy = Arc::new(AtomicUsize::new(0));
    let cache = Arc::new(Cache::default());
    let html = Arc::new(OnceLock::new());
    let units = args.units.units;
    {
        let (html, cache) = (Arc::clone(&html), Arc::clone(&cache));
        std::thread::spawn(move || html.get_or_init(|| page(units, &cache)).len());
    }
    for stream in listener.incoming() {
        let Ok(stream) = stream else { continue };
        if busy.fetch_add(1, Ordering::SeqCst) >= MAX_CONNECTIONS {
            busy.fetch_sub(1, Ordering::SeqCst);
            let mut s = stream;
            let _ = respond(&mut s, 503, "text/plain", b"busy: too many connections\n");
            continue;
        }
        let (busy, cache, html) = (Arc::clone(&busy), Arc::clone(&cache), Arc::clone(&html));
        let spawned = std::thread::Builder::new().spawn(move || {
            let mut s = stream;
            let page = || html.get_or_init(|| page(units, &cache)).as_str();
            let _ = handle(&mut s, &cache, page);
            busy.fetch_sub(1, Ordering::SeqCst);
        });
        if spawned.is_err() {
            eprintln!("boltzone serve: could not start a thread for a connection");
        }
    }
    Ok(Status::Converged)
}

/// Reads one request head and answers it (`page` gives the page).
fn handle<'a>(
    stream: &mut TcpStream,
    cache: &Cache,
    page: impl FnOnce() -> &'a str,
) -> std::io::Result<()> {
    stream.set_read_timeout(Some(Duration::from_secs(10)))?;
    stream.set_write_timeout(Some(Duration::from_secs(10)))?;
    let mut head = Vec::new();
    let mut buf = [0u8; 2048];
    while !head.windows(4).any(|w| w == b"\r\n\r\n") {
        let n = stream.read(&mut buf)?;
        if n == 0 {
            break;
        }
        head.extend_from_slice(&buf[..n]);
        if head.len() > MAX_REQUEST {
            return respond(stream, 431, "text/plain", b"request head too large\n");
        }
    }
    let text = String::from_utf8_lossy(&head);
    let mut parts = text.lines().next().unwrap_or("").split_whitespace();
    let (method, target) = (parts.next().unwrap_or(""), parts.next().unwrap_or(""));
    if method != "GET" && method != "HEAD" {
        return respond(stream, 405, "text/plain", b"only GET\n");
    }
    let (path, query) = target.split_once('?').unwrap_or((target, ""));
    let (status, kind, body) = match path {
        "/" | "/index.html" => (200, "text/html; charset=utf-8", page().as_bytes().to_vec()),
        "/api/health" => (200, "application/json", b"{\"ok\":true}\n".to_vec()),
        "/api/joint" => joint(query, cache),
        _ => (404, "text/plain", b"not found\n".to_vec()),
    };
    let body = if method == "HEAD" { Vec::new() } else { body };
    respond(stream, status, kind, &body)
}

/// Successful answers by joint (the bits of a, b, d, c, ν, d2 and the unit system), oldest
/// first out.
#[derive(Default)]
struct Cache(Mutex<Store>);

/// A joint's key: the bits of a, b, d, ν, c and d2 (absent: all ones) and the unit system.
type Key = [u64; 7];
/// The answers by key and the keys in the order they came.
type Store = (HashMap<Key, Arc<Vec<u8>>>, VecDeque<Key>);

impl Cache {
    fn key(q: &api::JointQuery) -> Key {
        let bits = |x: Option<f64>| x.map_or(u64::MAX, f64::to_bits);
        [
            q.a.to_bits(),
            q.b.to_bits(),
            q.d.to_bits(),
            q.nu.to_bits(),
            bits(q.c),
            bits(q.d2),
            q.units as u64,
        ]
    }

    fn get(&self, key: &Key) -> Option<Arc<Vec<u8>>> {
        self.0.lock().ok()?.0.get(key).cloned()
    }

    fn put(&self, key: Key, body: Arc<Vec<u8>>) {
        if let Ok(mut g) = self.0.lock() {
            let (map, order) = &mut *g;
            if map.insert(key, body).is_none() {
                order.push_back(key);
            }
            while order.len() > CACHE_ENTRIES {
                if let Some(old) = order.pop_front() {
                    map.remove(&old);
                }
            }
        }
    }
}

/// An error answer: (status, JSON content type, `{"error": message}`).
fn error(status: u16, message: String) -> (u16, &'static str, Vec<u8>) {
    let body = serde_json::json!({ "error": message })
        .to_string()
        .into_bytes();
    (status, "application/json", body)
}

/// The API's answer: (status, content type, body); a panic is caught and answered 500.
fn joint(query: &str, cache: &Cache) -> (u16, &'static str, Vec<u8>) {
    match api::parse(query) {
        Ok(q) => joint_of(q, cache),
        Err(e) => error(400, format!("{e:#}")),
    }
}

/// The answer to the parsed joint `q`, from the cache or solved (and kept).
fn joint_of(q: api::JointQuery, cache: &Cache) -> (u16, &'static str, Vec<u8>) {
    let key = Cache::key(&q);
    if let Some(body) = cache.get(&key) {
        return (200, "application/json", body.to_vec());
    }
    match std::panic::catch_unwind(|| api::answer(&q)) {
        Ok(Ok(v)) => {
            let body = v.to_string().into_bytes();
            cache.put(key, Arc::new(body.clone()));
            (200, "application/json", body)
        }
        Ok(Err(e)) if super::exit::code_of(&e) == 2 => error(400, format!("{e:#}")),
        Ok(Err(e)) => error(500, format!("{e:#}")),
        Err(_) => error(
            500,
            "internal error: the solver panicked on this joint".into(),
        ),
    }
}

fn respond(stream: &mut TcpStream, status: u16, kind: &str, body: &[u8]) -> std::io::Result<()> {
    let reason = match status {
        200 => "OK",
        400 => "Bad Request",
        404 => "Not Found",
        405 => "Method Not Allowed",
        431 => "Request Header Fields Too Large",
        503 => "Service Unavailable",
        _ => "Internal Server Error",
    };
    let head = format!(
        "HTTP/1.1 {status} {reason}\r\nContent-Type: {kind}\r\nContent-Length: {}\r\n\
         Cache-Control: no-store\r\nConnection: close\r\n\r\n",
        body.len()
    );
    stream.write_all(head.as_bytes())?;
    stream.write_all(body)?;
    stream.flush()
}
