//! Seeded mutated scenes (keys, types, values, TOML syntax) through the parser, the checks and
//! the sweep expansion: no panic, and every error is located (key and line within the file).
//! A few hundred in CI; 10⁴ in the ignored test. Seeded by the project's one generator
//! (`numerics::random::SplitMix64`).

use boltzone::numerics::random::SplitMix64;
use boltzone::scene::sweep::points;
use boltzone::scene::SceneError;

type Rng = SplitMix64;

const VALUES: [&str; 22] = [
    "0",
    "-1",
    "1e308",
    "-0.0",
    "nan",
    "inf",
    "-inf",
    "1e-308",
    "\"abc\"",
    "true",
    "[]",
    "[1, 2]",
    "{}",
    "{ E = 1 }",
    "0.4999",
    "0.5",
    "3",
    "\"peak-a\"",
    "\"welded\"",
    "1979-05-27",
    "\"steel-304\"",
    "{ E = 2e11, nu = 0.3 }",
];
const KEYS: [&str; 18] = [
    "radius",
    "outer_radius",
    "thickness",
    "material",
    "force",
    "pressure",
    "nut_displacement",
    "profile",
    "interface",
    "tolrance",
    "correlation",
    "conductivity",
    "roughness",
    "slope",
    "hardness",
    "conductance",
    "field",
    "midplane",
];
const SYNTAX: [&str; 8] = ["[", "]", "=", "\"", "[[plates]]", "[hole]", "= =", "#"];

fn mutate(rng: &mut Rng, base: &str) -> String {
    let mut lines: Vec<String> = base.lines().map(str::to_string).collect();
    for _ in 0..1 + rng.below(3) {
        let i = rng.below(lines.len());
        match rng.below(6) {
            0 => {
                if let Some((k, _)) = lines[i].clone().split_once('=') {
                    lines[i] = format!("{}= {}", k, rng.pick(&VALUES));
                }
            }
            1 => {
                if let Some((_, v)) = lines[i].clone().split_once('=') {
                    lines[i] = format!("{} ={v}", rng.pick(&KEYS));
                }
            }
            2 => {
                lines.remove(i);
                if lines.is_empty() {
                    lines.push(String::new());
                }
            }
            3 => {
                let at = rng.below(lines[i].len() + 1);
                let mut l = lines[i].clone();
                if l.is_char_boundary(at) {
                    let piece: &&str = rng.pick(&SYNTAX);
                    l.insert_str(at, piece);
                }
                lines[i] = l;
            }
            4 => {
                let j = rng.below(lines.len());
                let dup = lines[j].clone();
                lines.insert(i, dup);
            }
            _ => lines.insert(i, format!("{} = {}", rng.pick(&KEYS), rng.pick(&VALUES))),
        }
    }
    lines.join("\n") + "\n"
}

fn run(n: usize, seed: u64) {
    let bases = [
        crate::example("table1_row1"),
        crate::example("table2_case5"),
        crate::example("chapter6_pair"),
        crate::example("m8_aluminium_sweep"),
        crate::example("chapter5_lap"),
    ];
    let mut rng = Rng::new(seed);
    let (mut ok, mut bad) = (0, 0);
    for k in 0..n {
        let text = mutate(&mut rng, &bases[k % bases.len()]);
        let lines = text.lines().count().max(1);
        let r = std::panic::catch_unwind(|| points(&text));
        match r {
            Err(_) => panic!("panic on mutant {k}:\n{text}"),
            Ok(Ok(_)) => ok += 1,
            Ok(Err(e)) => {
                bad += 1;
                let SceneError::Invalid { key, line, .. } = &e else {
                    panic!("unlocated error {e} on mutant {k}:\n{text}")
                };
                assert!(!key.is_empty(), "no key: {e}\n{text}");
                assert!(
                    (1..=lines + 1).contains(line),
                    "line {line} of {lines}: {e}\n{text}"
                );
                let msg = e.to_string();
                assert!(msg.contains(&format!("line {line}")) && msg.contains(key.as_str()));
            }
        }
    }
    eprintln!("{n} mutants: {ok} valid, {bad} rejected with key and line");
    assert!(
        ok > 0 && bad > n / 4,
        "{ok} valid, {bad} rejected: the mutations must reach both"
    );
}

#[test]
fn mutated_scenes_never_panic_and_every_error_is_located() {
    run(400, 0x5EED_0010);
}

#[test]
#[ignore = "10^4 mutants, ~seconds; run before a release"]
fn ten_thousand_mutated_scenes() {
    run(10_000, 0xB017_2011);
}

#[test]
#[ignore = "solves ~500 valid mutants of the M8 sweep (Hankel route), about a minute"]
fn valid_mutants_solve_without_panic() {
    let base = crate::example("m8_aluminium_sweep");
    let mut rng = Rng::new(0x5015_E000);
    let (mut solved, mut failed, mut unconverged) = (0, 0, 0);
    for _ in 0..2_500 {
        let text = mutate(&mut rng, &base);
        let Ok(pts) = points(&text) else { continue };
        let results = std::panic::catch_unwind(|| boltzone::scene::sweep::solve_all(&pts, &|| {}))
            .unwrap_or_else(|_| panic!("panic solving:\n{text}"));
        for r in results {
            match r {
                Ok(s) => {
                    assert!(s.r_o.is_finite() && s.r_o_error.is_finite(), "{text}");
                    solved += 1;
                    unconverged += usize::from(!s.converged);
                }
                Err(_) => failed += 1,
            }
        }
    }
    eprintln!(
        "{solved} points solved ({unconverged} not converged), {failed} failed with an error"
    );
}
