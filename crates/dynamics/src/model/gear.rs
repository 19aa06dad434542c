//! Elastic gears: a joint whose motor is a coordinate of its own, coupled to the link through a
//! spring (thesis Table 2.3, Lola Type 3), described by the indices of both coordinates.

/// An elastic gear: the link joint's and the motor's coordinates and the ratio between them.
#[derive(Debug, Clone, PartialEq)]
pub struct ElasticGear {
    /// Link joint name.
    pub joint: String,
    /// Link coordinate index (q and v).
    pub link_q: usize,
    /// Link velocity index.
    pub link_v: usize,
    /// Motor coordinate index in `q`.
    pub motor_q: usize,
    /// Motor velocity index.
    pub motor_v: usize,
    /// Gear ratio `N` (motor angle = `N` link angle when the gear is unloaded).
    pub ratio: f64,
}
