//! Generic numerics, free of the physics: quadrature, roots, special functions, interpolation
//! and convergence estimates. Nothing here imports from the rest of the crate.
//!
//! - [`quadrature`]: Gauss–Legendre panels and ∫₀^∞ f(ξ) dξ for oscillatory f
//!   (partition–extrapolation with Wynn's ε);
//! - [`tanh_sinh`]: finite intervals with end-point singularities;
//! - [`root`]: Brent's bracketed root finder and the scan for the first upward crossing;
//! - [`integral_j0`]: Ji₀(x) = ∫₀^x J₀; [`bessel_i`], [`bessel_k`]: I₀, I₁, K₀, K₁ of complex
//!   argument; [`bessel_nu`]: J_ν of complex order and Γ;
//! - [`chebyshev`]: interpolation on the Chebyshev–Lobatto grid;
//! - [`panel_grid`]: rows of cos ξs, cos ξs − 1 and J₀(ξs) over equal Gauss panels, and
//!   interpolation on them (the holed two-plate route's tables, the slab's midplane rule);
//! - [`convergence`]: level estimates, fitted rates and observed orders of refinement sequences;
//! - [`random`]: a seeded generator (splitmix64) for reproducible studies.
//!
//! # Accuracy
//!
//! Each file's Accuracy section; the test crate is `tests/numerics/`, against arbitrary-precision
//! references in `tests/data/`.
//!
//! # Cost
//!
//! Each file's Cost section; `cargo bench --bench hankel`.
//!
//! ```
//! use boltzone::numerics::root::brent;
//! let mut f = |x: f64| Ok::<f64, std::convert::Infallible>(x.cos() - x);
//! let r = brent(&mut f, 0.0, 1.0, 1.0, 1f64.cos() - 1.0, 1e-15, 100)?;
//! assert!((r.x.cos() - r.x).abs() < 1e-14);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod bessel_i;
pub mod bessel_k;
pub mod bessel_nu;
pub mod chebyshev;
pub mod convergence;
pub mod integral_j0;
pub mod panel_grid;
pub mod quadrature;
pub mod random;
pub mod root;
pub mod secant;
pub mod tanh_sinh;
