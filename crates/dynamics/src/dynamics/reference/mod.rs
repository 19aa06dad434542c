//! Reference O(n) forward dynamics with sub-systems, written as the thesis states it
//! (Algorithms 2.1-2.4, eqs. (2.33)-(2.37), (2.56), (2.66)-(2.90)): dense 6x6 matrices, general
//! kinematics for every body and sub-system member, one module per step. It computes `qddot`
//! for `(q, v, tau)` from the [`Model`] alone (its body list, joints, sub-systems and rewired
//! node list) and serves as the yardstick for [`crate::forward_dynamics`]'s fast paths.
//!
//! Steps (Algorithm 2.1): `first` (1: kinematics, Algorithm 2.2), `body` (2: impressed forces
//! (2.56) and mass matrices (2.22)), `backward` and `subsystem` (3: Algorithm 2.3), `forward`
//! (4: Algorithm 2.4); `joint` holds the joint models (2.35)-(2.49). Where the extracted text
//! is inconsistent the module that implements the step says which reading it takes.

mod backward;
mod body;
mod first;
mod forward;
mod joint;
pub mod kinds;
mod subsystem;

use crate::check;
use crate::spatial::Wrench;
use crate::{DynamicsError, Model};
use backward::Impressed;
use nalgebra::{DVector, Matrix6, Vector6};

/// Generalized accelerations `qddot` (for free quaternion joints `vdot`) at `(q, v)` with
/// generalized forces `tau` (`Q`), gravity and optional external wrenches (one per body, body
/// frame, moment about the origin): Algorithm 2.1 steps 1-4.
///
/// # Example
///
/// Dill(2) (four revolute bodies): the reference and the fast O(n) path agree.
///
/// ```
/// use biped_dynamics::dynamics::reference;
/// use biped_dynamics::{dill::dill, forward_dynamics, Algorithm, Data};
/// use nalgebra::DVector;
///
/// let model = dill(2)?;
/// let (q, v) = (DVector::from_element(4, 0.3), DVector::from_element(4, -0.5));
/// let tau = DVector::from_element(4, 1.0);
/// let qdd = reference::forward_dynamics(&model, &q, &v, &tau, None)?;
/// let mut data = Data::new(&model);
/// let fast = forward_dynamics(&model, &mut data, &q, &v, &tau, None, Algorithm::On)?;
/// assert!((&qdd - fast).amax() < 1e-10 * fast.amax());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn forward_dynamics(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
    tau: &DVector<f64>,
    fext: Option<&[Wrench]>,
) -> Result<DVector<f64>, DynamicsError> {
    Ok(forward_dynamics_with_accelerations(model, q, v, tau, fext)?.qddot)
}

/// Output of Algorithm 2.4.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    /// Generalized accelerations `qddot` (2.66), (2.79).
    pub qddot: DVector<f64>,
    /// Body accelerations `a_i = [omegadot; rddot_O]` (body frame) of the bodies outside
    /// sub-systems (2.34) and of the members with children outside (2.90); `None` for the
    /// other members, whose accelerations the algorithm does not form.
    pub acc: Vec<Option<Vector6<f64>>>,
}

/// [`forward_dynamics`] with the body accelerations Algorithm 2.4 forms ([`Solution`]).
pub fn forward_dynamics_with_accelerations(
    model: &Model,
    q: &DVector<f64>,
    v: &DVector<f64>,
    tau: &DVector<f64>,
    fext: Option<&[Wrench]>,
) -> Result<Solution, DynamicsError> {
    check::configuration(model, q)?;
    check::vector("v", v, model.nv())?;
    check::vector("tau", tau, model.nv())?;
    check::wrenches(model, fext)?;
    let kin = first::first_forward(model, q.as_slice(), v.as_slice())?; // step 1
    let (mass, force) = impressed(model, &kin, fext); // step 2
    let imp = Impressed {
        mass: &mass,
        force: &force,
        tau,
    };
    let props = backward::backward(model, &kin, &imp)?; // step 3
    let solution = forward::second_forward(model, &kin, &props)?; // step 4
    check::result("qddot", solution.qddot.as_slice())?;
    Ok(solution)
}

/// Step 2 of Algorithm 2.1: `M_i` (2.22) and `f_i` (2.56) of every body, gravity `g_i =
/// A_kI g` in body coordinates.
fn impressed(
    model: &Model,
    kin: &first::Kinematics,
    fext: Option<&[Wrench]>,
) -> (Vec<Matrix6<f64>>, Vec<Vector6<f64>>) {
    let mut mass = Vec::with_capacity(model.nbodies());
    let mut force = Vec::with_capacity(model.nbodies());
    for (i, (b, k)) in model.bodies().iter().zip(&kin.bodies).enumerate() {
        let omega = body::upper(&k.vel);
        let g = k.rot_ki * model.gravity();
        mass.push(body::mass_matrix(b.inertia()));
        force.push(body::force(b.inertia(), &omega, &g, fext.map(|f| &f[i])));
    }
    (mass, force)
}

/// The child nodes of node `n` (first child, then its brothers, Fig. 2.7).
fn children(model: &Model, n: usize) -> impl Iterator<Item = usize> + '_ {
    let nodes = model.nodes();
    std::iter::successors(nodes[n].first_child, move |&c| nodes[c].brother)
}

/// The error for a node list this reference cannot follow (none that [`crate::ModelBuilder`]
/// builds).
fn malformed(what: &'static str) -> DynamicsError {
    DynamicsError::Unsupported(what)
}
