//! Semi-analytic infinite-slab solutions by Hankel transforms (Sneddon 1946).
pub mod hole;
