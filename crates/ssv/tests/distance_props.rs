//! Property tests of the six closed-form distance functions (Table 6.1) and the swap
//! relation against the KKT reference solver: generic, lattice-degenerate and mixed-scale
//! families. Case counts per pair type are the second macro arguments.

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
