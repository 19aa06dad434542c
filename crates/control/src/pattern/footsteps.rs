//! Footstep planner for straight, sideways and turning walks.
//!
//! Each step places the swing foot relative to the stance foot (stance sole frame):
//! `(step_length, +-step_width + side, turn_angle)`, where `side = step_sideways` when the
//! swing foot is the one on the side of the lateral motion and 0 otherwise (the leading foot
//! steps out, the trailing foot closes to the nominal width). The first step is therefore a
//! half step (the foot travels `step_length`, later ones `2 step_length`), and the last step
//! closes the feet side by side and parallel: `(0, +-step_width, 0)`. The first swing foot
//! is the one on the side of the motion (sideways motion first, then the turn; left when
//! walking straight). Yaw angles are kept continuous (not wrapped).

use super::{FootGeometry, PatternError, PatternParams};
use nalgebra::{Isometry3, Point2, Rotation2, Translation3, UnitQuaternion, Vector2};
use serde::{Deserialize, Serialize};

/// Which foot.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Foot {
    /// Left foot (index 0).
    Left,
    /// Right foot (index 1).
    Right,
}

impl Foot {
    /// Index 0 (left) or 1 (right).
    pub fn index(self) -> usize {
        match self {
            Foot::Left => 0,
            Foot::Right => 1,
        }
    }
    /// The other foot.
    pub fn other(self) -> Foot {
        match self {
            Foot::Left => Foot::Right,
            Foot::Right => Foot::Left,
        }
    }
    /// Lateral sign: +1 left, -1 right.
    pub fn sign(self) -> f64 {
        match self {
            Foot::Left => 1.0,
            Foot::Right => -1.0,
        }
    }
}

/// Planar pose of a sole frame on the ground: position and yaw.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Pose2 {
    /// x \[m].
    pub x: f64,
    /// y \[m].
    pub y: f64,
    /// Yaw about the vertical \[rad] (continuous, not wrapped).
    pub yaw: f64,
}

impl Pose2 {
    /// Pose of `(dx, dy, dyaw)` given in this pose's frame.
    pub fn compose(&self, dx: f64, dy: f64, dyaw: f64) -> Pose2 {
        let (s, c) = self.yaw.sin_cos();
        Pose2 {
            x: self.x + c * dx - s * dy,
            y: self.y + s * dx + c * dy,
            yaw: self.yaw + dyaw,
        }
    }
    /// Position as a 2-vector.
    pub fn position(&self) -> Vector2<f64> {
        Vector2::new(self.x, self.y)
    }
    /// World point of a point `(px, py)` of this frame.
    pub fn point(&self, px: f64, py: f64) -> Point2<f64> {
        let p = self.compose(px, py, 0.0);
        Point2::new(p.x, p.y)
    }
    /// Point `p` expressed in this frame.
    pub fn to_local(&self, p: &Vector2<f64>) -> Vector2<f64> {
        Rotation2::new(-self.yaw) * (p - self.position())
    }
    /// The 3D sole pose on the ground plane `z = height`.
    pub fn isometry(&self, height: f64) -> Isometry3<f64> {
        Isometry3::from_parts(
            Translation3::new(self.x, self.y, height),
            UnitQuaternion::from_euler_angles(0.0, 0.0, self.yaw),
        )
    }
}

/// One step: the swing foot moves from `from` to `to` while the other foot stands.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Footstep {
    /// The swing foot.
    pub foot: Foot,
    /// Its sole pose at lift-off.
    pub from: Pose2,
    /// Its sole pose at touch-down.
    pub to: Pose2,
}

/// The planned footsteps of a walk.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FootstepPlan {
    /// Initial sole poses `[left, right]` (standing, centred on the world origin).
    pub initial: [Pose2; 2],
    /// The steps in order.
    pub steps: Vec<Footstep>,
}

impl FootstepPlan {
    /// Plans the footsteps of `params` (validated first); rejects overlapping feet.
    pub fn new(params: &PatternParams) -> Result<FootstepPlan, PatternError> {
        params.validate()?;
        let half = 0.5 * params.step_width;
        let mut feet = [
            Pose2 {
                x: 0.0,
                y: half,
                yaw: 0.0,
            },
            Pose2 {
                x: 0.0,
                y: -half,
                yaw: 0.0,
            },
        ];
        let plan_initial = feet;
        check_overlap(&feet, &params.foot, 0)?;
        let mut swing = first_swing(params);
        let mut steps = Vec::with_capacity(params.n_steps);
        for k in 1..=params.n_steps {
            let stance = feet[swing.other().index()];
            let s = swing.sign();
            let to = if k == params.n_steps {
                stance.compose(0.0, s * params.step_width, 0.0)
            } else {
                let side = if s * params.step_sideways > 0.0 {
                    params.step_sideways
                } else {
                    0.0
                };
                stance.compose(
                    params.step_length,
                    s * params.step_width + side,
                    params.turn_angle,
                )
            };
            steps.push(Footstep {
                foot: swing,
                from: feet[swing.index()],
                to,
            });
            feet[swing.index()] = to;
            check_overlap(&feet, &params.foot, k)?;
            swing = swing.other();
        }
        Ok(FootstepPlan {
            initial: plan_initial,
            steps,
        })
    }

    /// Sole poses `[left, right]` after `k` steps (`k = 0`: initial stance).
    pub fn stance_after(&self, k: usize) -> [Pose2; 2] {
        let mut feet = self.initial;
        for s in self.steps.iter().take(k) {
            feet[s.foot.index()] = s.to;
        }
        feet
    }
}

/// First swing foot: towards the sideways motion, else towards the turn, else left.
fn first_swing(p: &PatternParams) -> Foot {
    let cue = if p.step_sideways != 0.0 {
        p.step_sideways
    } else {
        p.turn_angle
    };
    if cue < 0.0 {
        Foot::Right
    } else {
        Foot::Left
    }
}

/// Corners of a foot rectangle in world coordinates.
pub fn foot_corners(pose: &Pose2, foot: &FootGeometry) -> [Point2<f64>; 4] {
    let (f, b, w) = (foot.front, foot.back, foot.half_width);
    [
        pose.point(f, w),
        pose.point(-b, w),
        pose.point(-b, -w),
        pose.point(f, -w),
    ]
}

/// Whether two oriented foot rectangles overlap (separating-axis test on 4 axes).
pub fn feet_overlap(a: &Pose2, b: &Pose2, foot: &FootGeometry) -> bool {
    let (ca, cb) = (foot_corners(a, foot), foot_corners(b, foot));
    let axes = [
        a.yaw,
        a.yaw + std::f64::consts::FRAC_PI_2,
        b.yaw,
        b.yaw + std::f64::consts::FRAC_PI_2,
    ];
    axes.iter().all(|&ang| {
        let n = Vector2::new(ang.cos(), ang.sin());
        let proj = |c: &[Point2<f64>; 4]| {
            c.iter().fold((f64::MAX, f64::MIN), |(lo, hi), p| {
                let d = n.dot(&p.coords);
                (lo.min(d), hi.max(d))
            })
        };
        let ((a0, a1), (b0, b1)) = (proj(&ca), proj(&cb));
        a1 > b0 && b1 > a0
    })
}

fn check_overlap(feet: &[Pose2; 2], foot: &FootGeometry, step: usize) -> Result<(), PatternError> {
    if feet_overlap(&feet[0], &feet[1], foot) {
        Err(PatternError::FeetOverlap { step })
    } else {
        Ok(())
    }
}
