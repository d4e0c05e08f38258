//! Axisymmetric finite elements (report Appendices A and B).
