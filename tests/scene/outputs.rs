//! What a scene's outputs share with `two`'s: the friction zones and the curve's τ, s and state
//! columns equal `two --interface friction`'s on the same joint (bit for bit, in m-Pa-N where
//! both read the same numbers), `[outputs] plot` draws R_o and the 45° cone's radius B + D, and
//! `[outputs] report` equals `two --report`'s results and rules on the same joint.

use crate::common::{boltzone, json_of, succeeded};

/// The data rows of a CSV written by boltzone (header first, `#` provenance lines skipped).
fn data(csv: &str) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut lines = csv.lines();
    let head = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    let rows = lines
        .filter(|l| !l.starts_with('#') && !l.is_empty())
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    (head, rows)
}

fn temp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("boltzone-outputs-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn friction_zones_and_curve_columns_equal_two() {
    let dir = temp("friction");
    let (scene, scene_csv, two_csv) = (
        dir.join("pair.toml"),
        dir.join("scene.csv"),
        dir.join("two.csv"),
    );
    // Table 2 case 5's pair in SI, steel over aluminium, μ = 0.3
    std::fs::write(
        &scene,
        format!(
            "units = \"m-Pa-N\"\ntolerance = 5e-3\n[hole]\nradius = 0.003\n[load]\n\
             outer_radius = 0.005\nforce = 5000.0\n[[plates]]\nthickness = 0.003\n\
             material = {{ E = 2.0e11, nu = 0.3 }}\n[[plates]]\nthickness = 0.006\n\
             material = {{ E = 7.0e10, nu = 0.3 }}\n[joint]\nouter_radius = 0.05\n\
             interface = \"friction\"\nmu = 0.3\n[outputs]\ninterface_pressure = \"{}\"\n",
            scene_csv.display()
        ),
    )
    .unwrap();
    let solve = json_of(&boltzone(&["solve", scene.to_str().unwrap(), "--json"]));
    let two = json_of(&boltzone(&[
        "two",
        "--units",
        "m-Pa-N",
        "--a",
        "0.003",
        "--b",
        "0.005",
        "--d",
        "0.003",
        "--d2",
        "0.006",
        "--c",
        "0.05",
        "--e",
        "2.0e11",
        "--e2",
        "7.0e10",
        "--force",
        "5000",
        "--interface",
        "friction",
        "--mu",
        "0.3",
        "--tol",
        "5e-3",
        "--method",
        "fem",
        "--json",
        "--curve",
        two_csv.to_str().unwrap(),
    ]));
    for key in ["r_o", "mu", "stick_zones", "slip_zones", "max_slip"] {
        assert_eq!(solve[key], two[key], "{key}");
    }
    assert!(
        !solve["slip_zones"].as_array().unwrap().is_empty(),
        "{solve}"
    );
    let (sh, srows) = data(&std::fs::read_to_string(&scene_csv).unwrap());
    let (th, trows) = data(&std::fs::read_to_string(&two_csv).unwrap());
    assert_eq!(sh, th);
    assert_eq!(
        sh,
        ["r [m]", "p [Pa]", "g [m]", "tau [Pa]", "s [m]", "state [-]"]
    );
    assert_eq!(srows.len(), trows.len());
    for (a, b) in srows.iter().zip(&trows) {
        for (x, y) in a.iter().zip(b) {
            // both printed to 11 significant digits from the same numbers
            assert!(
                (x - y).abs() <= 1e-10 * x.abs().max(y.abs()),
                "{a:?} vs {b:?}"
            );
        }
    }
    // Coulomb's law at every closed node (independent of the zones' bookkeeping): inside the
    // cone where sticking, on it where slipping
    let p_max = srows.iter().fold(0.0f64, |m, r| m.max(r[1]));
    for r in &srows {
        match r[5] as u8 {
            1 => assert!(r[3].abs() <= 0.3 * r[1] + 1e-9 * p_max, "{r:?}"),
            2 => assert!((r[3].abs() - 0.3 * r[1]).abs() <= 1e-9 * p_max, "{r:?}"),
            _ => {}
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `solve` of the scene `text` (written to `dir` as bad`i`.toml, run there) exits 2 naming `key`.
fn refused(dir: &std::path::Path, i: usize, text: &str, key: &str) {
    let scene = dir.join(format!("bad{i}.toml"));
    std::fs::write(&scene, text).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(["solve", scene.to_str().unwrap()])
        .current_dir(dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{i}: {err}");
    assert!(err.contains(key), "{i}: {err}");
}

#[test]
fn plot_marks_r_o_and_the_cone_and_is_refused_where_it_cannot_be_drawn() {
    let dir = temp("plot");
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/table1_row1.toml"),
    )
    .unwrap();
    for method in ["fem", "hankel"] {
        let plot = dir.join(format!("p-{method}.svg"));
        let scene = dir.join(format!("row1-{method}.toml"));
        std::fs::write(
            &scene,
            text.replace("method = \"auto\"", &format!("method = \"{method}\""))
                .replace(
                    "r_o = true",
                    &format!("r_o = true\nplot = \"{}\"", plot.display()),
                ),
        )
        .unwrap();
        let out = boltzone(&["solve", scene.to_str().unwrap(), "--json"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v = json_of(&out);
        let svg = std::fs::read_to_string(&plot).unwrap();
        let r_o = v["r_o"].as_f64().unwrap();
        assert!(
            svg.contains(&format!("{r_o:.4}")),
            "{method}: R_o {r_o} not marked"
        );
        // the 45° cone: R = B + D = 0.31 + 0.1 in
        assert!(
            svg.contains(&format!("{:.4}", 0.31 + 0.1)),
            "{method}: cone not marked"
        );
        assert_eq!(
            dir.join(format!("p-{method}-gap.svg")).exists(),
            method == "fem"
        );
    }
    let bad = [
        (
            text.replace("r_o = true", "r_o = true\nplot = \"p.pdf\""),
            "outputs.plot",
        ),
        (
            text.replace("model = \"two-plate\"", "model = \"single-plate\"")
                .replace("r_o = true", "r_o = true\nplot = \"p.svg\""),
            "outputs.plot",
        ),
        (
            format!(
                "{}\n[sweep]\n\"load.outer_radius\" = [0.3, 0.4]\n",
                text.replace("r_o = true", "r_o = true\nplot = \"p.svg\"")
            ),
            "outputs.plot",
        ),
    ];
    for (i, (scene_text, key)) in bad.iter().enumerate() {
        refused(&dir, i, scene_text, key);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The rows of the Markdown table under `heading` in `md` (header and separator skipped).
fn table_under<'a>(md: &'a str, heading: &str) -> Vec<&'a str> {
    md.split(heading)
        .nth(1)
        .unwrap_or("")
        .lines()
        .skip_while(|l| !l.starts_with('|'))
        .take_while(|l| l.starts_with('|'))
        .skip(2)
        .collect()
}

#[test]
fn scene_report_equals_two_report_and_is_refused_where_it_cannot_be_written() {
    let dir = temp("report");
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/table1_row1.toml"),
    )
    .unwrap()
    .replace("method = \"auto\"", "method = \"fem\"");
    let (md, plot, html) = (dir.join("r.md"), dir.join("p.svg"), dir.join("r.html"));
    let outputs = format!(
        "r_o = true\nplot = \"{}\"\nreport = \"{}\"",
        plot.display(),
        md.display()
    );
    let scene = dir.join("row1.toml");
    std::fs::write(&scene, text.replace("r_o = true", &outputs)).unwrap();
    let v = json_of(&boltzone(&["solve", scene.to_str().unwrap(), "--json"]));
    let two_md = dir.join("two.md");
    let out = boltzone(&[
        "two",
        "--method",
        "fem",
        "--a",
        "0.1",
        "--b",
        "0.31",
        "--d",
        "0.1",
        "--c",
        "1.54",
        "--p",
        "1000",
        "--report",
        two_md.to_str().unwrap(),
    ]);
    succeeded(&out);
    let (scene_md, two_md) = (
        std::fs::read_to_string(&md).unwrap(),
        std::fs::read_to_string(&two_md).unwrap(),
    );
    // R_o ± bar as the JSON says, and the same results and rules as `two`'s report
    let r_o = v["r_o"].as_f64().unwrap();
    assert!(scene_md.contains(&format!(
        "{r_o:.6} ± {:.1e} in",
        v["r_o_error"].as_f64().unwrap()
    )));
    for heading in ["## Results", "## Rules of thumb"] {
        let rows = table_under(&scene_md, heading);
        assert!(rows.len() >= 3, "{heading}: {scene_md}");
        assert_eq!(rows, table_under(&two_md, heading), "{heading}");
    }
    // the scene's keys with their units; the plot's figures linked
    assert!(
        scene_md.contains("| hole.radius | 0.1 | in |"),
        "{scene_md}"
    );
    assert!(
        scene_md.contains(&format!("]({})", plot.display())),
        "{scene_md}"
    );
    assert!(scene_md.contains("-gap.svg)"), "{scene_md}");
    // HTML without a plot: self-contained, both interface figures inlined
    let scene = dir.join("row1-html.toml");
    let outputs = format!("r_o = true\nreport = \"{}\"", html.display());
    std::fs::write(&scene, text.replace("r_o = true", &outputs)).unwrap();
    let out = boltzone(&["solve", scene.to_str().unwrap()]);
    succeeded(&out);
    let page = std::fs::read_to_string(&html).unwrap();
    assert_eq!(page.matches("<svg").count(), 2, "pressure and gap");
    assert!(!page.contains("src=") && !page.contains("href="));
    // refused: a wrong extension, a single plate, a sweep
    let with = |r: &str| text.replace("r_o = true", &format!("r_o = true\nreport = \"{r}\""));
    let bad = [
        with("bad.txt"),
        with("bad.md").replace("model = \"two-plate\"", "model = \"single-plate\""),
        format!(
            "{}\n[sweep]\n\"load.outer_radius\" = [0.3, 0.4]\n",
            with("bad.md")
        ),
    ];
    for (i, scene_text) in bad.iter().enumerate() {
        refused(&dir, i, scene_text, "outputs.report");
        assert!(!dir.join("bad.md").exists() && !dir.join("bad.txt").exists());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
