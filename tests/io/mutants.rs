//! Mutated decks (issue 12): seeded random edits of valid decks — characters in fields, columns
//! shifted, cards cut, dropped, doubled, swapped or moved — must never panic, and every rejected
//! deck must name a line of the file (or the one after its end) and a field, with columns inside
//! a card. A few hundred mutants run in CI; `cargo test --test deck_mutants -- --ignored` runs
//! 100 000.

use boltzone::fem::Spacing;
use boltzone::io::deck::{read_decks, run, single_plate_deck, write_deck, DeckError};
use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};

use boltzone::numerics::random::SplitMix64 as Rng;

fn seeds() -> Vec<String> {
    let ring = std::fs::read_to_string("tests/data/decks/ring.deck").unwrap();
    let load = FaceLoad::uniform(0.1, 0.31, 1000.0).unwrap();
    let plate = SinglePlate::new(
        0.1,
        OuterRadius::Finite(0.5),
        0.1,
        Material::new(28.0e6, 0.3).unwrap(),
        load,
    )
    .unwrap();
    let r = Spacing::uniform(0.1, 0.5, 8).unwrap();
    let z = Spacing::uniform(0.0, 0.1, 2).unwrap();
    let plate = write_deck(&single_plate_deck(&plate, &r, &z, "SMALL PLATE").unwrap()).unwrap();
    vec![ring, plate]
}

const CHARS: &[u8] = b" 0123456789.-+EeDx*\t9";

fn mutate(text: &str, rng: &mut Rng) -> String {
    let mut lines: Vec<String> = text.lines().map(String::from).collect();
    for _ in 0..1 + rng.below(3) {
        let n = lines.len();
        let k = rng.below(n);
        match rng.below(8) {
            0 | 1 => {
                // a character of a field
                let mut b = lines[k].clone().into_bytes();
                let c = CHARS[rng.below(CHARS.len())];
                if b.is_empty() {
                    b.push(c)
                } else {
                    let i = rng.below(b.len());
                    b[i] = c;
                }
                lines[k] = String::from_utf8(b).unwrap();
            }
            2 => {
                // columns shifted: blanks inserted or a character removed
                let l = &mut lines[k];
                let i = rng.below(l.len() + 1);
                if rng.below(2) == 0 {
                    l.insert_str(i, &" ".repeat(1 + rng.below(3)))
                } else if i < l.len() {
                    l.remove(i);
                }
            }
            3 => {
                let cut = rng.below(lines[k].len() + 1);
                lines[k].truncate(cut);
            }
            4 => {
                lines.remove(k);
            }
            5 => {
                let l = lines[k].clone();
                lines.insert(k, l);
            }
            6 => {
                let j = rng.below(n);
                lines.swap(k, j);
            }
            _ => {
                let l = lines.remove(k);
                let j = rng.below(lines.len() + 1);
                lines.insert(j, l);
            }
        }
        if lines.is_empty() {
            lines.push(String::new());
        }
    }
    lines.join("\n") + "\n"
}

fn check(e: &DeckError, text: &str) {
    let n_lines = text.lines().count();
    assert!(
        e.line >= 1 && e.line <= n_lines + 1,
        "line {} of {n_lines}: {e}\n{text}",
        e.line
    );
    assert!(!e.field.is_empty(), "no field: {e}\n{text}");
    if let Some((a, b)) = e.columns {
        assert!(a >= 1 && a <= b && b <= 80, "columns {a}-{b}: {e}");
    }
    assert!(e.to_string().starts_with(&format!("line {}", e.line)));
}

/// Runs `count` mutants; returns (accepted and solved, rejected).
fn mutants(count: usize, seed: u64) -> (usize, usize) {
    let seeds = seeds();
    let mut rng = Rng::new(seed);
    let (mut ok, mut bad) = (0, 0);
    for i in 0..count {
        let text = mutate(&seeds[i % seeds.len()], &mut rng);
        let outcome = std::panic::catch_unwind(|| match read_decks(&text) {
            Err(e) => Err(e),
            Ok(decks) => decks
                .iter()
                .map(run)
                .collect::<Result<Vec<_>, _>>()
                .map(|sols| {
                    // an accepted deck has a finite answer
                    for s in sols {
                        let n = s.nodes.iter().flat_map(|n| [n.u, n.w]);
                        let e = s
                            .elements
                            .iter()
                            .flat_map(|e| [e.sigma_r, e.sigma_z, e.sigma_t, e.tau_rz]);
                        assert!(n.chain(e).all(f64::is_finite), "not finite");
                    }
                }),
        });
        match outcome {
            Err(_) => panic!("mutant {i} (seed {seed}) panicked:\n{text}"),
            Ok(Ok(())) => ok += 1,
            Ok(Err(e)) => {
                check(&e, &text);
                bad += 1;
            }
        }
    }
    (ok, bad)
}

#[test]
fn a_few_hundred_mutants_never_panic_and_name_line_and_field() {
    let (ok, bad) = mutants(400, 12);
    println!("400 mutants: {ok} accepted and solved, {bad} rejected with line and field");
    assert!(
        bad > 100 && ok > 10,
        "the mutations exercise both outcomes: {ok} / {bad}"
    );
}

#[test]
#[ignore = "100 000 mutants, a few seconds: run before a release"]
fn a_hundred_thousand_mutants() {
    let (ok, bad) = mutants(100_000, 1970);
    println!("100000 mutants: {ok} accepted and solved, {bad} rejected with line and field");
}
