//! A [`FigureData`] in another unit system ([`UnitSystem`]: `in-psi-lbf`, the report's and the
//! figures' own; `mm-MPa-N`; `m-Pa-N`): every abscissa, ordinate, bar, B, R_o and computed
//! value multiplied by its quantity's factor, and every number written with a unit in the
//! titles, labels and notes rewritten in the new unit.
//!
//! An axis's quantity is read from its label's bracket: `[in]` a length (× in/length unit),
//! `[psi]` a stress (× psi/stress unit), `[µin]` a small length (µin → µm in the metric
//! systems, × 0.0254); B, R_o and the computed values are abscissae and follow the x axis. In
//! text, a number (decimal or fraction) followed by `in`, `µin`, `psi` or `lb` (and the first
//! number of `x ± e unit` and `x and y unit`) is converted; other numbers (ratios, r/A) are left
//! as they are.
//!
//! # Accuracy
//!
//! Multiplication by the exact factors of [`UnitSystem`] (one rounding per number):
//! `tests/figures/units.rs` checks that the mm CSV equals the inch CSV × 25.4 and the stresses
//! × the psi → MPa factor built from the definitions of the inch and pound-force, to 1e-12.
//!
//! # Cost
//!
//! Negligible beside the figures' solves (`boltzone figures --units mm-MPa-N` prints each
//! figure's time).
//!
//! ```
//! use boltzone::figures::{compute, units::in_units, FiguresParams};
//! use boltzone::scene::UnitSystem;
//! let fig = compute("20", &FiguresParams::default())?; // the load profiles: no solve
//! let mm = in_units(&fig, UnitSystem::MmMpaN);
//! assert_eq!(mm.x_label, "r [mm]");
//! assert!((mm.curves[0].x[0] - 25.4 * fig.curves[0].x[0]).abs() < 1e-12);
//! # Ok::<(), boltzone::figures::FigureError>(())
//! ```

use super::FigureData;
use crate::units::UnitSystem;
use crate::units::INCH;

/// Factor and new symbol of the unit `symbol` (`in`, `µin`, `psi`, `lb`) in `units`.
fn unit(symbol: &str, units: UnitSystem) -> Option<(f64, String)> {
    let (l, s, f) = units.symbols();
    let inch = UnitSystem::InPsiLbf;
    let metric = units != inch;
    Some(match symbol {
        "in" => (inch.length() / units.length(), l.to_string()),
        "µin" if metric => (INCH, "µm".to_string()),
        "µin" => (1.0, "µin".to_string()),
        "psi" => (inch.stress() / units.stress(), s.to_string()),
        "lb" | "lbf" => (inch.force() / units.force(), f.to_string()),
        _ => return None,
    })
}

/// `x` with six significant digits, trailing zeros dropped (and −0 written 0): for labels
/// and axis ticks.
pub fn number(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return format!("{x}");
    }
    let digits = (5 - x.abs().log10().floor() as i32).clamp(0, 15) as usize;
    let s = format!("{x:.digits$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        &s
    };
    if s == "-0" {
        "0".into()
    } else {
        s.to_string()
    }
}

/// The number a word writes: a decimal or a fraction `p/q` (the nominal "1/4 in").
fn value(word: &str) -> Option<f64> {
    if let Ok(x) = word.parse::<f64>() {
        return Some(x);
    }
    let (p, q) = word.split_once('/')?;
    Some(p.parse::<f64>().ok()? / q.parse::<f64>().ok()?)
}

/// `text` with every "number unit" (and "number ± number unit") in `units`.
pub fn text_in(text: &str, units: UnitSystem) -> String {
    let mut words: Vec<String> = text.split(' ').map(str::to_string).collect();
    for j in 1..words.len() {
        let core = words[j].trim_end_matches([',', ';', ')', '.', ':']);
        let tail = words[j][core.len()..].to_string();
        let Some((factor, symbol)) = unit(core, units) else {
            continue;
        };
        let Some(x) = value(&words[j - 1]) else {
            continue;
        };
        words[j - 1] = number(x * factor);
        // "x ± e unit" and "x and y unit": the first number has the same unit
        if j >= 3 && (words[j - 2] == "±" || words[j - 2] == "and") {
            if let Some(v) = value(&words[j - 3]) {
                words[j - 3] = number(v * factor);
            }
        }
        words[j] = format!("{symbol}{tail}");
    }
    words.join(" ")
}

/// The factor of an axis labelled `label` (its `[unit]`) and the label in `units`.
fn axis(label: &str, units: UnitSystem) -> (f64, String) {
    let bracket = label
        .split_once('[')
        .and_then(|(_, rest)| rest.split_once(']'))
        .map(|(u, _)| u);
    match bracket.and_then(|u| Some((u, unit(u, units)?))) {
        Some((u, (factor, symbol))) => (
            factor,
            text_in(
                &label.replacen(&format!("[{u}]"), &format!("[{symbol}]"), 1),
                units,
            ),
        ),
        None => (1.0, text_in(label, units)),
    }
}

/// `fig` in `units` (a copy; `in-psi-lbf` returns it unchanged).
pub fn in_units(fig: &FigureData, units: UnitSystem) -> FigureData {
    let mut out = fig.clone();
    if units == UnitSystem::InPsiLbf {
        return out;
    }
    let (fx, x_label) = axis(&fig.x_label, units);
    let (fy, y_label) = axis(&fig.y_label, units);
    out.x_label = x_label;
    out.y_label = y_label;
    out.title = text_in(&fig.title, units);
    out.note = text_in(&fig.note, units);
    out.report_values = text_in(&fig.report_values, units);
    for c in &mut out.curves {
        c.x.iter_mut().for_each(|x| *x *= fx);
        c.y.iter_mut().for_each(|y| *y *= fy);
        // B and R_o are abscissae (r/D on the slab's axis: no unit, unchanged)
        c.b *= fx;
        if let Some(v) = &mut c.r_o {
            v.value *= fx;
            v.error *= fx;
        }
        // "what: R_o = x ± e in" rebuilt from the converted value (not the label's rounding)
        c.label = match (c.r_o, c.label.split_once(": R_o = ")) {
            (Some(v), Some((what, rest))) if rest.ends_with(" in") => format!(
                "{}: R_o = {} ± {:.1e} {}",
                text_in(what, units),
                number(v.value),
                v.error,
                units.symbols().0
            ),
            _ => text_in(&c.label, units),
        };
    }
    for s in &mut out.points {
        s.label = text_in(&s.label, units);
        for p in &mut s.points {
            p.x *= fx;
            p.y *= fy;
            p.x_bar = (p.x_bar.0 * fx, p.x_bar.1 * fx);
            p.y_bar = (p.y_bar.0 * fy, p.y_bar.1 * fy);
        }
    }
    for v in &mut out.values {
        v.value *= fx;
        v.error *= fx;
    }
    out
}
