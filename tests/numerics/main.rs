//! Integration tests of `boltzone::numerics`: quadrature and special functions against
//! closed forms and arbitrary-precision references (`tests/data/`).

mod bessel_ik;
mod bessel_j;
mod quadrature;
mod root;
mod secant;
mod tanh_sinh;
