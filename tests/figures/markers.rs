//! Every figure's markers are at the values the report prints: read here from `reference/`
//! (the transcription of the report's Tables 1 and 2, the Chapter V table and the numbers of
//! its text, each checked against the report's text) with this file's own CSV parser, never
//! from the figure code's constants; figures for which the report prints nothing say so.

use super::gallery::{figure, manifest, points, reference};

/// Hole radius of Table 1's plates, in (Chapter IV.A: A = 0.1 in).
const A1: f64 = 0.1;
/// Hole radius of the test plates, in (Chapter III: hole 0.257 in in diameter).
const A2: f64 = 0.257 / 2.0;

/// `got` is `want` up to the one rounding of a product or quotient (and none of the CSV's
/// shortest round-trip printing).
fn same(got: f64, want: f64, what: &str) {
    assert!(
        (got - want).abs() <= 2.0 * f64::EPSILON * want.abs(),
        "{what}: {got} vs the report's {want}"
    );
}

fn num(s: &str) -> f64 {
    s.parse()
        .unwrap_or_else(|_| panic!("'{s}' is not a number"))
}

/// Table 2's row of `case` as numbers (empty fields NaN).
fn table2(case: u32) -> Vec<f64> {
    reference("table2_experiments.csv")
        .into_iter()
        .find(|r| r[0] == case.to_string())
        .unwrap()
        .iter()
        .take(14) // the 15th is the footnote marker
        .map(|f| if f.is_empty() { f64::NAN } else { num(f) })
        .collect()
}

/// The text value `key` of `reference/text_values.csv`: (value, r).
fn text(key: &str) -> (f64, f64) {
    let row = reference("text_values.csv")
        .into_iter()
        .find(|r| r[0] == key)
        .unwrap_or_else(|| panic!("{key} missing"));
    let r = if row[4].is_empty() {
        f64::NAN
    } else {
        num(&row[4])
    };
    (num(&row[2]), r)
}

/// The source of point series `k` of figure `id` in the manifest.
fn source(id: &str, k: usize) -> String {
    figure(id)["points"][k]["source"]
        .as_str()
        .unwrap()
        .to_string()
}

/// Figs. 12–17: the triangles are Table 1's R_o/A (single plate for 12–14, two plates for
/// 15–17) of the rows A/D = 1, 0.75, 0.5, times A, on the axis.
#[test]
fn figs12_to_17_are_table1() {
    let table = reference("table1_separation_radius.csv");
    for (fig, a_over_d, column) in [
        ("fig12", "1", 2),
        ("fig13", ".75", 2),
        ("fig14", ".5", 2),
        ("fig15", "1", 3),
        ("fig16", ".75", 3),
        ("fig17", ".5", 3),
    ] {
        let want: Vec<f64> = table
            .iter()
            .filter(|r| num(&r[0]) == num(a_over_d))
            .map(|r| A1 * num(&r[column]))
            .collect();
        let got = points(fig, 0);
        assert_eq!((want.len(), got.len()), (4, 4), "{fig}");
        for (g, w) in got.iter().zip(&want) {
            same(g[0], *w, fig);
            assert_eq!(g[1], 0.0);
        }
        assert_eq!(source(fig, 0), "report");
    }
}

/// The points of Table 2's `case` on a figure: series `first` the report's computed 2R_o / 2 on
/// the axis, then the rubbing and (where done) autoradiographic ranges halved (average, min,
/// max), measured.
fn table2_markers(fig: &str, case: u32, first: usize) {
    let row = table2(case);
    let computed = points(fig, first);
    same(computed[0][0], row[11] / 2.0, &format!("{fig} computed"));
    assert_eq!(computed[0][1], 0.0);
    assert_eq!(source(fig, first), "report");
    let mut ranges = vec![(5, "rubbing")];
    if !row[8].is_nan() {
        ranges.push((8, "autoradiographic"));
    }
    for (k, (col, what)) in ranges.iter().enumerate() {
        let p = points(fig, first + 1 + k)[0];
        let what = format!("{fig} case {case} {what}");
        same(p[0], row[col + 2] / 2.0, &format!("{what} average"));
        same(p[2], row[*col] / 2.0, &format!("{what} min"));
        same(p[3], row[col + 1] / 2.0, &format!("{what} max"));
        assert!(p[1] < 0.0, "{what}: ranges sit below the axis");
        assert_eq!(source(fig, first + 1 + k), "measured");
    }
    let series = figure(fig)["points"].as_array().unwrap().len();
    assert!(series >= first + 1 + ranges.len(), "{fig}");
}

/// Figs. 18, 23, 24, 26, 27: Table 2's cases 4, 3, 2, 1 and 5 (the 1/4, 3/16, 1/8, 1/16 and
/// 1/8-on-1/4 in pairs): the report's computed R_o and the tests' ranges.
#[test]
fn pair_figures_are_table2() {
    for (fig, case) in [
        ("fig18", 4),
        ("fig23", 3),
        ("fig24", 2),
        ("fig26", 1),
        ("fig27", 5),
    ] {
        table2_markers(fig, case, 0);
    }
    // case 5 has no autoradiographic test
    assert_eq!(figure("fig27")["points"].as_array().unwrap().len(), 2);
}

/// Figs. 18, 19, 21: the Chapter IV.B text's r/A = 2.73–2.93 (two plates, every loading of the
/// 1/4 in pair) as a range and 3.5 (single plate) as a point, times the test plates' A.
#[test]
fn load_variants_are_the_chapter4_text() {
    let (lo, _) = text("variants_two_r_over_a_min");
    let (hi, _) = text("variants_two_r_over_a_max");
    let (single, _) = text("single_r_over_a");
    assert_eq!((lo, hi, single), (2.73, 2.93, 3.5), "as printed");
    for (fig, first) in [("fig18", 3), ("fig19", 0), ("fig21", 0)] {
        let range = points(fig, first)[0];
        same(range[2], lo * A2, fig);
        same(range[3], hi * A2, fig);
        let p = points(fig, first + 1)[0];
        same(p[0], single * A2, fig);
        assert_eq!(p[1], 0.0);
        assert_eq!(source(fig, first), "report");
        assert_eq!(source(fig, first + 1), "report");
    }
}

/// Fig. 22: the report's 50 µin under each nut (Fig. 21's loading) as a bar from A to B at
/// w = −50 µin (toward the interface).
#[test]
fn fig22_marker_is_the_nut_displacement() {
    let (w, _) = text("nut_displacement");
    assert_eq!(w, 50.0, "as printed");
    let p = points("fig22", 0)[0];
    assert_eq!((p[1], p[4], p[5]), (-w, -w, -w));
    same(p[2], A2, "A");
    same(p[3], table2(4)[4] / 2.0, "B");
}

/// Fig. 25: the report prints no gap for its 1/8 in pair; Chapter VI prints the 1/4 in pair's
/// (98.6 µin at r = 2 in, 3 µin at 1/32 in beyond R_o = 0.35 in), drawn with that pair's gap.
#[test]
fn fig25_markers_are_chapter6_gaps() {
    let p = points("fig25", 0);
    for (k, key) in ["gap_near_separation", "gap_outer_radius"]
        .iter()
        .enumerate()
    {
        let (g, r) = text(key);
        assert_eq!((p[k][0], p[k][1]), (r, g), "{key}");
    }
    assert_eq!(text("gap_outer_radius"), (98.6, 2.0), "as printed");
    assert_eq!(text("gap_near_separation"), (3.0, 0.35 + 1.0 / 32.0));
    let (r_o, _) = text("separation_radius_quarter");
    assert_eq!(points("fig25", 1)[0][0], r_o);
    // Chapter VI's R_o of the 1/4 in pair is Table 2's computed 2R_o / 2
    same(r_o, table2(4)[11] / 2.0, "Ch. VI R_o vs Table 2");
    let fig = figure("fig25");
    let note = fig["report_values"].as_str().unwrap();
    assert!(note.contains("no gap for Fig. 25's 1/8 in pair"), "{note}");
    assert!(fig["curves"][2]["label"]
        .as_str()
        .unwrap()
        .starts_with("1/4 in pair (case 4)"));
}

/// Fig. 28: against our 2R_o, the report's computed 2R_o (Table 2) and the tests' ranges
/// (average, bars min–max) of all seven cases (autoradiographic: cases 1–4).
#[test]
fn fig28_is_table2() {
    let rows: Vec<Vec<f64>> = (1..=7).map(table2).collect();
    let report = points("fig28", 1);
    let rubbing = points("fig28", 2);
    let autorad = points("fig28", 3);
    assert_eq!((report.len(), rubbing.len(), autorad.len()), (7, 7, 4));
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(report[k][1], row[11]);
        assert_eq!(
            (rubbing[k][1], rubbing[k][4], rubbing[k][5]),
            (row[7], row[5], row[6])
        );
        if k < 4 {
            assert_eq!(
                (autorad[k][1], autorad[k][4], autorad[k][5]),
                (row[10], row[8], row[9])
            );
        }
    }
    assert_eq!(source("fig28", 1), "report");
    assert_eq!(source("fig28", 2), "measured");
}

/// Fig. 29: the outer radii of Chapter V's contact rings (the last is the report's edge of the
/// lap joint's contact zone).
#[test]
fn fig29_markers_are_the_chapter5_rings() {
    let want: Vec<f64> = reference("chapter5_interface.csv")
        .iter()
        .map(|r| num(&r[0]))
        .collect();
    let got: Vec<f64> = points("fig29", 0).iter().map(|p| p[0]).collect();
    assert_eq!(got, want);
}

/// Every figure says what the report prints for it; exactly those without a report or measured
/// series (Fig. 20's load profiles and the slab, not a figure of the report) say it prints
/// nothing, in the manifest and in the CSV.
#[test]
fn figures_without_report_values_say_so() {
    let none = "The report prints no value for this figure";
    let mut silent = vec![];
    for fig in manifest()["figures"].as_array().unwrap() {
        let id = fig["id"].as_str().unwrap();
        let note = fig["report_values"].as_str().unwrap();
        let from_report = fig["points"]
            .as_array()
            .unwrap()
            .iter()
            .any(|s| s["source"] != "computed");
        assert_eq!(note.starts_with(none), !from_report, "{id}: {note}");
        if !from_report {
            silent.push(id.to_string());
        }
        let csv = std::fs::read_to_string(super::gallery::dir().join(format!("{id}.csv"))).unwrap();
        assert!(
            csv.contains(&format!("# report values: {note}")),
            "{id}.csv"
        );
    }
    assert_eq!(silent, ["fig20", "slab"]);
}
