//! Shared test support: SSV pair generators (case families) and the full check of a
//! closed-form distance result against the KKT reference solver of `tests/reference`.
#![allow(dead_code)]

pub mod families;

use crate::reference;
use biped_ssv::distance::{ll, lt, pl, pp, pt, tt};
use biped_ssv::{DistanceResult, Lss, PrimitiveParam, Pss, Ssv, Tss};
use nalgebra::{Point3, Vector3};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

/// Kind of primitive of a generated SSV.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// PSS.
    P,
    /// LSS.
    L,
    /// TSS.
    T,
}

/// Random numbers of one shape: three vectors in [-1,1]^3 and six scalars in [0,1).
pub type Raw = ([f64; 9], [f64; 6]);

/// Builds an SSV pair of the given kinds from the raw numbers of a, b and a common part.
pub type Builder = fn(Kind, Kind, &Raw, &Raw, &Raw) -> (Ssv, Ssv);

/// Strategy for the raw numbers of one shape.
fn raw() -> impl Strategy<Value = Raw> {
    (
        prop::array::uniform9(-1.0..1.0f64),
        prop::array::uniform6(0.0..1.0f64),
    )
}

/// Strategy for SSV pairs of kinds `(ka, kb)` made by `build`.
pub fn pair(ka: Kind, kb: Kind, build: Builder) -> impl Strategy<Value = (Ssv, Ssv)> {
    (raw(), raw(), raw()).prop_map(move |(a, b, c)| build(ka, kb, &a, &b, &c))
}

/// Proptest configuration with `cases` cases, thorough shrinking, and no regression
/// files (minimal reproducers found this way become explicit tests instead).
pub fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        max_shrink_iters: 20_000,
        failure_persistence: None,
        ..ProptestConfig::with_cases(cases)
    }
}

/// The i-th raw vector.
pub fn vec3(raw: &Raw, i: usize) -> Vector3<f64> {
    Vector3::new(raw.0[3 * i], raw.0[3 * i + 1], raw.0[3 * i + 2])
}

/// 10^(lo + (hi - lo) s): log-uniform magnitude for s in [0, 1).
pub fn log_mag(s: f64, lo: f64, hi: f64) -> f64 {
    10f64.powf(lo + (hi - lo) * s)
}

/// An SSV of `kind` from the first 1-3 of `v` with radius `r` (inputs are valid).
pub fn make(kind: Kind, v: [Point3<f64>; 3], r: f64) -> Ssv {
    match kind {
        Kind::P => Pss::new(v[0], r).expect("valid PSS").into(),
        Kind::L => Lss::new(v[0], v[1], r).expect("valid LSS").into(),
        Kind::T => Tss::new(v[0], v[1], v[2], r).expect("valid TSS").into(),
    }
}

/// Test scale `max(1, largest |coordinate|, radii)`.
///
/// Why: every algorithm that forms differences of input coordinates of magnitude S makes
/// absolute rounding errors of order eps*S, however small the primitives are, so an error
/// bound must be relative to the largest coordinate (or radius, which enters d additively),
/// not to the distance. The floor 1 (one length unit, 1 m for robot models) stops tiny
/// configurations from demanding accuracy far below any physical meaning. With the bound
/// `1e-9 * scale` the closed forms have ~4.5e6 ulps of slack for conditioning (near-parallel
/// cases), yet any wrong branch or clamp produces errors of the size of the geometry itself.
pub fn scale(a: &Ssv, b: &Ssv) -> f64 {
    scale_from(1.0, a, b)
}

/// `max(floor, largest |coordinate|, radii)`; floor 0 gives a purely relative scale.
pub fn scale_from(floor: f64, a: &Ssv, b: &Ssv) -> f64 {
    a.vertices()
        .iter()
        .chain(b.vertices())
        .flat_map(|v| v.iter().copied())
        .chain([a.radius(), b.radius()])
        .fold(floor, |m, x| m.max(x.abs()))
}

/// Signed reference distance of (6.9): primitive distance by the KKT solver minus radii.
///
/// The reference is a feasible point evaluated exactly, so it is never below the true
/// minimum (up to rounding); since `check_result` also verifies that the closed-form
/// points are feasible and realise the returned distance, a closed form *above* the
/// reference is suboptimal, and one *below* it would expose a reference miss.
pub fn reference_distance(a: &Ssv, b: &Ssv) -> f64 {
    reference::closest(a.vertices(), b.vertices()).dist - a.radius() - b.radius()
}

/// The closed-form function of Table 6.1 for the pair (upper triangle called directly,
/// lower triangle through the swap relation).
pub fn typed(a: &Ssv, b: &Ssv) -> DistanceResult {
    match (a, b) {
        (Ssv::Point(a), Ssv::Point(b)) => pp(a, b),
        (Ssv::Point(a), Ssv::Line(b)) => pl(a, b),
        (Ssv::Point(a), Ssv::Triangle(b)) => pt(a, b),
        (Ssv::Line(a), Ssv::Line(b)) => ll(a, b),
        (Ssv::Line(a), Ssv::Triangle(b)) => lt(a, b),
        (Ssv::Triangle(a), Ssv::Triangle(b)) => tt(a, b),
        _ => typed(b, a).swapped(),
    }
}

/// Full check of one pair in both orders: reference distance, invariants, swap relation,
/// with the tolerance `1e-9 * scale(a, b)`.
pub fn check_pair(a: &Ssv, b: &Ssv) -> Result<(), TestCaseError> {
    check_pair_with(a, b, scale(a, b))
}

/// [`check_pair`] with a purely relative scale (no floor 1): tiny configurations must be
/// as accurate, relative to their size, as unit-size ones.
pub fn check_pair_relative(a: &Ssv, b: &Ssv) -> Result<(), TestCaseError> {
    check_pair_with(a, b, scale_from(0.0, a, b))
}

/// [`check_pair`] with tolerances relative to `scale`.
fn check_pair_with(a: &Ssv, b: &Ssv, scale: f64) -> Result<(), TestCaseError> {
    let d_ref = reference_distance(a, b);
    let tol = 1e-9 * scale;
    let ab = typed(a, b);
    check_result(a, b, &ab, d_ref, tol, scale)?;
    prop_assert!(
        ab == biped_ssv::distance(a, b),
        "dispatch differs for {a:?} {b:?}"
    );
    let ba = biped_ssv::distance(b, a);
    check_result(b, a, &ba, d_ref, tol, scale)?;
    let same_kind = std::mem::discriminant(a) == std::mem::discriminant(b);
    if same_kind {
        prop_assert!(
            (ba.distance - ab.distance).abs() <= tol,
            "swap: d(a,b) = {} but d(b,a) = {} for {a:?} {b:?}",
            ab.distance,
            ba.distance
        );
    } else {
        prop_assert!(ba == ab.swapped(), "swap relation broken for {a:?} {b:?}");
    }
    Ok(())
}

/// Whether every number of the result is finite.
fn all_finite(r: &DistanceResult) -> bool {
    let params = [r.param_a, r.param_b].into_iter().flat_map(|p| match p {
        PrimitiveParam::Point => vec![],
        PrimitiveParam::Line(s) => vec![s],
        PrimitiveParam::Triangle(s0, s1) => vec![s0, s1],
    });
    [r.point_a, r.point_b, r.closest_a, r.closest_b]
        .iter()
        .flat_map(|p| p.iter().copied())
        .chain(r.normal.iter().copied())
        .chain(params)
        .chain([r.distance])
        .all(f64::is_finite)
}

/// Tolerance on parameters leaving their domain (6.6).
const PARAM_TOL: f64 = 1e-12;

/// The point of `s` at `param`, or an error if the parameter kind or domain is wrong.
fn point_at(s: &Ssv, param: PrimitiveParam) -> Result<Point3<f64>, TestCaseError> {
    let lo = -PARAM_TOL;
    let hi = 1.0 + PARAM_TOL;
    match (s, param) {
        (Ssv::Point(p), PrimitiveParam::Point) => Ok(*p.center()),
        (Ssv::Line(l), PrimitiveParam::Line(t)) => {
            prop_assert!((lo..=hi).contains(&t), "line param {t} outside [0,1]");
            Ok(l.point_at(t))
        }
        (Ssv::Triangle(t), PrimitiveParam::Triangle(s0, s1)) => {
            prop_assert!(
                s0 >= lo && s1 >= lo && s0 + s1 <= hi,
                "triangle params ({s0}, {s1}) violate (6.6)"
            );
            Ok(t.point_at(s0, s1))
        }
        _ => Err(TestCaseError::fail(format!(
            "param kind {param:?} does not match primitive"
        ))),
    }
}

/// Checks one result of `dist(a, b)` against the reference and its own invariants.
pub fn check_result(
    a: &Ssv,
    b: &Ssv,
    r: &DistanceResult,
    d_ref: f64,
    tol: f64,
    scale: f64,
) -> Result<(), TestCaseError> {
    let ctx = || format!("\n a = {a:?}\n b = {b:?}\n result = {r:?}\n d_ref = {d_ref:?}");
    prop_assert!(all_finite(r), "non-finite output{}", ctx());
    prop_assert!(
        r.distance <= d_ref + tol,
        "closed form above the reference by {:e} (tol {tol:e}): not minimal{}",
        r.distance - d_ref,
        ctx()
    );
    prop_assert!(
        r.distance >= d_ref - tol,
        "closed form below the reference by {:e} (tol {tol:e}){}",
        d_ref - r.distance,
        ctx()
    );
    // Points on the primitives, at their parameters, and the surface points (6.11): pure
    // evaluation, so a tight tolerance (a draft TT once differed by 9e-12 here).
    let ftol = 1e-12 * scale;
    let on_a = point_at(a, r.param_a).map_err(|e| TestCaseError::fail(format!("{e}{}", ctx())))?;
    let on_b = point_at(b, r.param_b).map_err(|e| TestCaseError::fail(format!("{e}{}", ctx())))?;
    prop_assert!(
        (on_a - r.closest_a).norm() <= ftol,
        "closest_a != point_at(param_a){}",
        ctx()
    );
    prop_assert!(
        (on_b - r.closest_b).norm() <= ftol,
        "closest_b != point_at(param_b){}",
        ctx()
    );
    prop_assert!(
        (r.normal.norm() - 1.0).abs() <= 1e-12,
        "|normal| != 1{}",
        ctx()
    );
    let pa = r.closest_a + r.normal * a.radius();
    let pb = r.closest_b - r.normal * b.radius();
    prop_assert!(
        (pa - r.point_a).norm() <= ftol,
        "point_a != closest_a + r_a n{}",
        ctx()
    );
    prop_assert!(
        (pb - r.point_b).norm() <= ftol,
        "point_b != closest_b - r_b n{}",
        ctx()
    );
    // The returned closest points realise the returned distance, and n is along c*.
    let c = r.c_star();
    prop_assert!(
        (c.norm() - a.radius() - b.radius() - r.distance).abs() <= tol,
        "|c*| - r_a - r_b != distance{}",
        ctx()
    );
    prop_assert!(
        (c - r.normal * c.norm()).norm() <= tol,
        "normal not along c*{}",
        ctx()
    );
    Ok(())
}

/// One proptest per pair type for a case family: `pair_tests!(family, cases[, check])`
/// expands to tests `pp`, `pl`, `pt`, `ll`, `lt`, `tt`, each running `check` (default
/// `check_pair`) on `cases` cases (both argument orders, so LP, TP, TL are covered too).
macro_rules! pair_tests {
    ($family:path, $cases:expr) => {
        $crate::support::pair_tests!($family, $cases, $crate::support::check_pair);
    };
    ($family:path, $cases:expr, $check:path) => {
        use $crate::support::{config, pair, Kind};
        use proptest::prelude::*;
        $crate::support::pair_tests!(@each $family, $cases, $check,
            pp: P P, pl: P L, pt: P T, ll: L L, lt: L T, tt: T T);
    };
    (@each $family:path, $cases:expr, $check:path, $($name:ident: $ka:ident $kb:ident),*) => {
        proptest! {
            #![proptest_config(config($cases))]
            $(
                #[test]
                fn $name((a, b) in pair(Kind::$ka, Kind::$kb, $family)) {
                    $check(&a, &b)?;
                }
            )*
        }
    };
}
pub(crate) use pair_tests;
