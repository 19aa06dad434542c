//! Property tests of the six closed-form distance functions (Table 6.1) and the swap
//! relation against the KKT reference solver: generic, lattice-degenerate and mixed-scale
//! families. Case counts per pair type are the second macro arguments.
//!
//! Cases per pair type (PP, PL, PT, LL, LT, TT), over this file and `adversarial.rs`:
//! random 30k + lattice 25k + mixed scale 15k + pow2 scaled 10k + near-degenerate 30k +
//! touching 15k + intersecting 15k = 140k. Every case is checked in both argument orders,
//! so LP, TP, TL (via `biped_ssv::distance` and the swap relation) get 140k each too.

mod reference;
mod support;

/// Generic positions in [-10, 10]^3.
mod random {
    crate::support::pair_tests!(crate::support::families::random, 30_000);
}

/// Integer lattice: coincidences, zero-length segments, collinear triangles, exact touching.
mod lattice {
    crate::support::pair_tests!(crate::support::families::lattice, 25_000);
}

/// Coordinates up to 1e6, sizes and offsets 1e-6..1e6, radii 0..1e6.
mod mixed_scale {
    crate::support::pair_tests!(crate::support::families::mixed_scale, 15_000);
}

/// Random, near-degenerate and intersecting pairs rescaled exactly by 2^-20..2^20, checked
/// with a purely relative tolerance (scale without the floor 1).
mod pow2_scaled {
    crate::support::pair_tests!(
        crate::support::families::pow2_scaled,
        10_000,
        crate::support::check_pair_relative
    );
}
