//! Integration tests of `boltzone::numerics`: quadrature and special functions against
//! closed forms and arbitrary-precision references (`tests/data/`).

mod bessel_ik;
mod bessel_j;
mod panel_grid;
mod panel_grid_j0;
mod quadrature;
mod root;
mod secant;
mod tanh_sinh;
