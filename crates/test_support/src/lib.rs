//! Test support shared by the workspace's crates (a dev-dependency only, never published):
//! [`alloc`] counts heap allocations for the "no allocation per call" tests, [`mutate`]
//! produces corrupted copies of valid input files for the parsers' property tests.

pub mod alloc;
pub mod mutate;
