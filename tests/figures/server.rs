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
        let mut child = Command::new(env!("CARGO_BIN_EXE_boltzone"))
            .args(["serve", "--port", "0"])
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
    let two = json_of(&boltzone(&[&["two"], &args[..]].concat()));
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
