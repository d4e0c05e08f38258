//! One numeric field under the blank policy of the [module docs](super): the text of the
//! field's columns in, the value or the reason out (the [`Card`](super::Card) adds line,
//! columns and field name).
//!
//! # Accuracy
//!
//! `tests/io/fields.rs`: the policy table (`blanks_read_as_zeros_must_not_change_the_value`, the
//! FORTRAN 66 readings written out by hand) and 2000 random right-justified fields read back
//! exactly (`random_right_justified_fields_read_exactly`).
//!
//! # Cost
//!
//! Linear in the field width.
//!
//! ```
//! use boltzone::fortran::field::{integer, real};
//! assert_eq!(integer("  7"), Ok(7));
//! assert_eq!(integer("   "), Ok(0));
//! assert!(integer("7  ").unwrap_err().contains("read as 700"));
//! assert_eq!(real(" 1.5E+02", 8), Ok(150.0));
//! assert_eq!(real("  12345", 8), Ok(0.00012345)); // implied decimal point, E15.8
//! assert_eq!(real("-2.5-3", 8), Ok(-0.0025)); // exponent without a letter
//! assert_eq!(real("2.5    ", 0), Ok(2.5));
//! ```

/// Reads an `Iw` field's text (module docs); the error says why, in words.
pub fn integer(text: &str) -> Result<i64, String> {
    read_integer(text).map_err(|e| e.reason)
}

/// Reads an `Fw.d` or `Ew.d` field's text with `d` implied fraction digits (module docs).
pub fn real(text: &str, d: u32) -> Result<f64, String> {
    read_real(text, d).map_err(|e| e.reason)
}

/// Why a field was refused, and whether its blanks are the reason (then the field is quoted
/// with its blanks).
pub(super) struct Refusal {
    pub(super) reason: String,
    pub(super) blanks: bool,
}

pub(super) fn read_integer(text: &str) -> Result<i64, Refusal> {
    policy(text, parse_integer, "an integer (I format)")
}

pub(super) fn read_real(text: &str, d: u32) -> Result<f64, Refusal> {
    policy(text, |t| parse_real(t, d), "a real number (F/E format)")
}

/// The blank policy around a parser of blank-free text.
fn policy<T: PartialEq + std::fmt::Display + Default>(
    text: &str,
    parse: impl Fn(&str) -> Result<T, &'static str>,
    kind: &str,
) -> Result<T, Refusal> {
    let refuse = |reason: String, blanks: bool| Refusal { reason, blanks };
    if text.contains('\t') {
        return Err(refuse("a tab hides the column count".into(), true));
    }
    let t = text.trim_start_matches(' ');
    if t.is_empty() {
        return Ok(T::default());
    }
    if !t.contains(' ') {
        return parse(t).map_err(|why| refuse(format!("not {kind}: {why}"), false));
    }
    let written: String = t.chars().filter(|&c| c != ' ').collect();
    let as_1970: String = t.replace(' ', "0");
    let value = parse(&written).map_err(|why| refuse(format!("not {kind}: {why}"), false))?;
    let old = parse(&as_1970);
    if old.as_ref().is_ok_and(|v| *v == value) {
        return Ok(value);
    }
    let place = if t.trim_end_matches(' ').contains(' ') {
        "a blank inside the number"
    } else {
        "a trailing blank"
    };
    let then = match old {
        Ok(v) => format!("read as {as_1970} = {v}"),
        Err(why) => format!("read as {as_1970}, {why}"),
    };
    Err(refuse(
        format!(
            "{place}: the 1970 program (FORTRAN 66: non-leading blanks are zeros) {then}, not \
             {written}; right-justify the number or remove the blank"
        ),
        true,
    ))
}

/// An optionally signed integer without blanks.
fn parse_integer(t: &str) -> Result<i64, &'static str> {
    let digits = t.strip_prefix(['+', '-']).unwrap_or(t);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err("a sign and digits expected");
    }
    t.parse().map_err(|_| "out of range")
}

/// A FORTRAN real without blanks: sign, digits with at most one point, optional exponent.
fn parse_real(t: &str, d: u32) -> Result<f64, &'static str> {
    const FORM: &str = "sign, digits, point and exponent expected";
    let b = t.as_bytes();
    let mut i = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let start = i;
    while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
        i += 1;
    }
    let mantissa = &t[start..i];
    let points = mantissa.matches('.').count();
    if points > 1 || !mantissa.bytes().any(|c| c.is_ascii_digit()) {
        return Err(FORM);
    }
    let mut exponent: i64 = 0;
    if i < b.len() {
        let mut rest = &t[i..];
        if let Some(r) = rest.strip_prefix(['E', 'e', 'D', 'd']) {
            rest = r;
        } else if !rest.starts_with(['+', '-']) {
            return Err(FORM);
        }
        let digits = rest.strip_prefix(['+', '-']).unwrap_or(rest);
        if digits.is_empty() || !digits.bytes().all(|c| c.is_ascii_digit()) {
            return Err(FORM);
        }
        let significant = digits.trim_start_matches('0');
        if significant.len() > 5 {
            return Err("exponent out of range");
        }
        exponent = significant.parse().unwrap_or(0);
        if rest.starts_with('-') {
            exponent = -exponent;
        }
    }
    if points == 0 {
        exponent -= i64::from(d);
    }
    let sign = if t.starts_with('-') { "-" } else { "" };
    let v: f64 = format!("{sign}{mantissa}e{exponent}")
        .parse()
        .map_err(|_| FORM)?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err("overflows a double")
    }
}
