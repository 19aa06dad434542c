//! The closed-form fast path of the ankle and knee mechanisms (`relative_cached`, used by the
//! kinematics) on random geometries and states: against central finite differences of its own
//! poses (like the jet reference in `mech_ankle.rs` / `mech_knee.rs`), against the jet reference
//! [`Coupling::motion`] to round-off, and a warm shared cache against a cold one bit for bit.

mod mech_support;

use biped_dynamics::mechanism::ankle::{AnkleCoupling, AnkleDrive, AnkleDriveParams, AnklePart};
use biped_dynamics::mechanism::knee::{KneeCoupling, KneeDrive, KneeDriveParams, KneePart};
use biped_dynamics::mechanism::{
    CoupledMotion, Coupling, MechanismError, RelativeMotion, MAX_COUPLED,
};
use mech_support::check_coupling;
use nalgebra::Vector3;
use proptest::prelude::*;

/// The fast path of an ankle part behind the [`Coupling`] interface (cold cache per call).
struct FastAnkle(AnkleCoupling);

impl Coupling for FastAnkle {
    fn n_inputs(&self) -> usize {
        2
    }
    fn motion(&self, q: &[f64], qd: &[f64]) -> Result<CoupledMotion, MechanismError> {
        Ok(self.0.relative_cached(q, qd, &mut None)?.to_coupled())
    }
}

/// The fast path of a knee part behind the [`Coupling`] interface (cold cache per call).
struct FastKnee(KneeCoupling);

impl Coupling for FastKnee {
    fn n_inputs(&self) -> usize {
        1
    }
    fn motion(&self, q: &[f64], qd: &[f64]) -> Result<CoupledMotion, MechanismError> {
        Ok(self.0.relative_cached(q, qd, &mut None)?.to_coupled())
    }
}

/// `fast ~ reference` to round-off (rotation, origin, Jacobian columns, bias).
fn assert_round_off(fast: &RelativeMotion, reference: &CoupledMotion) {
    let slow = RelativeMotion::from_coupled(reference);
    // Rotor angles N_screw l (N_screw ~ 1257 rad/m, hundreds of rad) carry the round-off of
    // l times N_screw: a few ulp of the angle.
    let drot = (fast.rot - slow.rot).amax();
    assert!(drot < 1e-12, "rot {drot:e}");
    assert!((fast.pos - slow.pos).amax() < 1e-14, "pos");
    for k in 0..MAX_COUPLED {
        let (a, b) = (fast.jacobian[k], slow.jacobian[k]);
        assert!(
            (a - b).amax() <= 1e-11 * (1.0 + b.amax()),
            "J col {k}: {a} vs {b}"
        );
    }
    let (a, b) = (fast.bias, slow.bias);
    assert!(
        (a - b).amax() <= 1e-10 * (1.0 + b.amax()),
        "bias: {a} vs {b}"
    );
}

const ANKLE_PARTS: [AnklePart; 3] = [AnklePart::Nut, AnklePart::Rotor, AnklePart::Rod];
const KNEE_PARTS: [KneePart; 3] = [KneePart::Housing, KneePart::Nut, KneePart::Rotor];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]
    #[test]
    fn ankle_fast_path_matches_reference_and_finite_differences(
        dx in -0.03..0.03f64, dy in -0.01..0.01f64, ex in -0.2..0.2f64, ey in -0.2..0.2f64,
        fz in -0.02..0.05f64, rod in 0.15..0.25f64, off in -3.0..3.0f64,
        q0 in -0.3..0.3f64, q1 in -0.2..0.2f64, qd0 in -3.0..3.0f64, qd1 in -3.0..3.0f64,
    ) {
        let mut p = AnkleDriveParams::default();
        p.actuators[0].screw_top += Vector3::new(dx, dy, 0.0);
        p.actuators[0].screw_axis = Vector3::new(ex, ey, -1.0);
        p.actuators[0].motor_offset = off;
        p.actuators[1].foot_ball.z = fz;
        p.actuators[1].rod_length = rod;
        p.q_min = [-0.3, -0.2];
        p.q_max = [0.3, 0.2];
        let Ok(d) = AnkleDrive::new(p) else { return Ok(()) };
        let (q, qd) = ([q0, q1], [qd0, qd1]);
        let mut warm = None;
        for i in 0..2 {
            for part in ANKLE_PARTS {
                let c = d.part(i, part).unwrap();
                check_coupling(&FastAnkle(c), &q, &qd, 1e-6);
                let fast = c.relative_cached(&q, &qd, &mut warm).unwrap();
                prop_assert_eq!(fast, c.relative_cached(&q, &qd, &mut None).unwrap());
                assert_round_off(&fast, &c.motion(&q, &qd).unwrap());
            }
        }
    }

    #[test]
    fn knee_fast_path_matches_reference_and_finite_differences(
        bx in -0.06..-0.02f64, by in 0.25..0.35f64, ax in -0.06..-0.03f64, ay in 0.02..0.05f64,
        off in -3.0..3.0f64, tilt: bool, t in 0.0..1.0f64, qd in -4.0..4.0f64,
    ) {
        let params = KneeDriveParams {
            pivot_thigh: nalgebra::Vector2::new(bx, by),
            pin_shank: nalgebra::Vector2::new(ax, ay),
            motor_offset: off,
            screw_tilt: tilt,
            ..KneeDriveParams::default()
        };
        let Ok(d) = KneeDrive::new(params) else { return Ok(()) };
        let q = params.q_min + (params.q_max - params.q_min) * t;
        let mut warm = None;
        for part in KNEE_PARTS {
            let c = d.part(part);
            check_coupling(&FastKnee(c), &[q], &[qd], 1e-6);
            let fast = c.relative_cached(&[q], &[qd], &mut warm).unwrap();
            prop_assert_eq!(fast, c.relative_cached(&[q], &[qd], &mut None).unwrap());
            assert_round_off(&fast, &c.motion(&[q], &[qd]).unwrap());
        }
    }
}

/// One cache shared by two ankles and two knees (more loops than slots, interleaved like a
/// kinematics pass over two legs at two states) returns exactly the cold-cache results.
#[test]
fn shared_caches_never_mix_drives() {
    let ankles = [0.0, 0.01].map(|dy| {
        let mut p = AnkleDriveParams::default();
        p.actuators[0].screw_top.y += dy;
        AnkleDrive::new(p).unwrap()
    });
    let knees = [0.3, 0.31].map(|y| {
        KneeDrive::new(KneeDriveParams {
            pivot_thigh: nalgebra::Vector2::new(-0.04, y),
            ..KneeDriveParams::default()
        })
        .unwrap()
    });
    let (mut ac, mut kc) = (None, None);
    for (q, qd) in [
        ([0.1, -0.05], [0.3, 0.2]),
        ([0.1, -0.05], [0.3, 0.2]),
        ([0.2, 0.1], [0.0, 1.0]),
    ] {
        for (a, k) in ankles.iter().zip(&knees) {
            for part in KNEE_PARTS {
                let c = k.part(part);
                let warm = c.relative_cached(&q[..1], &qd[..1], &mut kc).unwrap();
                assert_eq!(
                    warm,
                    c.relative_cached(&q[..1], &qd[..1], &mut None).unwrap()
                );
            }
            for i in 0..2 {
                for part in ANKLE_PARTS {
                    let c = a.part(i, part).unwrap();
                    let warm = c.relative_cached(&q, &qd, &mut ac).unwrap();
                    assert_eq!(warm, c.relative_cached(&q, &qd, &mut None).unwrap());
                }
            }
        }
    }
}
