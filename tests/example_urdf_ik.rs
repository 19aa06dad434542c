//! `examples/urdf_ik.rs` runs as written and reaches its target inside the joint limits (its
//! `main` checks both by forward kinematics).

#[path = "../examples/urdf_ik.rs"]
mod urdf_ik;

#[test]
fn urdf_ik_example_reaches_its_target() {
    urdf_ik::main().unwrap();
}
