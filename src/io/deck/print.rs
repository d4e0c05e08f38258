//! The printout of a deck run, as the 1970 program laid it out (input echoed, nodal
//! displacements, stresses at each element's centre), with units on every column, and the JSON
//! form of the same results.
//!
//! # Accuracy
//!
//! The printed and JSON outputs carry the solution's numbers unchanged: `tests/io/cli.rs`
//! (`json_contract_and_emit_round_trip`).
//!
//! # Cost
//!
//! Linear in the nodes and elements.

use super::model::{Appendix, Code, Deck};
use super::run::DeckSolution;
use serde_json::{json, Value};
use std::fmt::Write;

/// The printed report of one deck and its solution. Units are the deck's own: lengths L,
/// stresses and E in F/L², loads F per radian, temperatures as in its tables.
pub fn report(deck: &Deck, sol: &DeckSolution) -> String {
    let mut o = String::new();
    let c = deck.appendix == Appendix::C;
    // the temperature column of Appendix C decks
    let t_column = |t: f64| {
        if c {
            format!(" {t:>10.3}")
        } else {
            String::new()
        }
    };
    let _ = writeln!(o, "{}", deck.title);
    let _ = writeln!(o, "Appendix {:?} deck (line {}); units: the deck's own (length L, stress F/L^2, load F per radian{})", deck.appendix, deck.line, if c { ", temperature as its tables" } else { "" });
    let _ = writeln!(
        o,
        "NUMBER OF NODAL POINTS----- {}\nNUMBER OF ELEMENTS--------- {}",
        deck.nodes.len(),
        deck.elements.len()
    );
    if c {
        let _ = writeln!(o, "REFERENCE TEMPERATURE------ {}", deck.t_ref);
    }
    for m in &deck.materials {
        let _ = writeln!(o, "MATERIAL NUMBER---- {}\n INITIAL VERTICAL STRESS= {:.3} F/L^2     INITIAL HORIZONTAL STRESS= {:.3} F/L^2 (echoed, not used with NORM = 0)", m.id, m.sigma_z0, m.sigma_r0);
        let _ = writeln!(
            o,
            "{:>14} {:>14} {:>10} {:>14}",
            "T", "E [F/L^2]", "NU [-]", "ALPHA [1/T]"
        );
        for r in &m.table {
            let _ = writeln!(
                o,
                "{:>14.4} {:>14.6e} {:>10.4} {:>14.6e}",
                r[0], r[1], r[2], r[3]
            );
        }
    }
    let _ = writeln!(
        o,
        "\n NODAL POINT     TYPE   R-ORDINATE [L]   Z-ORDINATE [L]   XR [F or L]   XZ [F or L]{}",
        if c { "   T" } else { "" }
    );
    for n in &deck.nodes {
        let code = match n.code {
            Code::Skew(a) => format!("{a}"),
            k => format!("{}", k.value()),
        };
        let _ = writeln!(
            o,
            "{:>12} {:>8} {:>16.6} {:>16.6} {:>13.5e} {:>13.5e}{}",
            n.n,
            code,
            n.r,
            n.z,
            n.xr,
            n.xz,
            t_column(n.t)
        );
    }
    let _ = writeln!(o, "\n ELEMENT NO.      I      J      K      L   MATERIAL");
    for e in &deck.elements {
        let n = e.nodes;
        let _ = writeln!(
            o,
            "{:>12} {:>6} {:>6} {:>6} {:>6} {:>10}",
            e.n, n[0], n[1], n[2], n[3], e.material
        );
    }
    if !deck.pressures.is_empty() {
        let _ = writeln!(
            o,
            "\nPRESSURE BOUNDARY CONDITIONS\n      I      J   PRESSURE [F/L^2]"
        );
        for p in &deck.pressures {
            let _ = writeln!(o, "{:>7} {:>6} {:>18.6e}", p.i, p.j, p.p);
        }
    }
    let _ = writeln!(
        o,
        "\n NODAL POINT   R-DISPLACEMENT [L]   Z-DISPLACEMENT [L]   (s and n at skew nodes)"
    );
    for n in &sol.nodes {
        let _ = writeln!(o, "{:>12} {:>20.7e} {:>20.7e}", n.n, n.u, n.w);
    }
    let _ = writeln!(o, "\n ELEMENT  R [L]  Z [L]   SIG(R)  SIG(Z)  SIG(T)  TAU(RZ)  SIG(1)  SIG(2) [F/L^2]  ANGLE [deg]{}", if c { "  T" } else { "" });
    for e in &sol.elements {
        let _ = writeln!(
            o,
            "{:>8} {:>9.4} {:>9.4} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e} {:>12.4e} {:>9.2}{}",
            e.n,
            e.r,
            e.z,
            e.sigma_r,
            e.sigma_z,
            e.sigma_t,
            e.tau_rz,
            e.principal[0],
            e.principal[1],
            e.angle_deg,
            t_column(e.temperature)
        );
    }
    let _ = writeln!(
        o,
        "\n {} equations, solved in {:.3} s\n END OF PROBLEM {}",
        sol.equations, sol.seconds, deck.title
    );
    o
}

/// The JSON of one deck's results (the contract of `boltzone deck --json`):
/// `{"title", "appendix", "nodes": [{"n", "r", "z", "u", "w"}], "elements": [{"n", "r", "z",
/// "sigma_r", "sigma_z", "sigma_t", "tau_rz"}]}`.
pub fn json_deck(deck: &Deck, sol: &DeckSolution) -> Value {
    json!({
        "title": deck.title,
        "appendix": format!("{:?}", deck.appendix),
        "nodes": sol.nodes,
        "elements": sol.elements,
    })
}
