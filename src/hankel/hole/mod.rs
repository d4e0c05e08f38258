//! The single plate with a hole by Hankel transforms: the hole correction (work in progress).

pub mod bessel_k;
pub mod eigen;
