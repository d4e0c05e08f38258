//! Fixed-column FORTRAN IV input fields, read as the 1970 programs read their cards.
//!
//! - A field is a range of card columns (1-based); a line shorter than the field is padded with
//!   blanks, columns past the last field are ignored (sequence numbers).
//! - `Iw`: an optionally signed integer. Leading blanks are skipped, an all-blank field is 0, and
//!   embedded or trailing blanks are zeros (FORTRAN IV, e.g. IBM System/360 FORTRAN IV: `"1  "`
//!   in I3 is 100; the error messages say so).
//! - `Ew.d` / `Fw.d`: a sign, digits with an optional point, an optional exponent written `E±n`,
//!   `D±n` or just `±n`. Blanks as for `Iw`. With no point punched the last d digits of the
//!   mantissa are the fraction (`"12345"` in E15.8 is 0.00012345); a punched point overrides d.
//!
//! Accuracy: values are converted by Rust's correctly rounded decimal parser. Tests:
//! `tests/heat_deck.rs`. Cost: linear in the field width.
//!
//! ```
//! use boltzone::heat::fortran::{integer, real};
//! assert_eq!(integer("  7"), Ok(7));
//! assert_eq!(real(" 1.5E+02", 8), Ok(150.0));
//! assert_eq!(real("  12345", 8), Ok(0.00012345));
//! assert_eq!(real("-2.5-3", 8), Ok(-0.0025));
//! ```

/// Columns `first..=last` (1-based) of `line`, padded with blanks.
pub fn columns(line: &[char], first: usize, last: usize) -> String {
    (first..=last)
        .map(|c| line.get(c - 1).copied().unwrap_or(' '))
        .collect()
}

/// The field with leading blanks removed and the remaining blanks turned into zeros.
fn blanks_to_zeros(field: &str) -> String {
    field
        .trim_start_matches(' ')
        .chars()
        .map(|c| if c == ' ' { '0' } else { c })
        .collect()
}

fn hint(field: &str) -> &'static str {
    let t = field.trim_start_matches(' ');
    if !t.is_empty() && t.contains(' ') {
        " (FORTRAN IV reads embedded and trailing blanks as zeros: right-justify the number)"
    } else {
        ""
    }
}

/// Reads an `Iw` field (module docs); the error says why.
pub fn integer(field: &str) -> Result<i64, String> {
    let s = blanks_to_zeros(field);
    if s.is_empty() {
        return Ok(0);
    }
    let (neg, digits) = match s.as_bytes()[0] {
        b'+' => (false, &s[1..]),
        b'-' => (true, &s[1..]),
        _ => (false, &s[..]),
    };
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err(format!("is not an integer{}", hint(field)));
    }
    let v: i64 = digits
        .parse()
        .map_err(|_| format!("is out of range{}", hint(field)))?;
    Ok(if neg { -v } else { v })
}

/// Reads an `Ew.d` or `Fw.d` field with `d` implied fraction digits (module docs).
pub fn real(field: &str, d: usize) -> Result<f64, String> {
    let s = blanks_to_zeros(field);
    if s.is_empty() {
        return Ok(0.0);
    }
    let bad = || format!("is not a FORTRAN real number{}", hint(field));
    let b = s.as_bytes();
    let mut i = 0;
    let neg = match b[0] {
        b'+' => {
            i = 1;
            false
        }
        b'-' => {
            i = 1;
            true
        }
        _ => false,
    };
    let (mut int, mut frac, mut point) = (String::new(), String::new(), false);
    while i < b.len() {
        match b[i] {
            c if c.is_ascii_digit() => {
                if point {
                    frac.push(c as char)
                } else {
                    int.push(c as char)
                }
            }
            b'.' if !point => point = true,
            _ => break,
        }
        i += 1;
    }
    if int.is_empty() && frac.is_empty() {
        return Err(bad());
    }
    // The exponent: E or D with an optional sign, or a bare sign.
    let mut exp: i64 = 0;
    if i < b.len() {
        let mut j = i;
        if matches!(b[j], b'E' | b'e' | b'D' | b'd') {
            j += 1;
        } else if !matches!(b[j], b'+' | b'-') {
            return Err(bad());
        }
        let rest = &s[j..];
        let (eneg, edig) = match rest.as_bytes().first() {
            Some(b'+') => (false, &rest[1..]),
            Some(b'-') => (true, &rest[1..]),
            _ => (false, rest),
        };
        if edig.is_empty() || !edig.bytes().all(|c| c.is_ascii_digit()) {
            return Err(bad());
        }
        // Long runs of zeros (trailing blanks) still fit: strip leading zeros first.
        let trimmed = edig.trim_start_matches('0');
        if trimmed.len() > 6 {
            return Err(format!("has an exponent out of range{}", hint(field)));
        }
        exp = if trimmed.is_empty() {
            0
        } else {
            trimmed.parse::<i64>().map_err(|_| bad())?
        };
        if eneg {
            exp = -exp;
        }
    }
    if !point {
        // Implied decimal point: the last d digits are the fraction.
        exp -= d as i64;
    }
    let text = format!(
        "{}{}.{}e{}",
        if neg { "-" } else { "" },
        if int.is_empty() { "0" } else { &int },
        if frac.is_empty() { "0" } else { &frac },
        exp
    );
    let v: f64 = text.parse().map_err(|_| bad())?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("overflows a double{}", hint(field)))
    }
}
