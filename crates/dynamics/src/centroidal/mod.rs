//! Centre of mass, its Jacobian, linear and angular momentum about the CoM (7.1), the angular
//! momentum Jacobian `J_L` (7.2) and the centroidal momentum matrix `A_G` with its bias.
//!
//! Momenta are force-like 6-vectors `h_G = [L_G; p]` (moment first, the crate's [`Force`](crate::spatial::Force)
//! convention): `L_G` is the angular momentum about the CoM (7.1) and `p` the linear momentum.
//! Columns are composite inertias applied to world Jacobian columns, so every body's motion,
//! including geared-rotor spin on its driver's coordinate, enters exactly.

mod com;
mod composite;
mod momentum;

pub use com::{center_of_mass, CenterOfMass};
pub use composite::Centroidal;
pub(crate) use momentum::MomentumTable;
pub use momentum::{centroidal_momentum, centroidal_momentum_current, CentroidalMomentum};

#[cfg(test)]
mod tests;
