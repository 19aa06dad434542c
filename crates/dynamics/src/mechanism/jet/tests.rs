use super::*;
use proptest::prelude::*;

proptest! {
    /// The constant-vector fast path equals the general rotation of a constant jet.
    #[test]
    fn rotate_constant_equals_rotate(
        c in prop::array::uniform3(-2.0..2.0f64), k in prop::array::uniform3(-1.0..1.0f64),
        q in prop::array::uniform2(-3.0..3.0f64), qd in prop::array::uniform2(-3.0..3.0f64),
    ) {
        let k = Vector3::from(k);
        prop_assume!(k.norm() > 1e-3);
        let axis = Unit::new_normalize(k);
        let qj = seed_inputs::<2>("test", &q, &qd).expect("finite");
        let angle = qj[0] * qj[1].sin();
        prop_assert_eq!(angle.sin_cos(), (angle.sin(), angle.cos()));
        let c = Vector3::from(c);
        let fast = VJet::rotate_constant(&c, &axis, angle);
        let slow = VJet::constant(c).rotate(&axis, angle);
        let close = |a: &Vector3<f64>, b: &Vector3<f64>| (a - b).amax() <= 1e-13 * (1.0 + b.amax());
        prop_assert!(close(&fast.v, &slow.v));
        prop_assert!(close(&fast.vel, &slow.vel) && close(&fast.acc, &slow.acc));
        prop_assert!(close(&fast.d[0], &slow.d[0]) && close(&fast.d[1], &slow.d[1]));
    }
}
