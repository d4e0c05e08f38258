//! Appendix D card decks (src/heat/deck.rs): a deck written by hand against the same network
//! built through the API, errors that name line and field, and seeded mutations that must never
//! panic. The FORTRAN field rules are tested in `tests/io/fields.rs`.

use boltzone::fortran::DeckError;
use boltzone::heat::deck::parse_network_decks;
use boltzone::heat::network::Network;

/// Two decks, punched by hand: the first a chain 1-2-3-4 (conductances 2.5, 1.5, 2.5; node 1 to
/// a ground at 100 through 10, node 4 to one at -20 through 5; 3 units of power in node 2), with
/// an implied decimal point (250000000 in E15.8 is 2.5), a D exponent, a bare-sign exponent
/// (-2.+1 is -20), a blank group and sequence numbers in columns 73-80; the second two nodes.
const DECK: &str = "\
0LAP JOINT CHAIN                                                        SSHT0001
0
0
1FOUR NODES
      4
1
0  1  2 2.50000000E+00  2  3 1.50000000D+00                             SSHT0002
1  3  4      250000000
1     1          1.0E1     4            5.0
1     1           100.     4          -2.+1
1     2             3.     0             0.                     

1SECOND DECK
      2
1
1  1  2            1.0
1     1            1.0     2            1.0
1     1            1.0
1
";

fn api_chain() -> Network {
    let mut net = Network::new(4).unwrap();
    net.connect(1, 2, 2.5).unwrap();
    net.connect(2, 3, 1.5).unwrap();
    net.connect(3, 4, 2.5).unwrap();
    net.ground(1, 10.0, 100.0).unwrap();
    net.ground(4, 5.0, -20.0).unwrap();
    net.power(2, 3.0).unwrap();
    net
}

#[test]
fn hand_written_deck_equals_the_api_network() {
    let decks = parse_network_decks(DECK).unwrap();
    assert_eq!(decks.len(), 2);
    assert_eq!(decks[0].title, "LAP JOINT CHAIN\nFOUR NODES");
    assert_eq!(decks[0].line, 1);
    assert_eq!(decks[0].network, api_chain());
    let (a, b) = (decks[0].solve().unwrap(), api_chain().solve().unwrap());
    assert_eq!(a.solution, b);
    // Closed form of the chain: resistances 1/10, 1/2.5, 1/1.5, 1/2.5, 1/5 in series, with 3
    // entering at node 2. Superpose: the 120-degree drop drives q0 = 120 / R; the source splits
    // by the resistances to each ground (left 0.5, right 1/1.5 + 0.4 + 0.2).
    let r: f64 = 0.1 + 0.4 + 1.0 / 1.5 + 0.4 + 0.2;
    let q0 = 120.0 / r;
    let (rl, rr) = (0.5, 1.0 / 1.5 + 0.6);
    let q_left = 3.0 * rr / (rl + rr); // source heat leaving by the left ground
    let t2 = 100.0 - q0 * 0.5 + q_left * 0.5;
    assert!(
        (a.solution.nodes[1].t - t2).abs() < 1e-12,
        "{} vs {t2}",
        a.solution.nodes[1].t
    );
    let s2 = decks[1].solve().unwrap();
    assert_eq!(s2.title, "SECOND DECK");
    assert!((s2.solution.nodes[1].t - 1.0 / 3.0).abs() < 1e-15);
    // The contract JSON: {"title", "nodes": [{"n", "t", ...}], "residual"}.
    let v = serde_json::to_value(&a).unwrap();
    assert_eq!(v["title"], "LAP JOINT CHAIN\nFOUR NODES");
    assert_eq!(v["nodes"][0]["n"], 1);
    assert!(v["nodes"][3]["t"].is_f64() && v["residual"].is_f64());
    let text = a.to_string();
    assert!(text.starts_with("LAP JOINT CHAIN") && text.contains("RESIDUAL"));
}

fn expect_error(deck: &str, line: usize, field: &str) {
    match parse_network_decks(deck) {
        Err(DeckError {
            line: l,
            columns: Some(_),
            field: f,
            ..
        }) => {
            assert_eq!(l, line, "{deck}");
            assert!(f.contains(field), "'{f}' should name '{field}'");
        }
        other => panic!("expected a field error, got {other:?}"),
    }
}

#[test]
fn errors_name_line_columns_and_field() {
    let base = "1T\n      2\n1\n";
    let tail = "1     1            1.0\n1\n1\n";
    // Higher node first: the listing would overwrite it; duplicate pair; node 3 of 2.
    expect_error(
        &format!("{base}1  2  1            1.0\n{tail}"),
        4,
        "nodes i, j",
    );
    expect_error(
        &format!("{base}0  1  2            1.0  1  2            2.0\n1\n{tail}"),
        4,
        "nodes i, j",
    );
    expect_error(
        &format!("{base}1  1  3            1.0\n{tail}"),
        4,
        "node j (I3)",
    );
    expect_error(
        &format!("{base}1  1  2            x.0\n{tail}"),
        4,
        "conductance (E15.8)",
    );
    expect_error("1T\n    x\n", 2, "dimension N");
    expect_error("1T\n      0\n1\n", 2, "dimension N");
    let e = parse_network_decks(&format!(
        "{base}1  1  2            1.0\n1     1           -1.0\n"
    ))
    .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("line 5, columns 8-22 (ground conductance group 1, value"),
        "{e}"
    );
    let e = parse_network_decks("1T\n      2\n1\n0  1  2            1.0\n").unwrap_err();
    assert_eq!(
        (e.line, e.columns, e.field.as_str()),
        (5, None, "the conductance cards (I1,3(2I3,E15.8)) of deck 1")
    );
    assert!(e.reason.contains("ends before"), "{e}");
    // Trailing blank cards make no deck; an unfinished identification does.
    assert_eq!(parse_network_decks("\n\n  \n").unwrap().len(), 0);
    assert!(matches!(
        parse_network_decks("0TITLE\n"),
        Err(DeckError {
            line: 2,
            columns: None,
            ..
        })
    ));
}

use crate::network_fixtures::Rng;

/// A mutation of the hand deck: characters replaced, inserted or deleted, lines dropped or
/// duplicated, from an alphabet of what cards hold.
fn mutate(rng: &mut Rng) -> String {
    let mut lines: Vec<Vec<char>> = DECK.lines().map(|l| l.chars().collect()).collect();
    let alphabet: Vec<char> = " 0123456789+-.EDed1x\u{e9}\t".chars().collect();
    for _ in 0..1 + rng.below(4) {
        let li = rng.below(lines.len());
        match rng.below(6) {
            0 => {
                lines.remove(li);
                if lines.is_empty() {
                    break;
                }
            }
            1 => {
                let l = lines[li].clone();
                lines.insert(li, l);
            }
            2 => {
                let c = rng.below(lines[li].len() + 1);
                lines[li].insert(c, alphabet[rng.below(alphabet.len())]);
            }
            3 if !lines[li].is_empty() => {
                let c = rng.below(lines[li].len());
                lines[li].remove(c);
            }
            _ => {
                let c = rng.below(80);
                while lines[li].len() <= c {
                    lines[li].push(' ');
                }
                lines[li][c] = alphabet[rng.below(alphabet.len())];
            }
        }
    }
    lines
        .iter()
        .map(|l| l.iter().collect::<String>() + "\n")
        .collect()
}

fn fuzz(cases: usize, seed: u64) -> (usize, usize) {
    let mut rng = Rng::new(seed);
    let (mut ok, mut errors) = (0, 0);
    for case in 0..cases {
        let deck = mutate(&mut rng);
        let result = std::panic::catch_unwind(|| parse_network_decks(&deck));
        match result {
            Err(_) => panic!("case {case} panicked on:\n{deck}"),
            Ok(Ok(decks)) => {
                ok += 1;
                for d in decks {
                    // Solving may fail (a floating node) but must not panic.
                    let _ = d
                        .solve()
                        .map(|s| assert!(s.solution.nodes.iter().all(|n| n.t.is_finite())));
                }
            }
            Ok(Err(e)) => {
                errors += 1;
                let msg = e.to_string();
                assert!(msg.starts_with("line "), "case {case}: {msg}");
                assert!(!e.field.is_empty(), "{msg}");
            }
        }
    }
    (ok, errors)
}

#[test]
fn mutated_decks_never_panic_and_errors_name_line_and_field() {
    let (ok, errors) = fuzz(400, 1970);
    // Both outcomes occur: the mutations are neither all harmless nor all fatal.
    assert!(ok > 20 && errors > 20, "ok {ok}, errors {errors}");
}

#[test]
#[ignore = "10^4 mutations, about a second; run with --ignored"]
fn ten_thousand_mutated_decks() {
    let (ok, errors) = fuzz(10_000, 71_821);
    eprintln!("10^4 mutations: {ok} read, {errors} rejected with line and field");
}
