//! Corner enrichment of the hole correction: exact homogeneous fields of the plate r ≥ A that
//! carry the Williams singularity of the 90° corner (A, ±D).
//!
//! **Why.** Where the free hole wall meets a loaded face the exact correction contains terms
//! ρ^λ (stresses ρ^(λ−1)), λ the free–free 90° wedge exponents, roots of sin(λπ/2) = ∓λ
//! (Williams, *J. Appl. Mech.* 19 (1952) 526): λ₁ = 2.7396 + 1.1190i (−), λ₂ = 4.8083 + 1.4639i
//! (+), λ₃ = 6.8451 + 1.6816i (−), … ([`corner_exponents`]). Smooth Papkovich–Fadle modes
//! resolve them only down to a height ~D/N, hence the N^(−1.74) residual without enrichment.
//!
//! **Construction.** The infinite slab (no hole) loaded symmetrically on both faces INSIDE the
//! hole, by a pressure q(r) = (1 − r²/A²)^(λ−1) or a radial shear τ_rz(r, ±D) = ±s(r),
//! s(r) = (r/A)(1 − r²/A²)^(λ−1), for r < A. In r ≥ A each is a homogeneous solution (faces free,
//! equilibrium, decaying); near the corner, (1 − r²/A²)^(λ−1) = (2(A − r)/A)^(λ−1)(1 + O(A − r)),
//! and the slab's response is a half-plane power field ρ^(λ−1)g(θ) plus smoother terms (λ is not
//! a half-plane exponent). The quarter-plane Williams eigenfunction continued to the half plane is
//! free on the face beyond the corner and carries a normal + shear traction ∝ ρ^(λ−1) on the
//! other half of the face — so a complex combination of the two loads contains it exactly, and
//! the rest is smoother (O(ρ^λ)). Real and imaginary parts give four real fit columns per λ.
//!
//! **Transforms** (Sonine's first finite integral, DLMF 10.22.19, with Λ of [`super::bessel_nu`]):
//! q̄(ξ) = ∫₀^A q(r) J₀(ξr) r dr = A² Λ_λ(ξA)/(2λ), s̄(ξ) = ∫₀^A s(r) J₁(ξr) r dr =
//! A² ξA Λ_(λ+1)(ξA)/(4λ(λ + 1)). The fields are those of [`crate::hankel::kernel`] (pressure q)
//! and [`crate::hankel::kernel_shear`] (shear s), integrated by [`super::corner_quad`].
//!
//! Sign convention: compression negative; the pressure load presses the faces (σ_z(r, ±D) =
//! −q(r)); displacements carry 1/(2G). Values are complex: the real and imaginary parts are the
//! responses to Re q and Im q (Re s, Im s).
//!
//! # Accuracy
//!
//! `tests/hankel/hole_corner.rs`: the Williams exponents and Λ_ν against mpmath, the transforms
//! against brute-force quadrature, the faces carry exactly the loads (Hankel inversion), the face
//! value at the corner against Weber–Schafheitlin, equilibrium and Hooke's law by differences, the
//! corner exponent of the traction on the hole, independence of where the tail starts.
//!
//! # Cost
//!
//! 25–35 % of a hole run (`cargo bench --bench hole`).
//!
//! ```
//! use boltzone::hankel::hole::corner::{corner_exponents, FieldComponent, CornerLoads};
//! let lam = corner_exponents(2);
//! assert!((lam[0].re - 2.739_593_4).abs() < 1e-7 && (lam[1].im - 1.463_928_1).abs() < 1e-7);
//! let loads = CornerLoads::new(0.1, 0.1, 0.3, 1.0, 1);
//! // on the face beyond the corner, σ_z = τ_rz = 0 (the loads act inside the hole only)
//! let f = loads.fields(0.13, &[0.1], &[FieldComponent::SigmaZ, FieldComponent::TauRz]);
//! for kind in 0..2 {
//!     assert!(f[0][0][0][kind].norm() < 1e-12 && f[0][0][1][kind].norm() < 1e-12);
//! }
//! ```

use super::corner_quad::{expint_table_extended, tail, ProductSeries};
use crate::hankel::kernel::{KernelNode, Kernels};
use crate::hankel::kernel_shear::ShearKernels;
use crate::numerics::bessel_nu::NormalBessel;
use crate::numerics::quadrature::gauss_legendre;
use num_complex::Complex64;
use std::f64::consts::PI;
use std::sync::OnceLock;

pub use super::corner_midplane::CornerMidplaneRule;

/// The first `n` free–free 90° wedge exponents λ (Re, Im > 0, λ = 1 excluded), alternately
/// roots of sin(λπ/2) = −λ and = +λ, by Newton's method from the estimate
/// λ ≈ 2k + ¾ + (2i/π) ln(4k + 1.5); converged to a relative step below 1e-15.
pub fn corner_exponents(n: usize) -> Vec<Complex64> {
    (1..=n)
        .map(|k| {
            let sign = if k % 2 == 1 { 1.0 } else { -1.0 };
            let re = 2.0 * k as f64 + 0.75;
            let mut l = Complex64::new(re, (2.0 / PI) * (2.0 * re).ln());
            for _ in 0..60 {
                let h = 0.5 * PI;
                let step = ((l * h).sin() + sign * l) / (h * (l * h).cos() + sign);
                l -= step;
                if step.norm() <= 1e-15 * l.norm() {
                    break;
                }
            }
            l
        })
        .collect()
}

/// The `n` leading exponents of the corner's singular expansion: the Williams exponents λ_k
/// ([`corner_exponents`]) and their axisymmetric companions λ_k + j (the terms ρ^(λ+j) that the
/// hole's curvature and the loads' shape add to each Williams term), ordered by real part:
/// λ₁, λ₁ + 1, λ₁ + 2, λ₂, λ₁ + 3, λ₂ + 1, …
pub fn enrichment_exponents(n: usize) -> Vec<Complex64> {
    let roots = corner_exponents(n);
    enrichment_terms(n)
        .into_iter()
        .map(|(k, j)| roots[k] + j as f64)
        .collect()
}

/// The (root index k, offset j) of each of [`enrichment_exponents`]: λ = λ_(k+1) + j.
fn enrichment_terms(n: usize) -> Vec<(usize, usize)> {
    let roots = corner_exponents(n);
    let mut all: Vec<(f64, usize, usize)> = Vec::new();
    for (k, l) in roots.iter().enumerate() {
        for j in 0..n {
            all.push((l.re + j as f64, k, j));
        }
    }
    all.sort_by(|a, b| a.0.total_cmp(&b.0));
    all.iter().take(n).map(|&(_, k, j)| (k, j)).collect()
}

/// A field component of the enrichment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FieldComponent {
    /// σ_r.
    SigmaR,
    /// σ_θ.
    SigmaTheta,
    /// σ_z.
    SigmaZ,
    /// τ_rz (odd in z).
    TauRz,
    /// u.
    U,
    /// w (odd in z).
    W,
}

/// Gauss–Legendre points per panel of the finite-part rule. A panel spans at most a half-period
/// of the fastest oscillation e^(iξ(A + r)) and 1.5/D, the kernels' scale (their poles lie
/// ≥ 3.7/D from the real ξ-axis): 12 points integrate both to ~1e-20 (the GL remainder for
/// e^(iπu/2) on [−1, 1] is ~1e-20 at 10 points). Measured: the traction columns at 257 heights
/// (A/D = 1 and 0.5) differ from a 20-point rule's by ≤ 5e-15 of each column's largest value,
/// the rounding level of the sums (10 points: 1.3e-14).
const NODES_PER_PANEL: usize = 12;

/// Beyond ξ(D − |z|) = `DECAYED` a height's share of the integrals is dropped, and the tail
/// too when X(D − |z|) exceeds it: every kernel there is e^(−ξ(D−|z|)) times a polynomial of
/// degree ≤ 2 in ξD (≤ 70 on the rule), so the dropped terms are below 4·70²·e^(−45) ≈ 6e-16
/// of the transform's value there, itself ≤ 1e-4 of its value at ξ = 0 (Λ_λ(ξA) decays like
/// (ξA)^(−Re λ − ½) and XA ≥ 30).
const DECAYED: f64 = 45.0;

/// One integral term: coefficient, power q of ξ, Bessel order n of J_n(ξr), kernel index into
/// [z, τ, r, m, n, w].
type Term = (f64, usize, usize, usize);

/// The terms of a component for the pressure load (the shear load has the opposite signs and
/// its own kernels), at radius r, shear modulus g (see the kernel tables).
fn terms(c: FieldComponent, r: f64, g: f64) -> Vec<Term> {
    let (kz, kt, kr, km, kn, kw) = (0, 1, 2, 3, 4, 5);
    match c {
        FieldComponent::SigmaR => vec![(-1.0, 1, 0, kr), (1.0 / r, 0, 1, km)],
        FieldComponent::SigmaTheta => vec![(-1.0, 1, 0, kn), (-1.0 / r, 0, 1, km)],
        FieldComponent::SigmaZ => vec![(-1.0, 1, 0, kz)],
        FieldComponent::TauRz => vec![(-1.0, 1, 1, kt)],
        FieldComponent::U => vec![(-0.5 / g, 0, 1, km)],
        FieldComponent::W => vec![(-0.5 / g, 0, 0, kw)],
    }
}

fn odd(c: FieldComponent) -> bool {
    matches!(c, FieldComponent::TauRz | FieldComponent::W)
}

/// The corner loads of one hole: for each exponent λ_k a pressure and a shear load inside the
/// hole (see the module docs).
#[derive(Debug, Clone)]
pub struct CornerLoads {
    pub(super) a: f64,
    pub(super) d: f64,
    nu: f64,
    g: f64,
    lams: Vec<Complex64>,
    normal: Vec<NormalBessel>,
    shear: Vec<NormalBessel>,
    /// Per Williams root used: the functions of orders λ_k + j, j = 0…(largest offset + 1),
    /// which one backward recurrence serves ([`NormalBessel::eval_family`]).
    families: Vec<Vec<NormalBessel>>,
    /// Per exponent: (family, offset j) of its pressure transform's order (the shear's is j + 1).
    members: Vec<(usize, usize)>,
    /// ξ beyond which the closed-form tail is used.
    x_cut: f64,
    /// The finite-part nodes for the hole r = A, with the transforms there (computed once).
    hole_nodes: Vec<Node>,
    /// The midplane rule of the first r_max asked for.
    pub(super) midplane_nodes: OnceLock<CornerMidplaneRule>,
}

/// A node of the finite-part rule: ξ, weight, J₀(ξr), J₁(ξr), (q̄_k, s̄_k) for every exponent.
#[derive(Debug, Clone)]
struct Node {
    xi: f64,
    weight: f64,
    bessel: [f64; 2],
    transforms: Vec<(Complex64, Complex64)>,
}

impl CornerLoads {
    /// The loads of the first `n` exponents for hole radius `a`, half-thickness `d`, Poisson's
    /// ratio `nu`, shear modulus `g`.
    pub fn new(a: f64, d: f64, nu: f64, g: f64, n: usize) -> Self {
        let lams = enrichment_exponents(n);
        let x_cut = lams
            .iter()
            .map(|l| (l + 1.0).norm_sqr().max(30.0) / a)
            .fold(20.0 / d, f64::max);
        let roots = corner_exponents(n);
        let terms = enrichment_terms(n);
        let mut families = Vec::new();
        let mut members = vec![(0, 0); n];
        for (k, root) in roots.iter().enumerate() {
            let top = terms.iter().filter(|t| t.0 == k).map(|t| t.1 + 2).max();
            if let Some(top) = top {
                for (i, t) in terms.iter().enumerate() {
                    if t.0 == k {
                        members[i] = (families.len(), t.1);
                    }
                }
                families.push(
                    (0..top)
                        .map(|j| NormalBessel::new(root + j as f64))
                        .collect(),
                );
            }
        }
        let mut loads = Self {
            families,
            members,
            a,
            d,
            nu,
            g,
            normal: lams.iter().map(|l| NormalBessel::new(*l)).collect(),
            shear: lams.iter().map(|l| NormalBessel::new(l + 1.0)).collect(),
            lams,
            x_cut,
            hole_nodes: Vec::new(),
            midplane_nodes: OnceLock::new(),
        };
        loads.hole_nodes = loads.nodes(a);
        loads
    }

    /// The same loads with the closed-form tail starting at ξ = `x`/A instead (it must stay in
    /// the tail's range: xA ≥ |λ + 1|² and xD ≥ 20 — else the result is inaccurate, which is
    /// what this is for: checking that the value does not depend on the split).
    pub fn with_tail_start(mut self, x: f64) -> Self {
        self.x_cut = x / self.a;
        self.hole_nodes = self.nodes(self.a);
        self
    }

    /// Where the closed-form tail starts, as ξA.
    pub fn tail_start(&self) -> f64 {
        self.x_cut * self.a
    }

    /// The panel ends of the finite-part rule for radius r: no wider than a half-period
    /// π/(A + r) of the fastest oscillation, and below ξ = 20/D (where the kernels still differ
    /// from their half-space form) no wider than 1.5/D, their scale; up to X, the first panel
    /// end at or beyond `x_cut`.
    fn panel_ends(&self, r: f64) -> Vec<f64> {
        let half = PI / (self.a + r);
        let (near, switch) = (half.min(1.5 / self.d), 20.0 / self.d);
        let mut ends = vec![0.0];
        let mut x = 0.0;
        while x < self.x_cut {
            x += if x < switch { near } else { half };
            ends.push(x);
        }
        ends
    }

    /// The finite-part rule for radius r on [`Self::panel_ends`], [`NODES_PER_PANEL`]
    /// Gauss–Legendre points per panel, with J₀(ξr), J₁(ξr) and the transforms at each node.
    fn nodes(&self, r: f64) -> Vec<Node> {
        let rule = gauss_legendre(NODES_PER_PANEL);
        let ends = self.panel_ends(r);
        let mut out = Vec::with_capacity(ends.len() * rule.len());
        for e in ends.windows(2) {
            let (c0, h) = (0.5 * (e[0] + e[1]), e[1] - e[0]);
            for &(x, w) in rule.iter() {
                let xi = c0 + 0.5 * h * x;
                out.push(Node {
                    xi,
                    weight: 0.5 * h * w,
                    bessel: [libm::j0(xi * r), libm::j1(xi * r)],
                    transforms: self.transforms_all(xi),
                });
            }
        }
        out
    }

    /// The end X of the finite part of the rule for radius r.
    fn x_end(&self, r: f64) -> f64 {
        *self.panel_ends(r).last().expect("at least one panel end")
    }

    /// The hole radius A the loads act inside.
    pub fn radius(&self) -> f64 {
        self.a
    }

    /// Number of exponents (each gives 4 real fields).
    pub fn count(&self) -> usize {
        self.lams.len()
    }

    /// The exponents λ_k.
    pub fn exponents(&self) -> &[Complex64] {
        &self.lams
    }

    /// The pressure q_k(r) and the shear s_k(r) of exponent k (zero for r ≥ A).
    pub fn loads(&self, k: usize, r: f64) -> (Complex64, Complex64) {
        if r >= self.a {
            return (Complex64::new(0.0, 0.0), Complex64::new(0.0, 0.0));
        }
        let q = ((self.lams[k] - 1.0) * (1.0 - (r / self.a).powi(2)).ln()).exp();
        (q, q * r / self.a)
    }

    /// The transforms (q̄_k(ξ), s̄_k(ξ)) (orders 0 and 1).
    pub fn transforms(&self, k: usize, xi: f64) -> (Complex64, Complex64) {
        let (a, l) = (self.a, self.lams[k]);
        let x = xi * a;
        let (ln, ls) = self.normal[k].eval_pair(&self.shear[k], x);
        (
            a * a * ln / (2.0 * l),
            a * a * x * ls / (4.0 * l * (l + 1.0)),
        )
    }

    /// [`Self::transforms`] of every exponent at once (one backward recurrence per family of
    /// orders λ_k + j instead of one per exponent).
    pub fn transforms_all(&self, xi: f64) -> Vec<(Complex64, Complex64)> {
        let x = xi * self.a;
        let values: Vec<Vec<Complex64>> = self
            .families
            .iter()
            .map(|f| NormalBessel::eval_family(f, x))
            .collect();
        let a2 = self.a * self.a;
        self.lams
            .iter()
            .zip(&self.members)
            .map(|(l, &(f, j))| {
                let (ln, ls) = (values[f][j], values[f][j + 1]);
                (a2 * ln / (2.0 * l), a2 * x * ls / (4.0 * l * (l + 1.0)))
            })
            .collect()
    }

    /// The half-space limits (α, β) of the kernels [z, τ, r, m, n, w] of the pressure (kind 0)
    /// and shear (kind 1) loads: k → (α + βu)e^(−u), u = ξ(D − |z|).
    fn half_space(&self, kind: usize) -> [(f64, f64); 6] {
        let nu = self.nu;
        if kind == 0 {
            [
                (1.0, 1.0),
                (0.0, -1.0),
                (1.0, -1.0),
                (1.0 - 2.0 * nu, -1.0),
                (2.0 * nu, 0.0),
                (2.0 * (1.0 - nu), 1.0),
            ]
        } else {
            [
                (0.0, 1.0),
                (1.0, -1.0),
                (2.0, -1.0),
                (2.0 * (1.0 - nu), -1.0),
                (2.0 * nu, 0.0),
                (1.0 - 2.0 * nu, 1.0),
            ]
        }
    }

    /// The components `comps` of every enrichment field at (r, z) for each z in `zs` (r > 0,
    /// |z| ≤ D): `out[height][k][component]` = [pressure field, shear field] of exponent k.
    pub fn fields(
        &self,
        r: f64,
        zs: &[f64],
        comps: &[FieldComponent],
    ) -> Vec<Vec<Vec<[Complex64; 2]>>> {
        let (a, d, nu) = (self.a, self.d, self.nu);
        let nl = self.lams.len();
        let zero = Complex64::new(0.0, 0.0);
        let mut out = vec![vec![vec![[zero; 2]; comps.len()]; nl]; zs.len()];
        let ts: Vec<Vec<Term>> = comps.iter().map(|c| terms(*c, r, self.g)).collect();
        let az: Vec<f64> = zs.iter().map(|z| z.abs().min(d)).collect();
        // finite part on [0, X] (the hole's nodes are computed once)
        let x_end = self.x_end(r);
        let fresh;
        let nodes = if r == a {
            &self.hole_nodes
        } else {
            fresh = self.nodes(r);
            &fresh
        };
        for node in nodes {
            let (xi, wt, bes, tr) = (node.xi, node.weight, node.bessel, &node.transforms);
            let kt = KernelNode::new(xi * d);
            for (hi, &zh) in az.iter().enumerate() {
                if xi * (d - zh) > DECAYED {
                    continue;
                }
                let kh = kt.height(xi * zh);
                let kn = Kernels::at_height(&kt, &kh, nu);
                let ks = ShearKernels::at_height(&kt, &kh, nu);
                let kv = [
                    [kn.z, kn.tau, kn.r, kn.m, kn.n, kn.w],
                    [ks.z, ks.tau, ks.r, ks.m, ks.n, ks.w],
                ];
                for (ci, tc) in ts.iter().enumerate() {
                    let mut v = [0.0; 2];
                    for &(coef, q, n, ki) in tc {
                        let base = coef * if q == 1 { xi } else { 1.0 } * bes[n] * wt;
                        v[0] += base * kv[0][ki];
                        v[1] -= base * kv[1][ki];
                    }
                    for (k, (qn, qs)) in tr.iter().enumerate() {
                        let o = &mut out[hi][k][ci];
                        o[0] += qn * v[0];
                        o[1] += qs * v[1];
                    }
                }
            }
        }
        // tail beyond X in closed form; the E_p tables per height and family of exponents
        // λ_k + j (one extended table serves them all)
        let hs = [self.half_space(0), self.half_space(1)];
        let kappas: Vec<f64> = [1.0, -1.0]
            .iter()
            .flat_map(|s1| [1.0, -1.0].map(|s2| s1 * a + s2 * r))
            .collect();
        let tables: Vec<Vec<Vec<Vec<Complex64>>>> = az
            .iter()
            .map(|&zh| {
                let y = d - zh;
                if y * x_end > DECAYED {
                    return Vec::new();
                }
                self.families
                    .iter()
                    .map(|f| {
                        let (base, extra) = (f[0].order(), f.len() - 2);
                        expint_table_extended(base, y, x_end, &kappas, extra)
                    })
                    .collect()
            })
            .collect();
        for (k, &lam) in self.lams.iter().enumerate() {
            let (family, offset) = self.members[k];
            let pref = [a * a / (2.0 * lam), a * a / (4.0 * lam * (lam + 1.0))];
            let series: Vec<[ProductSeries; 2]> = (0..2)
                .map(|kind| {
                    let (nu_t, tau) = if kind == 0 {
                        (lam, 0.0)
                    } else {
                        (lam + 1.0, 1.0)
                    };
                    [0, 1].map(|n| ProductSeries::new(nu_t, tau, n, a, r))
                })
                .collect();
            debug_assert!(series[0][0]
                .parts
                .iter()
                .zip(&kappas)
                .all(|(p, k)| p.0 == *k));
            let x_lam = (-lam * x_end.ln()).exp();
            for (hi, &zh) in az.iter().enumerate() {
                let y = d - zh;
                if tables[hi].is_empty() {
                    continue;
                }
                let e: Vec<&[Complex64]> = tables[hi][family]
                    .iter()
                    .map(|row| &row[offset..])
                    .collect();
                for (ci, tc) in ts.iter().enumerate() {
                    for kind in 0..2 {
                        let sign = if kind == 0 { 1.0 } else { -1.0 };
                        let mut v = zero;
                        for &(coef, q, n, ki) in tc {
                            let (al, be) = hs[kind][ki];
                            v += sign
                                * coef
                                * tail(&series[kind][n], &e, x_lam, q, al, be, y, x_end);
                        }
                        out[hi][k][ci][kind] += pref[kind] * v;
                    }
                }
            }
        }
        for (z, oh) in zs.iter().zip(out.iter_mut()) {
            if *z < 0.0 {
                for ok in oh.iter_mut() {
                    for (c, o) in comps.iter().zip(ok.iter_mut()) {
                        if odd(*c) {
                            *o = [-o[0], -o[1]];
                        }
                    }
                }
            }
        }
        out
    }

    /// σ_r and τ_rz on the cylinder of radius r at the heights `zs`:
    /// `out[height][k]` = [σ_r pressure, σ_r shear, τ pressure, τ shear].
    pub fn tractions(&self, r: f64, zs: &[f64]) -> Vec<Vec<[Complex64; 4]>> {
        self.fields(r, zs, &[FieldComponent::SigmaR, FieldComponent::TauRz])
            .into_iter()
            .map(|h| {
                h.into_iter()
                    .map(|c| [c[0][0], c[0][1], c[1][0], c[1][1]])
                    .collect()
            })
            .collect()
    }
}
