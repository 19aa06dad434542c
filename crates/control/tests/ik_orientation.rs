//! Appendix C: angle-axis orientation error (C.1) and Euler Z-X-Z relations (C.3)-(C.6),
//! checked against independent constructions (nalgebra axis-angle rotations, elementary
//! rotation products, finite differences).

use biped_control::ik::orientation::{
    euler_zxz_angles, euler_zxz_matrix, euler_zxz_rate_matrix, euler_zxz_rates, orientation_error,
    rotation_log,
};
use nalgebra::{Matrix3, Rotation3, Vector3};
use proptest::prelude::*;

fn rot(v: Vector3<f64>) -> Matrix3<f64> {
    Rotation3::from_scaled_axis(v).into_inner()
}

proptest! {
    #[test]
    fn error_recovers_the_applied_rotation(
        a in prop::array::uniform3(-1.0f64..1.0), b in prop::array::uniform3(-1.0f64..1.0), s in 1e-9f64..3.0
    ) {
        let axis = Vector3::from(a);
        prop_assume!(axis.norm() > 1e-3);
        let dx = axis.normalize() * s;
        let current = rot(Vector3::from(b));
        // A_d = exp([dx]x) A  =>  Delta x_rot = gamma e_e = dx (C.1)
        let desired = rot(dx) * current;
        let e = orientation_error(&desired, &current);
        prop_assert!((e - dx).norm() < 1e-9 * (1.0 + s), "{e} vs {dx}");
        // Swapping desired and current reverses the error in the reference frame.
        let back = orientation_error(&current, &desired);
        prop_assert!((back + dx).norm() < 1e-9 * (1.0 + s));
    }

    #[test]
    fn euler_zxz_matrix_is_the_elementary_product_and_angles_round_trip(
        phi in -3.0f64..3.0, theta in 0.05f64..3.05, psi in -3.0f64..3.0
    ) {
        let rz = |a: f64| Rotation3::from_axis_angle(&Vector3::z_axis(), a).into_inner();
        let rx = |a: f64| Rotation3::from_axis_angle(&Vector3::x_axis(), a).into_inner();
        let a = euler_zxz_matrix(phi, theta, psi);
        prop_assert!((a - rz(phi) * rx(theta) * rz(psi)).norm() < 1e-12);
        let (p2, t2, s2) = euler_zxz_angles(&a);
        prop_assert!((euler_zxz_matrix(p2, t2, s2) - a).norm() < 1e-12);
        prop_assert!((t2 - theta).abs() < 1e-9 && (p2 - phi).abs() < 1e-9 && (s2 - psi).abs() < 1e-9);
    }

    #[test]
    fn rate_matrix_maps_euler_rates_to_angular_velocity(
        phi in -3.0f64..3.0, theta in 0.2f64..2.9, psi in -3.0f64..3.0, r in prop::array::uniform3(-1.0f64..1.0)
    ) {
        // omega from finite differences: [omega]x = dA/dt A^T (reference frame I).
        let rates = Vector3::from(r);
        let h = 1e-6;
        let ap = euler_zxz_matrix(phi + h * rates.x, theta + h * rates.y, psi + h * rates.z);
        let am = euler_zxz_matrix(phi - h * rates.x, theta - h * rates.y, psi - h * rates.z);
        let a = euler_zxz_matrix(phi, theta, psi);
        let w = (ap - am) / (2.0 * h) * a.transpose();
        let omega = Vector3::new(w[(2, 1)], w[(0, 2)], w[(1, 0)]);
        prop_assert!((euler_zxz_rate_matrix(phi, theta) * rates - omega).norm() < 1e-7);
        let back = euler_zxz_rates(phi, theta, &omega).unwrap();
        prop_assert!((back - rates).norm() < 1e-6);
    }
}

#[test]
fn printed_c6_is_inconsistent_with_c5_and_body_frame_inverse_is_derived() {
    // (C.6) contains psi, so it cannot be the inverse of T(phi, theta) of (C.5). The inverse
    // for the body-frame omega_B = A^T omega is (derived by hand)
    // 1/s(theta) [[s psi, c psi, 0], [c psi s theta, -s psi s theta, 0],
    //             [-s psi c theta, -c psi c theta, s theta]];
    // the printed (C.6) has the rows in reverse order and the omega_y signs flipped (typo).
    let (phi, theta, psi) = (0.4f64, 1.1f64, -0.7f64);
    let rates = Vector3::new(0.3, -0.5, 0.8);
    let omega = euler_zxz_rate_matrix(phi, theta) * rates;
    let omega_b = euler_zxz_matrix(phi, theta, psi).transpose() * omega;
    let (sp, cp, st, ct) = (psi.sin(), psi.cos(), theta.sin(), theta.cos());
    let derived = Matrix3::new(sp, cp, 0.0, cp * st, -sp * st, 0.0, -sp * ct, -cp * ct, st) / st;
    assert!((derived * omega_b - rates).norm() < 1e-12);
    let printed = Matrix3::new(-sp * ct, cp * ct, st, cp * st, sp * st, 0.0, sp, -cp, 0.0) / st;
    assert!((printed * omega - rates).norm() > 0.1);
    assert!((printed * omega_b - rates).norm() > 0.1);
    assert!(
        euler_zxz_rates(phi, 0.0, &omega).is_none(),
        "singular at sin(theta) = 0"
    );
}

#[test]
fn log_is_accurate_for_tiny_and_near_pi_angles() {
    let small = Vector3::new(1e-9, -2e-9, 3e-10);
    assert!((rotation_log(&rot(small)) - small).norm() < 1e-22);
    let big = Vector3::new(0.0, 0.6, 0.8) * (std::f64::consts::PI - 1e-6);
    let l = rotation_log(&rot(big));
    assert!((l - big).norm() < 1e-6, "{l}");
    assert!(rotation_log(&Matrix3::identity()).norm() == 0.0);
}
