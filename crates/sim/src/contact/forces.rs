//! Contact forces of all feet from the foot body states: either from each foot's own joint
//! chain ([`ContactSet::evaluate`]) or from a preceding kinematics pass of the dynamics
//! ([`ContactSet::evaluate_from`], the plant's right-hand side: no second kinematics).
//!
//! Per foot the point forces `f_j` (world) are summed once as `F = sum f_j` and
//! `M = sum r_j x f_j` with `r_j = A c_j` the world offset of point `c_j` from the body origin;
//! the body-frame wrench is then `[A^T M; A^T F]` and the foot torque about the sole reference
//! `M + (r_O - r_ref) x F` (one rotation per foot instead of one per point). The side wrenches
//! (a foot with its toe) follow from the entries' ([`ContactSet::sum_sides`]).

use super::{BodyState, ContactOutput, ContactSet, FootWrench};
use biped_dynamics::{BodyId, Data, Wrench};
use nalgebra::{Vector2, Vector3};

impl BodyState {
    /// World pose and velocity of `body` from a kinematics pass stored in `data` (body-frame
    /// velocities rotated to the world); `None` if `body` is out of range.
    pub fn from_data(data: &Data, body: BodyId) -> Option<Self> {
        let (rot, pos, v) = (
            data.world_rot.get(body)?,
            data.world_pos.get(body)?,
            data.vel.get(body)?,
        );
        Some(Self {
            rot: *rot,
            pos: *pos,
            omega: rot * v.ang,
            vel: rot * v.lin,
        })
    }
}

impl ContactSet {
    /// Contact forces at `(q, v)` with bristle states `s`: writes the bristle rates into `sdot`,
    /// sets the entry bodies' `fext` (body frame, moment about the body origin) and fills `out`
    /// (entries and sides). No allocation. `fext` entries of other bodies are left alone.
    pub fn evaluate(
        &self,
        q: &[f64],
        v: &[f64],
        s: &[f64],
        sdot: &mut [f64],
        fext: &mut [Wrench],
        out: &mut ContactOutput,
    ) {
        for k in 0..self.feet.len() {
            let st = self.feet[k].chain.eval(q, v);
            self.foot_forces(k, &st, s, sdot, fext, out);
        }
        self.sum_sides(out);
    }

    /// Same as [`Self::evaluate`] with the foot poses and velocities read from `data`, which
    /// must hold a kinematics pass with velocities at the same `(q, v)` (e.g. after
    /// `biped_dynamics::forward_dynamics_kinematics`). Feet outside `data` get the world frame.
    pub fn evaluate_from(
        &self,
        data: &Data,
        s: &[f64],
        sdot: &mut [f64],
        fext: &mut [Wrench],
        out: &mut ContactOutput,
    ) {
        for k in 0..self.feet.len() {
            let st = BodyState::from_data(data, self.feet[k].body).unwrap_or(BodyState::identity());
            self.foot_forces(k, &st, s, sdot, fext, out);
        }
        self.sum_sides(out);
    }

    /// Point forces, bristle rates, body wrench and foot wrench of foot `k` in state `st`.
    fn foot_forces(
        &self,
        k: usize,
        st: &BodyState,
        s: &[f64],
        sdot: &mut [f64],
        fext: &mut [Wrench],
        out: &mut ContactOutput,
    ) {
        let (p, foot) = (&self.params, &self.feet[k]);
        let (mut force, mut moment) = (Vector3::zeros(), Vector3::zeros());
        let (mut fn_sum, mut cop, mut in_contact) = (0.0, Vector3::zeros(), 0);
        let range = foot.first..foot.first + foot.spec.points.len();
        let states = s[2 * range.start..2 * range.end].chunks_exact(2);
        let rates = sdot[2 * range.start..2 * range.end].chunks_exact_mut(2);
        let forces = out.point_forces[range].iter_mut();
        for (((c, sj), rate_j), f_j) in foot.spec.points.iter().zip(states).zip(rates).zip(forces) {
            let r = st.rot * c;
            let (pos, vel) = (st.pos + r, st.vel + st.omega.cross(&r));
            let f_n = p.normal_force(p.ground_height - pos.z, -vel.z);
            let (f_t, rate) =
                p.tangential(Vector2::new(sj[0], sj[1]), Vector2::new(vel.x, vel.y), f_n);
            rate_j.copy_from_slice(rate.as_slice());
            let f = Vector3::new(f_t.x, f_t.y, f_n);
            *f_j = f;
            if f_n > 0.0 {
                in_contact += 1;
                fn_sum += f_n;
                cop += Vector3::new(pos.x, pos.y, p.ground_height) * f_n;
            }
            force += f;
            moment += r.cross(&f);
        }
        let reference = st.rot * foot.spec.reference;
        fext[foot.body] = Wrench::new(st.rot.tr_mul(&moment), st.rot.tr_mul(&force));
        out.feet[k] = FootWrench {
            force,
            torque: moment - reference.cross(&force),
            reference: st.pos + reference,
            cop: (fn_sum > 0.0).then(|| cop / fn_sum),
            points_in_contact: in_contact,
        };
        out.foot_states[k] = *st;
    }
}
