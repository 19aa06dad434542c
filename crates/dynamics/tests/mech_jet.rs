//! The jet engine behind the mechanisms: partials, first and second time derivatives of
//! composed scalar and vector expressions against central finite differences.

use biped_dynamics::mechanism::jet::{seed_inputs, SJet, VJet};
use nalgebra::{Matrix3, Vector3};
use proptest::prelude::*;

/// A scalar expression using every scalar operation.
fn scalar(q: &[SJet<2>; 2]) -> SJet<2> {
    let a = (q[0].sin() * q[1].cos() + SJet::constant(0.1))
        .scale(0.5)
        .acos();
    let b = (q[0] * q[0] + SJet::constant(1.0)).sqrt().recip();
    a * b - q[1].cos() * q[0]
}

/// A vector expression using every vector operation.
fn vector(q: &[SJet<2>; 2]) -> VJet<2> {
    let m = Matrix3::new(1.0, 0.2, 0.0, -0.1, 0.9, 0.3, 0.0, 0.4, 1.1);
    let a = VJet::constant(Vector3::new(0.3, -0.2, 0.5))
        .rotate(&Vector3::x_axis(), q[1])
        .rotate(&Vector3::y_axis(), q[0])
        .offset(&Vector3::new(0.1, 0.0, -0.4));
    let b = a.transform(&m).scale(q[0]) - VJet::constant(Vector3::z());
    let c = (a.cross(&b) + VJet::constant(Vector3::new(5.0, 0.0, 0.0))).normalize()
        + a.scale(a.dot(&b));
    c.scale(c.dot_const(&Vector3::new(1.0, 2.0, 3.0)).sin())
}

fn at(q: [f64; 2], qd: [f64; 2], t: f64) -> [SJet<2>; 2] {
    seed_inputs::<2>("test", &[q[0] + qd[0] * t, q[1] + qd[1] * t], &qd).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]
    #[test]
    fn scalar_jets_match_finite_differences(
        q0 in -1.0..1.0f64, q1 in -1.0..1.0f64, qd0 in -2.0..2.0f64, qd1 in -2.0..2.0f64,
    ) {
        let (q, qd, h) = ([q0, q1], [qd0, qd1], 1e-5);
        let f = scalar(&at(q, qd, 0.0));
        let (fp, fm) = (scalar(&at(q, qd, h)).v, scalar(&at(q, qd, -h)).v);
        prop_assert!((f.vel - (fp - fm) / (2.0 * h)).abs() < 1e-8);
        prop_assert!((f.vel - (f.d[0] * qd0 + f.d[1] * qd1)).abs() < 1e-14);
        prop_assert!((f.acc - (fp - 2.0 * f.v + fm) / (h * h)).abs() < 1e-4);
        let fv = |t: f64| scalar(&at(q, qd, t)).vel;
        prop_assert!((f.acc - (fv(h) - fv(-h)) / (2.0 * h)).abs() < 1e-8);
    }

    #[test]
    fn vector_jets_match_finite_differences(
        q0 in -1.0..1.0f64, q1 in -1.0..1.0f64, qd0 in -2.0..2.0f64, qd1 in -2.0..2.0f64,
    ) {
        let (q, qd, h) = ([q0, q1], [qd0, qd1], 1e-5);
        let f = vector(&at(q, qd, 0.0));
        let (fp, fm) = (vector(&at(q, qd, h)), vector(&at(q, qd, -h)));
        let fd1 = (fp.v - fm.v) / (2.0 * h);
        prop_assert!((f.vel - fd1).amax() < 1e-7 * (1.0 + fd1.amax()));
        prop_assert!((f.vel - (f.d[0] * qd0 + f.d[1] * qd1)).amax() < 1e-13);
        let fd2 = (fp.vel - fm.vel) / (2.0 * h);
        prop_assert!((f.acc - fd2).amax() < 1e-7 * (1.0 + fd2.amax()));
    }
}
