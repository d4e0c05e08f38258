//! `boltzone serve`: the JSON API's contract and its survival (module docs of `main.rs`).

use crate::common::{boltzone, json_of};
use serde_json::Value;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};

/// A `boltzone serve --port 0` child, stopped when dropped.
pub struct Server {
    child: Child,
    /// Its port on 127.0.0.1.
    pub port: u16,
}

impl Server {
    /// Starts the server and reads the port it printed.
    pub fn start() -> Self {
        Self::start_with(&[])
    }

    /// Starts `boltzone serve --port 0 ARGS` and reads the port it printed.
    pub fn start_with(args: &[&str]) -> Self {
        let mut child = Command::new(env!("CARGO_BIN_EXE_boltzone"))
            .args(["serve", "--port", "0"])
            .args(args)
            .stdout(Stdio::piped())
            .spawn()
            .unwrap();
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        let port = line
            .split("127.0.0.1:")
            .nth(1)
            .and_then(|s| s.split('/').next())
            .and_then(|p| p.parse().ok())
            .unwrap_or_else(|| panic!("no port in '{line}'"));
        Self { child, port }
    }

    /// The server's process id.
    pub fn pid(&self) -> u32 {
        self.child.id()
    }

    /// GET `path`: (status, body).
    pub fn get(&self, path: &str) -> (u16, String) {
        let mut s = TcpStream::connect(("127.0.0.1", self.port)).unwrap();
        write!(s, "GET {path} HTTP/1.1\r\nHost: localhost\r\n\r\n").unwrap();
        let mut text = String::new();
        s.read_to_string(&mut text).unwrap();
        let status = text[9..12].parse().unwrap();
        let body = text.split_once("\r\n\r\n").map_or("", |x| x.1).to_string();
        (status, body)
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The contract: `two` holds the numbers `two --json` prints for the same joint (the same
/// solver at the same defaults: equal to the last bit), `single` those of `single --json`
/// (finite elements, tolerance 5e-4), and the rules their closed forms' radii.
#[test]
fn api_gives_the_cli_numbers() {
    let server = Server::start();
    let (status, body) = server.get("/api/joint?a=0.1&b=0.22&d=0.1&c=1.54");
    assert_eq!(status, 200, "{body}");
    assert!(
        !body.contains("null"),
        "an absent quantity is left out, never null"
    );
    let api: Value = serde_json::from_str(&body).unwrap();
    let args = [
        "--a", "0.1", "--b", "0.22", "--d", "0.1", "--c", "1.54", "--json",
    ];
    // the page draws the pressure curve, so it takes the FE; `two`'s auto would take the tables
    let two = json_of(&boltzone(
        &[&["two", "--method", "fem"], &args[..]].concat(),
    ));
    for key in ["r_o", "r_o_error", "converged", "full_contact"] {
        assert_eq!(api["two"][key], two[key], "two.{key}");
    }
    let single = json_of(&boltzone(
        &[&["single", "--tol", "5e-4"], &args[..]].concat(),
    ));
    for key in ["r_o", "r_o_error", "converged"] {
        assert_eq!(api["single"][key], single[key], "single.{key}");
    }
    // 45° cone: R = B + D (C far away)
    let rules = api["rules"].as_array().unwrap();
    assert_eq!(rules[0]["name"], "45° cone");
    assert!((rules[0]["radius"].as_f64().unwrap() - 0.32).abs() < 1e-15);
    let p = &api["curves"]["pressure"];
    assert_eq!(
        p["r"].as_array().unwrap().len(),
        p["p"].as_array().unwrap().len()
    );
}

/// A bad query gets HTTP 400 naming the field; the page and the health check keep answering.
#[test]
fn bad_queries_get_400_naming_the_field_and_the_server_survives() {
    let server = Server::start();
    for (query, field) in [
        ("a=0.1&b=abc&d=0.1", "b"),
        ("a=0.1&b=0.3", "d"),
        ("a=0.1&b=0.05&d=0.1", "B"),
        ("a=0.1&b=0.3&d=0.1&nu=0.7", "nu"),
        ("a=0.1&b=0.3&d=0.1&zz=1", "zz"),
        ("a=0.1&b=0.3&d=-1", "d"),
        ("a=0.1&b=0.3&d=0.1&c=0.2", "c"),
        ("a=%ZZ&b=0.3&d=0.1", "a"),
        ("a=1e400&b=0.3&d=0.1", "a"),
        ("a=0.1&b=0.3&d=0.1&units=furlongs", "units = 'furlongs'"),
        ("a=0.1&b=0.3&d=0.1&units=", "units = ''"),
        (
            "a=0.1&b=0.3&d=0.1&units=mm%2DMPa%2DN&units=m-Pa-N",
            "units = m-Pa-N",
        ),
    ] {
        let (status, body) = server.get(&format!("/api/joint?{query}"));
        assert_eq!(status, 400, "{query}: {body}");
        let v: Value = serde_json::from_str(&body).unwrap();
        let msg = v["error"].as_str().unwrap();
        assert!(
            msg.contains(field),
            "{query}: '{msg}' does not name {field}"
        );
    }
    let (status, _) = server.get("/nowhere");
    assert_eq!(status, 404);
    // garbage instead of HTTP
    let mut s = TcpStream::connect(("127.0.0.1", server.port)).unwrap();
    s.write_all(b"\x00\x01garbage\r\n\r\n").unwrap();
    let mut sink = Vec::new();
    let _ = s.read_to_end(&mut sink);
    let (status, body) = server.get("/api/health");
    assert_eq!((status, body.trim()), (200, "{\"ok\":true}"));
    let (status, page) = server.get("/");
    assert_eq!(status, 200);
    assert!(page.contains("id=\"s-ad\"") && page.contains("/api/joint?"));
}

/// The `units` key of `two --json` and `unit_symbols` as the page's API gives them.
fn symbols(api: &Value) -> (&str, &str, &str) {
    let s = &api["unit_symbols"];
    let f = |k: &str| s[k].as_str().unwrap_or("");
    (f("length"), f("stress"), f("force"))
}

/// The API in mm-MPa-N answers what `two --units mm-MPa-N --json` prints for the same joint,
/// bit for bit (R_o, its error, convergence, contact, the deflection under the nut, the mesh,
/// the rules), and names its units; against the same joint asked in inches (every length
/// divided by 25.4), R_o is 25.4 times larger within the two error bars, and the deflection
/// scales as P·D/E (P = 1 and E = 28e6 psi in each system's stress, the psi built here from
/// the inch and the pound-force).
#[test]
fn api_in_mm_is_two_in_mm_bit_for_bit() {
    let server = Server::start();
    let (status, body) = server.get("/api/joint?a=2.54&b=5.588&d=2.54&c=39.116&units=mm-MPa-N");
    assert_eq!(status, 200, "{body}");
    let api: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(api["units"], "mm-MPa-N");
    assert_eq!(symbols(&api), ("mm", "MPa", "N"));
    let two = json_of(&boltzone(&[
        "two", "--a", "2.54", "--b", "5.588", "--d", "2.54", "--c", "39.116", "--units",
        "mm-MPa-N", "--method", "fem", "--json",
    ]));
    assert_eq!(two["units"], "mm-MPa-N");
    for key in [
        "r_o",
        "r_o_error",
        "converged",
        "full_contact",
        "nut_deflection",
        "nodes",
        "dofs",
        "observed_order",
        "r_o_over_a",
    ] {
        assert!(!two[key].is_null(), "two --json has no {key}");
        assert_eq!(api["two"][key], two[key], "two.{key}");
    }
    assert_eq!(api["rules"], two["rules"], "rules");
    assert_eq!(api["inputs"]["e"], two["inputs"]["e"], "E");

    let (status, body) = server.get("/api/joint?a=0.1&b=0.22&d=0.1&c=1.54");
    assert_eq!(status, 200, "{body}");
    let inch: Value = serde_json::from_str(&body).unwrap();
    assert_eq!(inch["units"], "in-psi-lbf");
    assert_eq!(symbols(&inch), ("in", "psi", "lbf"));
    let f = |v: &Value, k: &str| v["two"][k].as_f64().unwrap();
    let ratio = f(&api, "r_o") / (25.4 * f(&inch, "r_o"));
    let bar = f(&api, "r_o_error") / f(&api, "r_o") + f(&inch, "r_o_error") / f(&inch, "r_o");
    assert!(
        (ratio - 1.0).abs() <= bar,
        "R_o mm/in/25.4 = {ratio}, bars {bar}"
    );
    const PSI_IN_MPA: f64 = 0.453_592_37 * 9.806_65 / (0.0254 * 0.0254) / 1e6;
    // δ ∝ P·D/E: D 25.4 times larger, E PSI_IN_MPA times smaller in number, P = 1 in both
    let deflection = f(&api, "nut_deflection") / f(&inch, "nut_deflection") * PSI_IN_MPA / 25.4;
    assert!(
        (deflection - 1.0).abs() <= bar,
        "deflection ratio / (25.4 / psi in MPa) = {deflection}"
    );
}

/// The boot JSON the page embeds (between `<script id="boot" type="application/json">` and
/// `</script>`).
fn boot_of(page: &str) -> Value {
    let start = "<script id=\"boot\" type=\"application/json\">";
    let at = page.find(start).expect("no boot script") + start.len();
    let end = page[at..].find("</script>").unwrap();
    serde_json::from_str(&page[at..at + end]).unwrap()
}

/// The page embeds the answer to its opening joint (A = 0.1 in, B = 3.1 A, D = A, C = 15 A,
/// ν = 0.3): the same bits as `two --json` for that joint and as the API's answer; with
/// `serve --units mm-MPa-N` the opening joint is the same joint in mm (A = 2.54 mm) and the
/// answer is `two --units mm-MPa-N --json`'s; a bad `--units` exits 2 naming the flag.
#[test]
fn the_page_embeds_the_opening_answer() {
    for (flags, units, a, b, d, c) in [
        (&[][..], "in-psi-lbf", "0.1", "0.31", "0.1", "1.5"),
        (
            &["--units", "mm-MPa-N"][..],
            "mm-MPa-N",
            "2.54",
            "7.874",
            "2.54",
            "38.1",
        ),
    ] {
        let server = Server::start_with(flags);
        let (status, page) = server.get("/");
        assert_eq!(status, 200);
        let boot = boot_of(&page);
        assert_eq!(boot["units"], units);
        let answer = &boot["answer"];
        assert_eq!(answer["units"], units);
        let two = json_of(&boltzone(&[
            "two", "--a", a, "--b", b, "--d", d, "--c", c, "--units", units, "--method", "fem",
            "--json",
        ]));
        for key in ["r_o", "r_o_error", "converged", "nut_deflection"] {
            assert_eq!(answer["two"][key], two[key], "{units}: two.{key}");
        }
        let query = format!("a={a}&b={b}&d={d}&c={c}&nu=0.3&units={units}");
        let (status, body) = server.get(&format!("/api/joint?{query}"));
        assert_eq!(status, 200, "{body}");
        let api: Value = serde_json::from_str(&body).unwrap();
        assert_eq!(answer["two"], api["two"], "{units}: embedded vs API");
        assert_eq!(answer["curves"], api["curves"], "{units}: curves");
        let hole = boot["systems"][units]["hole"].as_f64().unwrap();
        assert_eq!(hole, a.parse::<f64>().unwrap(), "{units}: the page's A");
    }
    let bad = boltzone(&["serve", "--port", "0", "--units", "furlongs"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("--units"));
}
