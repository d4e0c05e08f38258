//! The separation radius R_o finer than one element, from the shape of a smooth separation.
//!
//! Where two elastic bodies separate smoothly (no corner in the load there), the contact pressure
//! vanishes like a square root and the gap opens like a power 3/2 (the Hertz-type receding edge):
//!
//! p(r) ≈ c_p √(R_o − r)  (r < R_o),   g(r) ≈ c_g (r − R_o)^{3/2}  (r > R_o).
//!
//! So g^{2/3} and p² are linear in r near R_o and both vanish at R_o. Given nodal values from a
//! discrete contact solution (the last contact node at index k, the first open node at k + 1),
//!
//! - the **gap estimator** draws the line g^{2/3} through the first two open nodes (k+1, k+2) and
//!   returns its zero; the line through nodes (k+2, k+3) gives a second value whose difference
//!   measures the neglected curvature (error O(h²) for a gap c_g s^{3/2}(1 + a s));
//! - the **pressure estimator** does the same with p² over the contact nodes (k−1, k−2), skipping
//!   the outermost contact node k whose tributary pressure averages across the edge.
//!
//! Nodal displacements are far more accurate than tributary pressures, so the gap estimate is
//! the answer and the others measure its uncertainty. Units: those of r.
//!
//! # Accuracy
//!
//! Exact on the pure asymptotic form, second order with curvature, the spread bounding the error
//! (`tests/contact/separation.rs`, synthetic data with a known R_o).
//!
//! # Cost
//!
//! O(points near the edge) per level.
//!
//! ```
//! use boltzone::contact::separation::{estimate, NodalInterface};
//! let r: Vec<f64> = (0..20).map(|i| 0.1 + 0.02 * i as f64).collect();
//! let r_o = 0.2713;
//! let p: Vec<f64> = r.iter().map(|&x| if x < r_o { (r_o - x).sqrt() } else { 0.0 }).collect();
//! let g: Vec<f64> = r.iter().map(|&x| if x > r_o { (x - r_o).powf(1.5) } else { 0.0 }).collect();
//! let e = estimate(&NodalInterface { radius: &r, pressure: &p, gap: &g }).ok_or("no separation")?;
//! assert!((e.r_o - r_o).abs() < 1e-14);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

/// Nodal values along the interface, ordered by increasing radius.
#[derive(Debug, Clone, Copy)]
pub struct NodalInterface<'a> {
    /// Node radii, strictly increasing.
    pub radius: &'a [f64],
    /// Interface pressure at the nodes (> 0 in contact, 0 where open).
    pub pressure: &'a [f64],
    /// Gap at the nodes (0 in contact, > 0 where open).
    pub gap: &'a [f64],
}

/// An estimate of R_o with its parts.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeparationEstimate {
    /// The estimate: zero of g^{2/3} through the first two open nodes.
    pub r_o: f64,
    /// The same from the next two open nodes (None if fewer than three open nodes).
    pub r_o_gap_far: Option<f64>,
    /// Zero of p² through the two contact nodes inside the outermost one (None if too few).
    pub r_o_pressure: Option<f64>,
    /// Radius of the outermost contact node.
    pub last_contact: f64,
    /// Radius of the first open node beyond it.
    pub first_open: f64,
    /// Spread of the estimators: max |other − r_o|; a one-mesh measure of the error.
    pub spread: f64,
}

/// Zero of the line through (x1, y1), (x2, y2) (None if the line is flat).
fn zero_of_line(x1: f64, y1: f64, x2: f64, y2: f64) -> Option<f64> {
    let dy = y2 - y1;
    (dy != 0.0)
        .then(|| x1 - y1 * (x2 - x1) / dy)
        .filter(|x| x.is_finite())
}

/// Estimates R_o from nodal values (module docs). Returns None when there is no contact node
/// followed by two open nodes (the contact zone is empty or reaches the end of the data).
pub fn estimate(data: &NodalInterface<'_>) -> Option<SeparationEstimate> {
    let n = data.radius.len();
    let (r, p, g) = (data.radius, data.pressure, data.gap);
    let k = (0..n).rev().find(|&i| p[i] > 0.0)?;
    if k + 2 >= n {
        return None;
    }
    let gg = |i: usize| g[i].max(0.0).powf(2.0 / 3.0);
    let r_o = zero_of_line(r[k + 1], gg(k + 1), r[k + 2], gg(k + 2))?;
    let r_o_gap_far = (k + 3 < n)
        .then(|| zero_of_line(r[k + 2], gg(k + 2), r[k + 3], gg(k + 3)))
        .flatten();
    let r_o_pressure = (k >= 2 && p[k - 1] > 0.0 && p[k - 2] > 0.0)
        .then(|| zero_of_line(r[k - 2], p[k - 2].powi(2), r[k - 1], p[k - 1].powi(2)))
        .flatten();
    let spread = [r_o_gap_far, r_o_pressure]
        .iter()
        .flatten()
        .map(|x| (x - r_o).abs())
        .fold(0.0, f64::max);
    Some(SeparationEstimate {
        r_o,
        r_o_gap_far,
        r_o_pressure,
        last_contact: r[k],
        first_open: r[k + 1],
        spread,
    })
}
