//! Cached fast path of the ankle parts: the slider-crank loops of the last kinematics pass
//! ([`AnkleLoop`]) shared by the parts of one actuator and read back as motor rows.

use super::closure::{trig, Closure};
use super::{AnkleCoupling, AnklePart, SliderCrank, NAME};
use crate::mechanism::cache::LoopSlots;
use crate::mechanism::jet::input_arrays;
use crate::mechanism::{AxialMotion, CoupledMotion, MechanismError, RelativeMotion};

/// Closed slider-crank loops of the last kinematics pass, keyed by crank identity and exact
/// inputs (see [`crate::mechanism::cache`]): the three parts (nut, rotor, rod) of one actuator share one
/// loop closure (3.23)-(3.29), the two actuators of one ankle share the sines and cosines, and
/// [`crate::Data::coupled_spin_row`] reads the motor rows back.
#[derive(Debug, Clone, Copy)]
pub struct AnkleLoop {
    slots: LoopSlots<AnkleKey, Closure>,
    /// Ankle angles of the last loop closure and their sines and cosines ([`trig`]).
    trig: ([f64; 2], [f64; 4]),
}

impl AnkleLoop {
    /// Closes `crank`'s loop at `(q, qd)` (reusing the sines and cosines of the last closure at
    /// the same ankle angles) and stores it.
    #[inline(never)]
    fn close(
        &mut self,
        crank: &SliderCrank,
        q: [f64; 2],
        qd: [f64; 2],
    ) -> Result<&Closure, MechanismError> {
        if self.trig.0 != q {
            self.trig = (q, trig(q));
        }
        let (key, trig) = (
            AnkleKey {
                id: crank.id,
                q,
                qd,
            },
            self.trig.1,
        );
        self.slots
            .store_with(key, |c| crank.solve_into(q, trig, qd, c))
    }
}

impl Default for AnkleLoop {
    fn default() -> Self {
        Self {
            slots: LoopSlots::default(),
            trig: ([f64::NAN; 2], [0.0; 4]),
        }
    }
}

/// Identity of a closed loop: the crank's construction identity and its exact inputs.
#[derive(Debug, Clone, Copy)]
struct AnkleKey {
    id: u64,
    q: [f64; 2],
    qd: [f64; 2],
}

impl AnkleCoupling {
    /// Same result as [`crate::mechanism::Coupling::motion`], reusing `cache` when it holds this part's
    /// slider-crank closed at exactly the same `(q_in, qd_in)`, else closing the loop and
    /// storing it in `cache` for the actuator's next part.
    pub fn motion_cached(
        &self,
        q_in: &[f64],
        qd_in: &[f64],
        cache: &mut Option<AnkleLoop>,
    ) -> Result<CoupledMotion, MechanismError> {
        Ok(self.relative_cached(q_in, qd_in, cache)?.to_coupled())
    }

    /// [`Self::motion_cached`] as a [`RelativeMotion`] (no quaternion conversion).
    pub fn relative_cached(
        &self,
        q_in: &[f64],
        qd_in: &[f64],
        cache: &mut Option<AnkleLoop>,
    ) -> Result<RelativeMotion, MechanismError> {
        let closure = self.closure_cached(q_in, qd_in, cache)?;
        Ok(self.crank.part_motion(self.part, closure))
    }

    /// Spin of a rotor part (3.22) or travel of a nut (3.29) with their rates (3.32)-(3.33) at
    /// `(q_in, qd_in)`, from `cache` like [`Self::relative_cached`]; `None` for the rod.
    pub(crate) fn axial_motion_cached(
        &self,
        q_in: &[f64],
        qd_in: &[f64],
        cache: &mut Option<AnkleLoop>,
    ) -> Result<Option<AxialMotion>, MechanismError> {
        let (n, offset) = match self.part {
            AnklePart::Rotor => (self.crank.ratio, self.crank.act.motor_offset),
            AnklePart::Nut => (1.0, 0.0),
            AnklePart::Rod => return Ok(None),
        };
        let c = self.closure_cached(q_in, qd_in, cache)?;
        Ok(Some(AxialMotion {
            travel: n * c.l + offset,
            row: [n * c.l_q[0], n * c.l_q[1], 0.0],
            speed: n * c.l_dot,
            bias: n * c.l_acc,
        }))
    }

    /// This part's slider-crank closed at `(q_in, qd_in)`: from `cache` when it holds it, else
    /// closed and stored there.
    #[inline(always)]
    fn closure_cached<'c>(
        &self,
        q_in: &[f64],
        qd_in: &[f64],
        cache: &'c mut Option<AnkleLoop>,
    ) -> Result<&'c Closure, MechanismError> {
        let cache = cache.get_or_insert_with(AnkleLoop::default);
        let crank = &self.crank;
        // A hit needs no input validation: only validated (finite) inputs are stored, and a
        // NaN never compares equal to a stored key.
        if let (Ok(q), Ok(qd)) = (<[f64; 2]>::try_from(q_in), <[f64; 2]>::try_from(qd_in)) {
            let same = |a: [f64; 2], b: [f64; 2]| (a[0] == b[0]) & (a[1] == b[1]);
            let hit = |k: &AnkleKey| k.id == crank.id && same(k.q, q) && same(k.qd, qd);
            if let Some(i) = cache.slots.position(hit) {
                return Ok(cache.slots.value(i));
            }
        }
        let (q, qd) = input_arrays::<2>(NAME, q_in, qd_in)?;
        cache.close(crank, q, qd)
    }

    /// Part-frame z row of this part's relative Jacobian at `q_in` (for the rotor the motor
    /// row `N_screw dl/dq`, (3.22), (3.32)), from `cache` when it holds this crank closed at
    /// exactly `q_in`, else from a fresh loop closure.
    pub fn spin_row_cached(
        &self,
        q_in: &[f64],
        cache: Option<&AnkleLoop>,
    ) -> Result<[f64; 2], MechanismError> {
        let (q, _) = input_arrays::<2>(NAME, q_in, &[0.0; 2])?;
        let crank = &self.crank;
        let hit = cache.and_then(|c| c.slots.find(|k| k.id == crank.id && k.q == q));
        let fresh;
        let closure = match hit {
            Some(c) => c,
            None => {
                fresh = crank.solve(q, trig(q), [0.0; 2])?;
                &fresh
            }
        };
        if self.part == AnklePart::Rotor {
            return Ok(closure.l_q.map(|x| crank.ratio * x));
        }
        let m = crank.part_motion(self.part, closure);
        Ok([m.jacobian[0][2], m.jacobian[1][2]])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanism::ankle::{AnkleDrive, AnkleDriveParams};
    use crate::mechanism::Coupling;

    /// The cached fast path equals the jet reference part by part (to round-off), across
    /// actuators (misses on a different crank) and inputs (misses on different `q` or `qd`);
    /// hits return the stored loop bit for bit; the spin rows equal the reference's z rows.
    #[test]
    fn cached_motion_equals_motion() {
        let drive = AnkleDrive::new(AnkleDriveParams::default()).expect("default drive");
        let mut cache = None;
        for (q, qd) in [
            ([0.1, -0.05], [0.3, 0.2]),
            ([0.1, -0.05], [0.3, 0.1]),
            ([0.0, 0.1], [0.0, 0.0]),
        ] {
            for act in 0..2 {
                for part in [AnklePart::Nut, AnklePart::Rotor, AnklePart::Rod] {
                    let c = drive.part(act, part).expect("part");
                    let fast = c.relative_cached(&q, &qd, &mut cache).expect("cached");
                    let again = c.relative_cached(&q, &qd, &mut cache).expect("hit");
                    assert_eq!(fast, again);
                    let slow = RelativeMotion::from_coupled(&c.motion(&q, &qd).expect("motion"));
                    // The rotor angle N_screw l (N_screw ~ 1257 rad/m) amplifies the round-off of l.
                    assert!((fast.rot - slow.rot).amax() < 1e-13);
                    assert!((fast.pos - slow.pos).amax() < 1e-15);
                    assert!((fast.bias - slow.bias).amax() < 1e-11 * (1.0 + slow.bias.amax()));
                    for (a, b) in fast.jacobian.iter().zip(&slow.jacobian) {
                        assert!((a - b).amax() < 1e-12 * (1.0 + b.amax()));
                    }
                    for cached in [cache.as_ref(), None] {
                        let row = c.spin_row_cached(&q, cached).expect("row");
                        for (r, col) in row.iter().zip(&slow.jacobian) {
                            assert!((r - col[2]).abs() < 1e-12 * (1.0 + col[2].abs()));
                        }
                    }
                }
            }
        }
        let c = drive.part(0, AnklePart::Rod).expect("part");
        assert!(c
            .relative_cached(&[f64::NAN, 0.0], &[0.0; 2], &mut cache)
            .is_err());
        // Stored angles with a bad velocity or wrong lengths are errors, not cache hits.
        let (q, qd) = ([0.0, 0.1], [0.0, 0.0]);
        assert!(c.relative_cached(&q, &qd, &mut cache).is_ok());
        for bad in [[f64::NAN, 0.0], [0.0, f64::INFINITY]] {
            assert!(c.relative_cached(&q, &bad, &mut cache).is_err());
        }
        assert!(c
            .relative_cached(&[0.0, 0.1, 0.2], &qd, &mut cache)
            .is_err());
        assert!(c.relative_cached(&q, &[0.0], &mut cache).is_err());
        assert!(c.spin_row_cached(&[0.0], cache.as_ref()).is_err());
    }
}
