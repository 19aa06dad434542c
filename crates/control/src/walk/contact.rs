//! Whether the planned motion keeps its supporting feet on the ground: the height of the
//! planned contact points of every foot the pattern has on the ground, in the configuration
//! the IK reached (the contact verdict of [`super::verdict`]).
//!
//! The contact points of a foot are the corners of the part the pattern puts on the ground
//! ([`crate::pattern::roll`]): the sole rectangle of a flat foot, the two ends of the heel
//! edge of a foot rolling on its heel, the toe segment's rectangle (from the toe joint axis
//! `toe_length` forward, `toe_height` below it) of a foot on its toe. A foot's lift is the
//! height of its highest contact point above the ground: a flat foot tilted so that one
//! corner is up does not stand flat either. A robot without toe frames stands on the front
//! edge of its sole in toe-off.

use super::robot::WalkRobot;
use crate::pattern::{Contact, Foot, FootGeometry, PatternSample};
use crate::tasks::Frame;
use biped_dynamics::Data;
use nalgebra::{Point3, Rotation3};

/// The largest lift of a supporting foot in one cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FootLift {
    /// Height of the highest planned contact point above the ground \[m] (0 without support
    /// in the pattern, negative: below the ground).
    pub height: f64,
    /// The foot.
    pub foot: Foot,
    /// The part of the foot the pattern has on the ground.
    pub contact: Contact,
}

impl FootLift {
    /// The foot and its supporting part in words (`left heel edge`).
    pub fn describe(&self) -> String {
        let part = match self.contact {
            Contact::Flat => "sole",
            Contact::Heel => "heel edge",
            Contact::Toe => "toe",
            Contact::Swing => "swing foot",
        };
        let side = match self.foot {
            Foot::Left => "left",
            Foot::Right => "right",
        };
        format!("{side} {part}")
    }
}

/// The sole and toe frames of a robot by foot, for [`SupportCheck::lift`].
#[derive(Debug, Clone, Copy)]
pub struct SupportCheck {
    soles: [Frame; 2],
    toes: Option<[Frame; 2]>,
    foot: FootGeometry,
}

impl SupportCheck {
    /// The check for `robot` with the sole geometry `foot` (the pattern's).
    pub fn new(robot: &WalkRobot, foot: FootGeometry) -> Self {
        let [r, l] = robot.frames.soles;
        Self {
            soles: [l, r],
            toes: robot.frames.toes.map(|[r, l]| [l, r]),
            foot,
        }
    }

    /// The foot of `sample` on the ground whose contact points reach highest in the
    /// kinematics `data`; `None` if the pattern has no foot on the ground.
    pub fn lift(&self, data: &Data, sample: &PatternSample) -> Option<FootLift> {
        [Foot::Left, Foot::Right]
            .into_iter()
            .filter_map(|foot| {
                let contact = sample.foot(foot).contact;
                let height = self.highest(data, foot, contact)?;
                Some(FootLift {
                    height,
                    foot,
                    contact,
                })
            })
            .max_by(|a, b| a.height.total_cmp(&b.height))
    }

    /// Height of the highest contact point of `foot` with `contact` (`None`: swing).
    fn highest(&self, data: &Data, foot: Foot, contact: Contact) -> Option<f64> {
        let g = &self.foot;
        let i = foot.index();
        let (frame, xs, z): (Frame, &[f64], f64) = match (contact, &self.toes) {
            (Contact::Swing, _) => return None,
            (Contact::Flat, _) => (self.soles[i], &[g.front, -g.back], 0.0),
            (Contact::Heel, _) => (self.soles[i], &[-g.back], 0.0),
            (Contact::Toe, Some(toes)) => (toes[i], &[0.0, g.toe_length], -g.toe_height),
            (Contact::Toe, None) => (self.soles[i], &[g.front], 0.0),
        };
        let rot = Rotation3::from_matrix_unchecked(data.world_rot[frame.body]);
        let origin = data.world_pos[frame.body];
        let corners = xs.iter().flat_map(|&x| {
            [
                Point3::new(x, g.half_width, z),
                Point3::new(x, -g.half_width, z),
            ]
        });
        let top = corners
            .map(|p| (origin + rot * (frame.offset * p).coords).z)
            .fold(f64::NEG_INFINITY, f64::max);
        Some(top)
    }
}
