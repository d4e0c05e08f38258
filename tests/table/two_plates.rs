//! `two --method auto` past the holed route's reach (B/D > 16): the far table answers, and its
//! bar holds against the finite elements, which share no code with it.

use crate::common::boltzone;

#[test]
fn auto_answers_wide_loads_by_the_far_table_within_the_fe_bar() {
    // B/D = 20 and 40: the FE at --tol 1e-5 (its estimates carry 2e-5 of R_o, so it ends
    // not converged, exit 3, with its bar)
    for b in ["2", "4"] {
        let args = |m: &str, tol: &str| -> serde_json::Value {
            let out = boltzone(&[
                "two", "--a", "0.1", "--b", b, "--d", "0.1", "--method", m, "--tol", tol, "--json",
            ]);
            serde_json::from_slice(&out.stdout).unwrap()
        };
        let t = args("auto", "1e-5");
        assert_eq!(t["method"], "table", "{t}");
        assert_eq!(t["converged"], true);
        let f = args("fem", "1e-5");
        let diff = (t["r_o"].as_f64().unwrap() - f["r_o"].as_f64().unwrap()).abs();
        let bars = t["r_o_error"].as_f64().unwrap() + f["r_o_error"].as_f64().unwrap();
        assert!(diff <= bars, "B = {b}: table {t} fe {f}");
    }
}
