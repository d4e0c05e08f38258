//! Plausibility warnings (`route::sanity`): the unit slips a user makes — a modulus typed in GPa
//! under `--units mm-MPa-N`, SI numbers run in the default inches — are named on stderr with the
//! flag or scene key and the likely slip, the exit code unchanged; `--strict` makes them exit 2;
//! a plausible joint (README's M8 example) gets none.

use std::process::{Command, Output};

fn boltzone(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_boltzone"))
        .args(args)
        .output()
        .unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

const M8: [&str; 17] = [
    "two", "--units", "mm-MPa-N", "--a", "4.5", "--b", "6.5", "--d", "6", "--c", "40", "--nu",
    "0.33", "--force", "10000", "--e", "70000",
];

#[test]
fn a_modulus_typed_in_gpa_is_named_and_strict_refuses_it() {
    let mut args = M8.to_vec();
    *args.last_mut().unwrap() = "70"; // 70 GPa typed where MPa is meant
                                      // the FE, whose deflection the thickness check reads (auto answers from the tables)
    args.extend(["--method", "fem"]);
    let o = boltzone(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("warning: --e = 70:") && err.contains("GPa"),
        "{err}"
    );
    // 10 kN on 70 MPa is no elastic metal either, and the plates deflect by far more than 1 %
    assert!(err.contains("warning: --force = 10000:"), "{err}");
    assert!(err.contains("% of the plate thickness"), "{err}");
    args.push("--strict");
    let o = boltzone(&args);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--e = 70:"), "{}", stderr(&o));
}

#[test]
fn si_numbers_in_the_default_inches_are_named() {
    let o = boltzone(&[
        "two", "--a", "0.0045", "--b", "0.0065", "--d", "0.006", "--e", "7e10", "--tol", "1e-2",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stderr(&o).contains("--units m-Pa-N"), "{}", stderr(&o));
}

#[test]
fn a_plausible_joint_gets_no_warning() {
    let o = boltzone(&M8);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("warning"), "{}", stderr(&o));
}

#[test]
fn a_scene_slip_names_the_key() {
    let dir = std::env::temp_dir().join(format!("boltzone-sanity-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("slip.toml");
    std::fs::write(
        &path,
        "units = \"mm-MPa-N\"\n[hole]\nradius = 4.5\n[load]\nouter_radius = 6.5\n\
         force = 10000.0\n[[plates]]\nthickness = 6\nmaterial = { E = 70, nu = 0.33 }\n",
    )
    .unwrap();
    let p = path.to_str().unwrap();
    let o = boltzone(&["solve", p]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("warning: plates[0].material:"),
        "{}",
        stderr(&o)
    );
    let o = boltzone(&["solve", p, "--strict"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    std::fs::remove_dir_all(&dir).unwrap();
}
