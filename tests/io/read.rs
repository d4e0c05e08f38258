//! The 1970 card reader (issue 12): FORTRAN fields, node and element generation, several decks
//! in one file, format detection, and every bad deck of the issue's list named by line, columns
//! and field. References: the edit-descriptor rules of FORTRAN IV and the report's Appendix B
//! input instructions; generated coordinates are checked against hand-computed values.

use boltzone::io::deck::{read_decks, read_decks_as, run, Appendix, Code};

const B: &str = "\
GENERATION
    9    4    2    0    1
    2        0.        0.
    1.0E+7      0.25
    1        0.        0.
    2.0E+7      0.30
    1    2       1.0       0.0
    3    2       3.0       0.0
    4    0       1.0       1.0
    6    0       3.0       2.0
    7    0       1.0       2.0
    9    0       3.0       3.0
    1    1    2    5    4    2
    2    2    3    6    5    1
    3    4    5    8    7    1
    4    5    6    9    8    1
    9    8       5.0
";

#[test]
fn node_and_element_generation_as_the_listing() {
    let d = &read_decks(B).unwrap()[0];
    assert_eq!(d.title, "GENERATION");
    assert_eq!(
        d.materials[0].table[0][1], 2.0e7,
        "material cards in any order"
    );
    let n = &d.nodes;
    // node 2 between 1 (1, 0) and 3 (3, 0); node 5 halfway from 4 (1, 1) to 6 (3, 2); node 8 likewise
    assert!(n[1].generated && n[1].code == Code::Free && (n[1].r, n[1].z) == (2.0, 0.0));
    assert_eq!((n[4].r, n[4].z), (2.0, 1.5));
    assert_eq!((n[7].r, n[7].z), (2.0, 2.5));
    assert!(!n[8].generated && n[8].line == 12);
    assert_eq!(d.pressures[0].p, 5.0);
    assert!(run(d).is_ok());
    // element 2 generated from card 1 (+1 on I, J, K, L, the material of card 1)
    let section = |cards: &str| {
        let (a, b) = (
            B.find("    1    1    2    5").unwrap(),
            B.find("    9    8       5.0").unwrap(),
        );
        B.replace(&B[a..b], cards)
    };
    let text = section("    1    1    2    5    4    2\n    3    4    5    8    7    1\n    4    5    6    9    8    1\n");
    let d = &read_decks(&text).unwrap()[0];
    assert_eq!(d.elements[1].nodes, [2, 3, 6, 5]);
    assert!(d.elements[1].generated && d.elements[1].material == 2 && d.elements[1].line == 14);
    // the listing adds 1 whatever the mesh: from card 1 to card 4, element 3 would be
    // (3, 4, 7, 6), across the mesh; the error names it and the card that closed the gap
    let e = read_decks(&section(
        "    1    1    2    5    4    2\n    4    5    6    9    8    1\n",
    ))
    .unwrap_err();
    assert_eq!((e.line, e.value.as_str()), (14, "3,4,7,6"), "{e}");
    assert!(e.reason.contains("generated element 3"), "{e}");
}

#[test]
fn several_decks_and_the_format_detected() {
    let text = std::fs::read_to_string("tests/data/decks/ring.deck").unwrap();
    let decks = read_decks(&text).unwrap();
    assert_eq!(decks.len(), 2);
    assert_eq!(
        (decks[0].appendix, decks[1].appendix),
        (Appendix::B, Appendix::C)
    );
    assert_eq!((decks[1].line, decks[1].t_ref), (15, 50.0));
    assert_eq!(decks[1].materials[0].table.len(), 2);
    // forced: the Appendix C deck read as B fails on its own cards, naming them
    let e = read_decks_as(&text, Some(Appendix::B)).unwrap_err();
    assert!(e.line >= 15, "{e}");
    // a file of separators only holds no deck
    assert!(read_decks("*****\n\n*****\n")
        .unwrap_err()
        .to_string()
        .contains("no deck"));
}

/// Each bad deck of the issue's list: (what, edit of deck B, line, field named).
#[test]
fn bad_decks_name_line_columns_and_field() {
    let lines: Vec<&str> = B.lines().collect();
    let with = |k: usize, new: &str| {
        let mut l = lines.clone();
        l[k] = new;
        l.join("\n")
    };
    let without = |k: usize| {
        let mut l = lines.clone();
        l.remove(k);
        l.join("\n")
    };
    let cases: Vec<(&str, String, usize, &str)> = vec![
        (
            "short element card",
            with(13, "    2    2    3"),
            14,
            "element node K",
        ),
        (
            "letters in a number",
            with(7, "    3    2       3.O       0.0"),
            8,
            "r",
        ),
        (
            "nodes out of sequence",
            with(8, "    2    0       1.0       1.0"),
            9,
            "node number",
        ),
        (
            "gap past the last node",
            with(8, "   12    0       1.0       1.0"),
            9,
            "node number",
        ),
        (
            "generation past the last node",
            B.replace("    9    4    2", "    9    5    2").replace(
                "    3    4    5    8    7    1\n    4    5    6    9    8    1",
                "    3    5    6    9    8    1\n    5    4    5    8    7    1",
            ),
            16,
            "element node K",
        ),
        (
            "missing last element card",
            without(15).replace("    9    8       5.0", ""),
            16,
            "element card",
        ),
        (
            "clockwise element",
            with(12, "    1    1    4    5    2    2"),
            13,
            "element nodes I,J,K,L",
        ),
        (
            "pressure on a non-edge",
            with(16, "    8    9       5.0"),
            17,
            "pressure card I, J",
        ),
        (
            "pressure across an element",
            with(16, "    1    5       5.0"),
            17,
            "pressure card I, J",
        ),
        (
            "bad code",
            with(6, "    1    7       1.0       0.0"),
            7,
            "CODE",
        ),
        (
            "no material",
            with(13, "    2    2    3    6    5    3"),
            14,
            "material number",
        ),
        (
            "bad Poisson ratio",
            with(3, "    1.0E+7       0.5"),
            4,
            "nu",
        ),
        (
            "zero elements",
            with(1, "    9    0    2    0    1"),
            2,
            "number of elements",
        ),
        (
            "extra card",
            format!("{B}    1    2       1.0\n"),
            18,
            "card after the last pressure card",
        ),
        (
            "first node not 1",
            with(6, "    2    2       1.0       0.0"),
            7,
            "node number",
        ),
        (
            "negative radius",
            with(6, "    1    2      -1.0       0.0"),
            7,
            "r",
        ),
    ];
    for (what, text, line, field) in cases {
        let e = match read_decks(&text) {
            Err(e) => e,
            Ok(d) => run(&d[0]).expect_err(what),
        };
        assert_eq!((e.line, e.field.as_str()), (line, field), "{what}: {e}");
        assert!(
            e.to_string().starts_with(&format!("line {line}")),
            "{what}: {e}"
        );
    }
    // a body free to move along z: the solver's failure names the supports, on the title line
    let free = B
        .replace("    1    2       1.0", "    1    0       1.0")
        .replace("    3    2       3.0", "    3    0       3.0");
    let e = run(&read_decks(&free).unwrap()[0]).unwrap_err();
    assert_eq!(
        (e.line, e.field.as_str()),
        (1, "nodal point codes (supports)"),
        "{e}"
    );
}

#[test]
fn appendix_c_generated_nodes_interpolate_temperature() {
    let text = std::fs::read_to_string("tests/data/decks/ring.deck").unwrap();
    let c = &text[text.find("HELD RING").unwrap()..];
    // drop the cards of nodes 2 and 5 and give nodes 1 and 3 different temperatures
    let c: String = c
        .lines()
        .filter(|l| {
            !l.starts_with("    2    2       1.5") && !l.starts_with("    5    0       1.5")
        })
        .map(|l| match &l[..5] {
            "    3" if l.len() > 50 => format!("{}     190.0", &l[..50]),
            _ => l.to_string(),
        })
        .collect::<Vec<_>>()
        .join("\n");
    let d = &read_decks(&c).unwrap()[0];
    let n2 = &d.nodes[1];
    assert!(n2.generated && n2.code == Code::Free);
    assert_eq!((n2.r, n2.t), (1.5, 170.0)); // halfway between 150 and 190
    assert_eq!(d.nodes[4].t, 150.0);
}
