//! The one FORTRAN field reader (`src/fortran/`) and its blank policy, for the decks of
//! Appendices B, C and D. References: the edit-descriptor rules of FORTRAN IV and the blank
//! rule of ANSI X3.9-1966 (non-leading blanks are zeros), applied by hand in each case below
//! (the value the 1970 program read is written out, not computed by the reader), and Rust's own
//! formatting of random numbers for the right-justified fields a deck writer punches.

use boltzone::fortran::field::{integer, real};
use boltzone::fortran::Card;
use boltzone::numerics::random::SplitMix64;

#[test]
fn fortran_fields() {
    let text = format!(
        "{:>5}{:>5}{:>10}{:>10}{:>10}{:>10}{:>10}",
        "12", "-3", "1.5E+03", "1.5D-3", "1.5+3", "1.5-3", "-.001"
    );
    let c = Card::new(7, &text);
    assert_eq!(c.int(1, 5, "N").unwrap(), 12);
    assert_eq!(c.int(6, 10, "N").unwrap(), -3);
    assert_eq!(c.real(11, 20, 0, "x").unwrap(), 1500.0);
    assert_eq!(c.real(21, 30, 0, "x").unwrap(), 1.5e-3);
    assert_eq!(c.real(31, 40, 0, "x").unwrap(), 1500.0); // exponent without a letter
    assert_eq!(c.real(41, 50, 0, "x").unwrap(), 1.5e-3);
    assert_eq!(c.real(51, 60, 0, "x").unwrap(), -0.001);
    assert_eq!(c.real(70, 79, 0, "x").unwrap(), 0.0); // beyond the line: blank, zero
                                                      // implied decimal point (Fw.d without a point), and a written point overrides d
    let c = Card::new(1, "     12345   1.2345");
    assert_eq!(c.real(1, 10, 3, "x").unwrap(), 12.345);
    assert_eq!(c.real(11, 19, 3, "x").unwrap(), 1.2345);
    // A left-justified real with a point reads as written (its trailing blanks are zero
    // fraction digits in 1970 too); a left-justified integer does not: FORTRAN 66 read "1    "
    // as 10000 (changed on purpose: this reader took it as 1 before the policy was unified).
    let c = Card::new(1, "1    2.5       ");
    assert_eq!(c.real(6, 15, 0, "r").unwrap(), 2.5);
    let msg = c.int(1, 5, "N").unwrap_err().to_string();
    assert!(
        msg.contains("trailing blank") && msg.contains("= 10000"),
        "{msg}"
    );
    for (text, why) in [
        ("  1 2", "blank inside"),
        (" 1.0 ", "not an integer"),
        ("  x  ", "not an integer"),
        ("   - ", "not an integer"),
        ("\t  12", "tab"),
    ] {
        let e = Card::new(4, text).int(1, 5, "element node K").unwrap_err();
        let msg = e.to_string();
        assert!(
            msg.starts_with("line 4, columns 1-5 (element node K"),
            "{msg}"
        );
        assert!(msg.contains(why), "{text:?}: {msg}");
    }
    for bad in ["1.5E", "1.2.3", "abc", "1E999", "E5", ".", "1.5E+3x"] {
        let e = Card::new(2, &format!("{bad:>10}"))
            .real(1, 10, 0, "r")
            .unwrap_err();
        assert_eq!(
            (e.line, e.columns, e.field.as_str()),
            (2, Some((1, 10)), "r"),
            "{bad}"
        );
    }
}

/// The Appendix D fields (E15.8, implied 8 decimals), formerly read by a second reader.
#[test]
fn fortran_fields_read_as_in_1970() {
    assert_eq!(integer("   "), Ok(0));
    assert_eq!(integer(" -12"), Ok(-12));
    // Changed on purpose: the Appendix D reader read "1  " as 100 without a word; FORTRAN 66
    // read 100, the card's author most likely meant 1, so it is an error naming both.
    let e = integer("1  ").unwrap_err();
    assert!(e.contains("read as 100 = 100, not 1"), "{e}");
    assert!(integer("1a").unwrap_err().contains("not an integer"));
    assert_eq!(real("               ", 8), Ok(0.0));
    assert_eq!(real("      250000000", 8), Ok(2.5));
    assert_eq!(real("            25.", 8), Ok(25.0));
    assert_eq!(real("        2.5D-03", 8), Ok(0.0025));
    assert_eq!(real("         25E+01", 8), Ok(25e-7)); // implied point, then the exponent
    assert_eq!(real("   -.5e1", 8), Ok(-5.0));
    assert_eq!(real("1.5            ", 8), Ok(1.5)); // trailing blanks as zero fraction digits
    let e = real("1.5E2          ", 8).unwrap_err(); // E2 and ten blank zeros: out of range
    assert!(
        e.contains("read as 1.5E20000000000, exponent out of range") && e.contains("right-justify"),
        "{e}"
    );
    assert!(real("1.5.2", 8).is_err());
    assert!(real("+", 8).is_err());
    assert!(real("E5", 8).is_err());
}

/// Each blank the policy meets: accepted when FORTRAN 66's zeros and the written text give one
/// value (the value given here by hand), refused naming the 1970 reading when they differ.
#[test]
fn blanks_read_as_zeros_must_not_change_the_value() {
    // (field, implied decimals or None for Iw, the value) — both readings agree.
    let agree: [(&str, Option<u32>, f64); 7] = [
        ("     ", None, 0.0),    // all blank: zero
        ("0    ", None, 0.0),    // 00000 = 0
        ("-  1", None, -1.0),    // -001 = -1
        ("1.5 0", Some(0), 1.5), // 1.500 = 1.50
        ("2.50  ", Some(3), 2.5),
        ("1.5 E2", Some(0), 150.0), // 1.50E2 = 1.5E2
        ("   .25   ", Some(0), 0.25),
    ];
    for (text, d, want) in agree {
        let got = match d {
            None => integer(text).map(|v| v as f64),
            Some(d) => real(text, d),
        };
        assert_eq!(got, Ok(want), "{text:?}");
    }
    // (field, implied decimals or None, what FORTRAN 66 read, the written value).
    let differ: [(&str, Option<u32>, &str, &str); 7] = [
        ("12   ", None, "12000 = 12000", "12"),
        (" 1 2 ", None, "1020 = 1020", "12"),
        (
            "2.5-3 ",
            Some(0),
            "2.5-30 = 0.0000000000000000000000000000025",
            "2.5-3",
        ),
        ("12345  ", Some(8), "1234500 = 0.012345", "12345"),
        ("1. 5", Some(0), "1.05 = 1.05", "1.5"),
        ("3E1 ", Some(0), "3E10 = 30000000000", "3E1"),
        ("   7 ", Some(0), "70 = 70", "7"), // no point: the blank is a units digit
    ];
    for (text, d, then, written) in differ {
        let e = match d {
            None => integer(text).map(|v| v as f64),
            Some(d) => real(text, d),
        }
        .unwrap_err();
        assert!(
            e.contains(&format!("read as {then}, not {written}")),
            "{text:?}: {e}"
        );
    }
}

/// Right-justified fields as a deck writer punches them (Rust's `{:>w}` of random integers and
/// of random reals in `{:e}`, `{:.6}` and exponent-without-letter form) read back exactly, and
/// the same integers left-justified are refused unless they end in no blank at all.
#[test]
fn random_right_justified_fields_read_exactly() {
    let mut rng = SplitMix64::new(1970);
    for _ in 0..2000 {
        let n = rng.below(199_999) as i64 - 99_999;
        assert_eq!(integer(&format!("{n:>10}")), Ok(n));
        let left = format!("{n:<10}");
        if left.ends_with(' ') {
            assert!(integer(&left).is_err(), "{left:?}");
        }
        let unit = (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        let x = (unit - 0.5) * 10f64.powi(rng.below(21) as i32 - 10);
        assert_eq!(real(&format!("{x:>25e}"), 0), Ok(x));
        let short = format!("{x:.6}");
        let want: f64 = short.parse().unwrap();
        assert_eq!(real(&format!("{short:>25}"), 3), Ok(want));
        assert_eq!(real(&format!("{short:<25}"), 3), Ok(want)); // trailing zeros of a fraction
        let m = format!("{x:e}").replace("e-", "-").replace('e', "+");
        assert_eq!(real(&format!("{m:>25}"), 0), Ok(x), "{m}");
    }
}
