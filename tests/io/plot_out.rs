//! `two --plot FILE`, `single --plot FILE` and `two --report FILE.md`: the interface pressure
//! and midplane σ_z figures of the user's joint (SVG and PNG) and its calculation report. The markers' radii and the report's rules
//! are checked against the rules' closed forms (45° cone R = B + D, 30° cone R = B + D tan 30°,
//! computed here), the R_o marker and the report's results against the JSON of the same run,
//! the PNG against the size asked (its IHDR header); a bad extension exits 2 and writes
//! nothing. (The PNGs of this case and of Table 2's unequal pair were looked at: the pressure
//! falls to zero and σ_z crosses zero at the R_o marker, the legend leaves the curves
//! uncovered.)

use super::py::temp_dir;
use crate::common::{boltzone, json_of};

#[test]
fn plots_mark_r_o_and_the_rules() {
    let dir = temp_dir("plot");
    let (b, d) = (0.31f64, 0.1f64);
    // the two-plate interface pressure and the single plate's midplane σ_z
    for (cmd, y_label) in [("two", "p [psi]"), ("single", "σz [psi]")] {
        let (svg, png) = (
            dir.join(format!("{cmd}.svg")),
            dir.join(format!("{cmd}.png")),
        );
        let line = format!("{cmd} --a 0.1 --b 0.31 --d 0.1 --c 1.54 --tol 1e-3");
        let base: Vec<&str> = line.split_whitespace().collect();
        let mut args = base.clone();
        args.extend(["--json", "--plot", svg.to_str().unwrap()]);
        let v = json_of(&boltzone(&args));
        let text = std::fs::read_to_string(&svg).unwrap();
        for want in [
            format!("45° cone: R = {:.4} in", b + d),
            format!("30° cone: R = {:.4} in", b + d * 30f64.to_radians().tan()),
            format!("B = {b:.4} in"),
            format!("Rₒ = {:.4} ±", v["r_o"].as_f64().unwrap()),
            "r [in]".to_string(),
            y_label.to_string(),
        ] {
            assert!(text.contains(&want), "{cmd}: no '{want}' in the SVG");
        }
        let mut args = base.clone();
        args.extend(["--plot", png.to_str().unwrap()]);
        assert!(boltzone(&args).status.success());
        let bytes = std::fs::read(&png).unwrap();
        assert_eq!(&bytes[1..4], b"PNG");
        let be =
            |k: usize| u32::from_be_bytes([bytes[k], bytes[k + 1], bytes[k + 2], bytes[k + 3]]);
        assert_eq!((be(16), be(20)), (900, 600));
        // a bad extension: exit 2 naming the flag, before any work, nothing written
        let bad = dir.join("p.txt");
        let mut args = base.clone();
        args.extend(["--plot", bad.to_str().unwrap()]);
        let out = boltzone(&args);
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&out.stderr).contains("--plot"));
        assert!(!bad.exists());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn calculation_report_records_inputs_results_and_rules() {
    let dir = temp_dir("report");
    let (md, svg) = (dir.join("r.md"), dir.join("p.svg"));
    let line = "two --a 0.1 --b 0.31 --d 0.1 --c 1.54 --tol 1e-3 --json";
    let mut args: Vec<&str> = line.split_whitespace().collect();
    args.extend([
        "--plot",
        svg.to_str().unwrap(),
        "--report",
        md.to_str().unwrap(),
    ]);
    let v = json_of(&boltzone(&args));
    let text = std::fs::read_to_string(&md).unwrap();
    let r_o = v["r_o"].as_f64().unwrap();
    // the rules' closed forms (45°: B + D; 30°: B + D tan 30°) and their errors against R_o
    let (b, d) = (0.31f64, 0.1f64);
    let cone =
        |r: f64, name: &str| format!("| {name} | {r:.4} | {:+.1} % |", 100.0 * (r - r_o) / r_o);
    for want in [
        format!("boltzone {}", env!("CARGO_PKG_VERSION")),
        "units in-psi-lbf".to_string(),
        "| a | 0.1 | in |".to_string(),
        "| e | 28000000.0 | psi |".to_string(),
        "| tol | 0.001 |".to_string(),
        format!(
            "| separation radius Rₒ | {r_o:.6} ± {:.1e} in |",
            v["r_o_error"].as_f64().unwrap()
        ),
        format!(
            "| converged to the tolerance | {} |",
            if v["converged"] == true { "yes" } else { "no" }
        ),
        cone(b + d, "45° cone"),
        cone(b + d * 30f64.to_radians().tan(), "30° cone"),
        format!("]({})", svg.display()),
    ] {
        assert!(text.contains(&want), "no '{want}' in the report:\n{text}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
