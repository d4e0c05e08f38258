//! The joint diagram of a preloaded bolted joint (VDI 2230 Part 1 (2015), section 3.4; Shigley,
//! *Mechanical Engineering Design*, section 8-7): the bolt's force against its elongation f,
//! F = f/δ_S, and the clamped parts' against their shortening read back from the bolt's, both
//! meeting at the preload F_M, at f_SM = δ_S F_M. The parts' line falls to zero at
//! f_SM + f_PM = (δ_S + δ_P) F_M, where an axial load would separate them. An axial load F_A at
//! the head and the nut (load introduction n = 1) raises the bolt's force by Φ F_A, with
//! Φ = δ_P/(δ_S + δ_P), and unloads the parts by (1 − Φ) F_A.
//!
//! # Accuracy
//!
//! Two straight lines through the answer's own F_M, δ_S and δ_P: `tests/joint/diagram.rs`
//! reads them back from the figure of `two --bolt M10 … --plot` against its JSON.
//!
//! # Cost
//!
//! Microseconds, before it is drawn.
//!
//! ```
//! use boltzone::plot::joint_diagram::JointDiagram;
//! let d = JointDiagram { preload: 24e3, bolt_compliance: 2.9e-6, member_compliance: 6.6e-7, length: "mm", force: "N" };
//! let fig = d.figure();
//! let bolt = &fig.curves[0].points;
//! assert_eq!(bolt[0], (0.0, 0.0));
//! let (f_sm, f_m) = fig.curves[1].points[0];
//! assert!((f_sm - 2.9e-6 * 24e3).abs() < 1e-12 && f_m == 24e3);
//! ```

use super::{Curve, CurveFigure, Marker, PALETTE};

/// The numbers of a joint diagram, in one unit system.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointDiagram<'a> {
    /// The preload F_M (force unit).
    pub preload: f64,
    /// The bolt's compliance δ_S (length per force).
    pub bolt_compliance: f64,
    /// The clamped parts' compliance δ_P (length per force).
    pub member_compliance: f64,
    /// The length unit's symbol.
    pub length: &'a str,
    /// The force unit's symbol.
    pub force: &'a str,
}

impl JointDiagram<'_> {
    /// The load factor Φ = δ_P/(δ_S + δ_P) (load introduction n = 1).
    pub fn load_factor(&self) -> f64 {
        self.member_compliance / (self.bolt_compliance + self.member_compliance)
    }

    /// The figure: the bolt's line (to 1.5 F_M), the parts' line from F_M down to zero, and
    /// markers at f_SM and f_SM + f_PM.
    pub fn figure(&self) -> CurveFigure {
        let (f_m, l, u) = (self.preload, self.length, self.force);
        let f_sm = self.bolt_compliance * f_m;
        let f_open = f_sm + self.member_compliance * f_m;
        let top = 1.5 * f_m;
        CurveFigure {
            title: format!(
                "Joint diagram: F_M = {f_m:.5e} {u}, Φ = δ_P/(δ_S + δ_P) = {:.5}",
                self.load_factor()
            ),
            x_label: format!("elongation of the bolt, shortening of the plates [{l}]"),
            y_label: format!("force [{u}]"),
            curves: vec![
                Curve {
                    label: format!(
                        "bolt: F = f/δ_S, δ_S = {:.4e} {l}/{u}",
                        self.bolt_compliance
                    ),
                    points: vec![(0.0, 0.0), (top * self.bolt_compliance, top)],
                    color: PALETTE[5],
                },
                Curve {
                    label: format!(
                        "plates: F = F_M − (f − f_SM)/δ_P, δ_P = {:.4e} {l}/{u}",
                        self.member_compliance
                    ),
                    points: vec![(f_sm, f_m), (f_open, 0.0)],
                    color: PALETTE[6],
                },
            ],
            markers: vec![
                Marker {
                    label: format!("f_SM = δ_S F_M = {f_sm:.4e} {l}"),
                    x: f_sm,
                    color: PALETTE[1],
                },
                Marker {
                    label: format!("f_SM + f_PM = {f_open:.4e} {l} (the plates open)"),
                    x: f_open,
                    color: PALETTE[3],
                },
            ],
            x_range: (0.0, 1.1 * f_open.max(top * self.bolt_compliance)),
            y_range: (0.0, 1.9 * f_m),
        }
    }
}
