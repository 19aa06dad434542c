//! The distance functions of Table 6.1 (6.4.1-6.4.6) and the dispatch over [`Ssv`].

use crate::primitives::{Lss, Pss, Ssv, Tss};
use crate::result::DistanceResult;

/// PP: point to point, eq. (6.12).
pub fn pp(a: &Pss, b: &Pss) -> DistanceResult {
    let _ = (a, b);
    todo!("helper S1")
}
/// PL: point to line segment, eqs. (6.13)-(6.17).
pub fn pl(a: &Pss, b: &Lss) -> DistanceResult {
    let _ = (a, b);
    todo!("helper S1")
}
/// PT: point to triangle, Table 6.2.
pub fn pt(a: &Pss, b: &Tss) -> DistanceResult {
    let _ = (a, b);
    todo!("helper S1")
}
/// LL: line segment to line segment (6.4.4).
pub fn ll(a: &Lss, b: &Lss) -> DistanceResult {
    let _ = (a, b);
    todo!("helper S1")
}
/// LT: line segment to triangle (6.4.5).
pub fn lt(a: &Lss, b: &Tss) -> DistanceResult {
    let _ = (a, b);
    todo!("helper S1")
}
/// TT: triangle to triangle (6.4.6).
pub fn tt(a: &Tss, b: &Tss) -> DistanceResult {
    let _ = (a, b);
    todo!("helper S1")
}

/// Distance between any two SSVs; the lower-triangle pairs of Table 6.1 use the swap relation.
#[inline]
pub fn distance(a: &Ssv, b: &Ssv) -> DistanceResult {
    match (a, b) {
        (Ssv::Point(a), Ssv::Point(b)) => pp(a, b),
        (Ssv::Point(a), Ssv::Line(b)) => pl(a, b),
        (Ssv::Point(a), Ssv::Triangle(b)) => pt(a, b),
        (Ssv::Line(a), Ssv::Point(b)) => pl(b, a).swapped(),
        (Ssv::Line(a), Ssv::Line(b)) => ll(a, b),
        (Ssv::Line(a), Ssv::Triangle(b)) => lt(a, b),
        (Ssv::Triangle(a), Ssv::Point(b)) => pt(b, a).swapped(),
        (Ssv::Triangle(a), Ssv::Line(b)) => lt(b, a).swapped(),
        (Ssv::Triangle(a), Ssv::Triangle(b)) => tt(a, b),
    }
}
