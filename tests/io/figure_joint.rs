//! The figures of `two --plot FILE` beside FILE — FILE-gap and FILE-deformed — and the HTML
//! calculation report, read back from the SVG: markers at the radii computed (located by a
//! pixel scale calibrated on two other markers whose radii are closed forms: B and the 45° cone's
//! B + D), the deformed drawing at equal scales in r and z with its R_o marker, the gap curve
//! zero inside the contact and positive beyond R_o (against the CSV of the same run), and the
//! HTML self-contained. Pixel positions are integers in plotters' SVG: 1 px is the resolution.

use super::py::{csv_columns, temp_dir};
use super::svg_util::{marker_x, polylines, texts};
use crate::common::{boltzone, json_of};

const R_O: &str = "#D55E00";
const B: &str = "#E69F00";
const CONE45: &str = "#0072B2";
const UNDEFORMED: &str = "#787878";

#[test]
fn gap_and_deformed_figures_mark_the_computed_radii() {
    let dir = temp_dir("fig-joint");
    let (svg, csv, html) = (dir.join("p.svg"), dir.join("c.csv"), dir.join("r.html"));
    let (a, b, d) = (0.1f64, 0.31f64, 0.1f64);
    let line = "two --a 0.1 --b 0.31 --d 0.1 --c 1.54 --tol 1e-3 --json";
    let mut args: Vec<&str> = line.split_whitespace().collect();
    let files = [
        svg.to_str().unwrap(),
        csv.to_str().unwrap(),
        html.to_str().unwrap(),
    ];
    args.extend([
        "--plot", files[0], "--curve", files[1], "--report", files[2],
    ]);
    let v = json_of(&boltzone(&args));
    let r_o = v["r_o"].as_f64().unwrap();
    // pressure and gap figures: R_o's marker where the scale set by B and B + D puts it
    for name in ["p.svg", "p-gap.svg"] {
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        let (xb, x45) = (marker_x(&text, B), marker_x(&text, CONE45));
        let scale = (x45 - xb) / d;
        let want = xb + (r_o - b) * scale;
        let got = marker_x(&text, R_O);
        assert!(
            (got - want).abs() <= 1.0,
            "{name}: R_o marker at {got} px, want {want}"
        );
    }
    // the gap: zero in contact, opening beyond R_o (the CSV of the same run)
    let (_, rows) = csv_columns(&std::fs::read_to_string(&csv).unwrap());
    let tol = 1e-3 * r_o;
    assert!(rows
        .iter()
        .filter(|r| r[0] < r_o - tol)
        .all(|r| r[2].abs() < 1e-15));
    assert!(rows.iter().filter(|r| r[0] > r_o + tol).all(|r| r[2] > 0.0));
    let gap_svg = std::fs::read_to_string(dir.join("p-gap.svg")).unwrap();
    assert!(texts(&gap_svg).iter().any(|t| t == "g [in]"));
    // the deformed joint: the undeformed outline spans A..cut in r and −D..D in z at one scale
    let text = std::fs::read_to_string(dir.join("p-deformed.svg")).unwrap();
    let title = texts(&text)
        .into_iter()
        .find(|t| t.starts_with("Deformed joint"))
        .unwrap();
    let cut: f64 = title
        .split("cut at r = ")
        .nth(1)
        .unwrap()
        .trim_end_matches(" in")
        .parse()
        .unwrap();
    let mut pts: Vec<(f64, f64)> = polylines(&text, UNDEFORMED).into_iter().flatten().collect();
    // the legend's dashed sample sits above the drawing, beyond the largest gap in y
    let mut ys: Vec<f64> = pts.iter().map(|p| p.1).collect();
    ys.sort_by(f64::total_cmp);
    ys.dedup();
    let split = ys
        .windows(2)
        .max_by(|a, b| (a[1] - a[0]).total_cmp(&(b[1] - b[0])))
        .unwrap()[1];
    pts.retain(|p| p.1 >= split);
    let ext = |f: fn(&(f64, f64)) -> f64| {
        pts.iter()
            .map(f)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            })
    };
    let ((x0, x1), (y0, y1)) = (ext(|p| p.0), ext(|p| p.1));
    let (sx, sy) = ((x1 - x0) / (cut - a), (y1 - y0) / (2.0 * d));
    // equal within the 1 px rounding at both ends of the shorter (z) span
    assert!(
        (sx - sy).abs() <= 2.0 / (2.0 * d),
        "px per in: r {sx}, z {sy}"
    );
    let got = marker_x(&text, R_O);
    let want = x0 + (r_o - a) * sx;
    assert!(
        (got - want).abs() <= 1.0,
        "deformed: R_o marker at {got} px, want {want}"
    );
    let k: f64 = title
        .split('×')
        .nth(1)
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .trim()
        .parse()
        .unwrap();
    assert!(k > 0.0);
    // the HTML report: self-contained, three inline figures, the results of the JSON
    let page = std::fs::read_to_string(&html).unwrap();
    assert_eq!(page.matches("<svg").count(), 3);
    for bad in ["src=", "href=", "<img", "<link", "<script"] {
        assert!(
            !page.contains(bad),
            "external reference '{bad}' in the HTML"
        );
    }
    let cone = 100.0 * (b + d - r_o) / r_o;
    for want in [
        format!(
            "<td>separation radius Rₒ</td><td>{r_o:.6} ± {:.1e} in</td>",
            v["r_o_error"].as_f64().unwrap()
        ),
        format!(
            "<td>45° cone</td><td>{:.4}</td><td>{cone:+.1} %</td>",
            b + d
        ),
        format!("boltzone {}", env!("CARGO_PKG_VERSION")),
        "<td>a</td><td>0.1</td><td>in</td>".to_string(),
    ] {
        assert!(page.contains(&want), "no '{want}' in the HTML");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn single_plot_writes_the_deformed_plate_and_a_bad_sibling_is_refused_first() {
    let dir = temp_dir("fig-single");
    let svg = dir.join("s.svg");
    let run = |line: &str, plot: &std::path::Path| {
        let mut args: Vec<&str> = line.split_whitespace().collect();
        args.extend(["--plot", plot.to_str().unwrap()]);
        boltzone(&args)
    };
    let out = run(
        "single --a 0.1 --b 0.31 --d 0.1 --c 1.54 --tol 1e-2 --json",
        &svg,
    );
    let r_o = json_of(&out)["r_o"].as_f64().unwrap();
    // σ_z against r: R_o's marker where the scale set by B and the 45° cone's B + D puts it
    let text = std::fs::read_to_string(&svg).unwrap();
    let (xb, x45) = (marker_x(&text, B), marker_x(&text, CONE45));
    let want = xb + (r_o - 0.31) * (x45 - xb) / 0.1;
    let got = marker_x(&text, R_O);
    assert!(
        (got - want).abs() <= 1.0,
        "single: R_o marker at {got} px, want {want}"
    );
    let text = std::fs::read_to_string(dir.join("s-deformed.svg")).unwrap();
    assert!(texts(&text)
        .iter()
        .any(|t| t.starts_with("Deformed single plate 2D thick")));
    // a directory where FILE-deformed goes: exit 2 naming --plot, nothing written
    let bad = dir.join("q.svg");
    std::fs::create_dir(dir.join("q-deformed.svg")).unwrap();
    let out = run("single --a 0.1 --b 0.31 --d 0.1", &bad);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--plot"));
    assert!(!bad.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
