//! Cached fast path of the knee parts: the loops of the last kinematics pass
//! ([`KneeLoopCache`]) shared by the parts of one drive and read back as motor rows.

use super::closure::KneeClosure;
use super::{KneeCoupling, KneePart, NAME};
use crate::mechanism::cache::LoopSlots;
use crate::mechanism::jet::input_arrays;
use crate::mechanism::{AxialMotion, MechanismError, RelativeMotion};

/// Closed knee loops of the last kinematics pass, keyed by drive identity and exact knee angle (see
/// [`crate::mechanism::cache`]): the three parts (housing, nut, rotor) of one drive share one loop
/// closure (3.4)-(3.7), and [`crate::Data::coupled_spin_row`] reads the motor rows back.
#[derive(Debug, Clone, Copy, Default)]
pub struct KneeLoopCache(LoopSlots<(u64, f64), KneeClosure>);

impl KneeCoupling {
    /// [`crate::mechanism::Coupling::motion`] as a [`RelativeMotion`], reusing `cache` when it holds this drive's
    /// loop closed at exactly the same `(q_in, qd_in)`, else closing it and storing it.
    pub fn relative_cached(
        &self,
        q_in: &[f64],
        qd_in: &[f64],
        cache: &mut Option<KneeLoopCache>,
    ) -> Result<RelativeMotion, MechanismError> {
        let ([q], [qd]) = input_arrays::<1>(NAME, q_in, qd_in)?;
        let closure = self.closure_cached(q, cache)?;
        Ok(self.drive.part_motion(self.part, closure, qd))
    }

    /// Spin of the rotor (`N_screw l + offset`, (3.3)) or travel of the nut (`l`, (3.4))
    /// relative to the housing, with rows and rates from (3.5)-(3.6), from `cache` like
    /// [`Self::relative_cached`]; `None` for the housing.
    pub(crate) fn axial_motion_cached(
        &self,
        q_in: &[f64],
        qd_in: &[f64],
        cache: &mut Option<KneeLoopCache>,
    ) -> Result<Option<AxialMotion>, MechanismError> {
        let drive = &self.drive;
        let (n, offset) = match self.part {
            KneePart::Rotor => (drive.screw_ratio(), drive.params.motor_offset),
            KneePart::Nut => (1.0, 0.0),
            KneePart::Housing => return Ok(None),
        };
        let ([q], [qd]) = input_arrays::<1>(NAME, q_in, qd_in)?;
        let c = self.closure_cached(q, cache)?;
        Ok(Some(AxialMotion {
            travel: n * c.l + offset,
            row: [n * c.l_q, 0.0, 0.0],
            speed: n * c.l_q * qd,
            bias: n * c.l_qq * qd * qd,
        }))
    }

    /// This drive's loop closed at knee angle `q`: from `cache` when it holds it, else closed
    /// and stored there.
    #[inline(always)]
    fn closure_cached<'c>(
        &self,
        q: f64,
        cache: &'c mut Option<KneeLoopCache>,
    ) -> Result<&'c KneeClosure, MechanismError> {
        let slots = &mut cache.get_or_insert_with(KneeLoopCache::default).0;
        let drive = &self.drive;
        match slots.position(|&(id, x)| id == drive.id && x == q) {
            Some(i) => Ok(slots.value(i)),
            None => slots.store_with((drive.id, q), |c| drive.solve_into(q, c)),
        }
    }

    /// Part-frame z row of this part's relative Jacobian at `q_in` (for the rotor the motor
    /// row `N_screw dl/dq`, (3.3), (3.5)), from `cache` when it holds this drive closed at
    /// exactly `q_in`, else from a fresh loop closure.
    pub fn spin_row_cached(
        &self,
        q_in: &[f64],
        cache: Option<&KneeLoopCache>,
    ) -> Result<f64, MechanismError> {
        let ([q], _) = input_arrays::<1>(NAME, q_in, &[0.0])?;
        let drive = &self.drive;
        let hit = cache.and_then(|c| c.0.find(|&(id, x)| id == drive.id && x == q));
        let c = match hit {
            Some(c) => *c,
            None => drive.solve(q)?,
        };
        // Only the rotor spins about its z axis ((3.5): N_screw dl/dq); the housing and the
        // nut turn about the knee axis, their y axis.
        Ok(match self.part {
            KneePart::Rotor => drive.screw_ratio() * c.l_q,
            KneePart::Housing | KneePart::Nut => 0.0,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanism::knee::{KneeDrive, KneeDriveParams};
    use crate::mechanism::Coupling;

    /// The cached fast path equals the jet reference part by part (to round-off), across drives
    /// (tilt on and off: misses on a different drive) and inputs; hits are bit-for-bit repeats;
    /// spin rows equal the reference's z rows with and without the cache.
    #[test]
    fn cached_relative_equals_motion() {
        let tilt = KneeDrive::new(KneeDriveParams::default()).expect("default drive");
        let fixed = KneeDrive::new(KneeDriveParams {
            screw_tilt: false,
            ..KneeDriveParams::default()
        })
        .expect("fixed-axis drive");
        let mut cache = None;
        for (q, qd) in [(0.4, 0.3), (0.4, -0.2), (1.1, 0.0), (-0.05, 2.0)] {
            for drive in [tilt, fixed] {
                for part in [KneePart::Housing, KneePart::Nut, KneePart::Rotor] {
                    let c = drive.part(part);
                    let fast = c.relative_cached(&[q], &[qd], &mut cache).expect("cached");
                    let again = c.relative_cached(&[q], &[qd], &mut cache).expect("hit");
                    assert_eq!(fast, again);
                    let slow =
                        RelativeMotion::from_coupled(&c.motion(&[q], &[qd]).expect("motion"));
                    // The rotor angle N_screw l (N_screw ~ 1257 rad/m) amplifies the round-off of l.
                    assert!((fast.rot - slow.rot).amax() < 1e-13);
                    assert!((fast.pos - slow.pos).amax() < 1e-15);
                    let tol = 1e-12 * (1.0 + slow.bias.amax());
                    assert!(
                        (fast.bias - slow.bias).amax() < tol,
                        "{part:?} {fast:?} {slow:?}"
                    );
                    let (a, b) = (fast.jacobian[0], slow.jacobian[0]);
                    assert!((a - b).amax() < 1e-12 * (1.0 + b.amax()), "{part:?}");
                    for cached in [cache.as_ref(), None] {
                        let row = c.spin_row_cached(&[q], cached).expect("row");
                        assert!((row - b[2]).abs() < 1e-12 * (1.0 + b[2].abs()));
                    }
                }
            }
        }
        let c = tilt.part(KneePart::Nut);
        assert!(c.relative_cached(&[f64::NAN], &[0.0], &mut cache).is_err());
        // A stored angle with a bad velocity or extra inputs is an error, not a cache hit.
        let q = -0.05;
        assert!(c.relative_cached(&[q], &[2.0], &mut cache).is_ok());
        for qd in [f64::NAN, f64::INFINITY] {
            assert!(c.relative_cached(&[q], &[qd], &mut cache).is_err());
        }
        assert!(c.relative_cached(&[q, q], &[2.0], &mut cache).is_err());
        assert!(c.relative_cached(&[q], &[], &mut cache).is_err());
        assert!(c.spin_row_cached(&[0.1, 0.2], cache.as_ref()).is_err());
    }
}
