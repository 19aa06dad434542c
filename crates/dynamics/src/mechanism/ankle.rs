//! Lola's ankle drive: two parallel spatial slider-cranks (thesis 3.3, eqs. (3.22)-(3.37)).
//!
//! Geometry (Fig. 3.2 is not in the extracted text; this is our reading of (3.23)):
//! - parent is the shank frame `s`; the ankle is a universal joint centred at `C`
//!   (`ankle_center`, shank coordinates) with `A_sf = A_y(q_flx) A_x(q_add)`: flexion about the
//!   shank y axis, then adduction about the foot's x axis (the thesis's `A_sa A_af`, with
//!   `a_r_pc,f = 0` as on Lola);
//! - actuator `i` (two of them): a roller screw fixed on the shank along the unit axis `e_i`
//!   (`screw_axis`) starting at `T_i` (`screw_top`); its nut's ball joint is at
//!   `N_i = T_i + l_i e_i`, `l_i` the nut travel; a coupler rod of length `l_c,i` joins `N_i` to
//!   the foot's ball joint `F_i = C + A_sf f_i` (`foot_ball`, foot coordinates);
//! - loop (3.23)-(3.24): `r = F_i - T_i` (`s_r_coupler,0`), `|r - l_i e_i| = l_c,i`, solved by
//!   (3.25)/(3.29): `l_i = e.r - d`, `d = sqrt(l_c^2 - r.r + (e.r)^2)`. The minus sign is the
//!   assembly branch: the nut lies *before* the foot ball along `e_i` (screw axis pointing from
//!   the knee towards the foot), the rod hangs from the nut to the foot; the plus sign is the
//!   point below the foot (footnote 1). `d^2 <= 0` is reported as
//!   [`MechanismError::OutOfRange`].
//! - the screw/rotor turns by `phi_i = N_screw l_i + offset_i` (3.22), (3.27).
//!
//! Derivatives (3.30)-(3.37) are exact: propagated by [`super::jet`] in the reference
//! [`Coupling::motion`], written out in closed form in the fast path (`closure.rs`) used by
//! [`AnkleCoupling::relative_cached`], [`AnkleDrive::transmission`] and the spin rows; the two
//! agree to round-off (tested).
//!
//! Parts ([`AnklePart`], each a [`Coupling`] with the two ankle angles as inputs, relative to the
//! shank): the nut (screw frame translated by `l_i`), the rotor (screw frame spun by `phi_i`)
//! and the coupler rod. Screw frame: z along `e_i`, `x = normalize(s_y x z)`, `y = z x x`.
//! Rod roll convention: origin at the nut ball `N_i`, z from `N_i` to `F_i`,
//! `x = normalize(s_y x z)`, `y = z x x` (a rod between two ball joints has no physical roll;
//! this choice equals the screw frame when the rod is parallel to the screw).

mod cached;
mod closure;

pub use cached::AnkleLoop;

use super::cache::instance_id;
use super::jet::{bad_param, input_arrays, seed_inputs, FrameJet, SJet, VJet};
use super::{CoupledMotion, Coupling, MechanismError};
use closure::trig;
use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};
use std::f64::consts::PI;
use std::ops::{Add, Mul, Sub};

const NAME: &str = "ankle drive";

/// Grid points per axis checked by [`AnkleDrive::new`].
const GRID: usize = 24;

/// Newton-Raphson iteration limit of [`AnkleDrive::ankle_angles`].
const MAX_ITER: usize = 60;

/// Geometry of one spatial slider-crank of the ankle drive, (3.23).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnkleActuatorParams {
    /// Start `T` of the nut travel on the screw axis, shank frame \[m] (`s_r_top`).
    pub screw_top: Vector3<f64>,
    /// Screw axis direction `e` (shank frame, normalized on validation; `s_e_screw`).
    pub screw_axis: Vector3<f64>,
    /// Foot ball-joint centre `f` relative to the ankle centre, foot frame \[m] (`f_r_bot`).
    pub foot_ball: Vector3<f64>,
    /// Coupler rod length `l_coupler` \[m] (3.24).
    pub rod_length: f64,
    /// Motor angle at zero nut travel \[rad].
    pub motor_offset: f64,
}

/// Parameters of the ankle drive, eqs. (3.22)-(3.37).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnkleDriveParams {
    /// Ankle (universal joint) centre `C` in the shank frame \[m].
    pub ankle_center: Vector3<f64>,
    /// The two slider-cranks.
    pub actuators: [AnkleActuatorParams; 2],
    /// Roller-screw lead `P_lead` \[m/rev] (3.22).
    pub lead: f64,
    /// Lower ends of the working range `[q_flx, q_add]` \[rad].
    pub q_min: [f64; 2],
    /// Upper ends of the working range `[q_flx, q_add]` \[rad].
    pub q_max: [f64; 2],
}

impl Default for AnkleDriveParams {
    /// Lola-like guess: ankle 0.40 m below the knee, screws (5 mm lead) behind the shank 35 mm
    /// either side of the sagittal plane, 0.20 m rods to balls 70 mm behind and 30 mm above the
    /// ankle; range flexion -0.5..0.4 rad, adduction -0.25..0.25 rad. Not Lola's real data.
    fn default() -> Self {
        let actuator = |y: f64| AnkleActuatorParams {
            screw_top: Vector3::new(-0.05, y, -0.06),
            screw_axis: Vector3::new(0.0, 0.0, -1.0),
            foot_ball: Vector3::new(-0.07, y, 0.03),
            rod_length: 0.20,
            motor_offset: 0.0,
        };
        Self {
            ankle_center: Vector3::new(0.0, 0.0, -0.40),
            actuators: [actuator(0.035), actuator(-0.035)],
            lead: 0.005,
            q_min: [-0.5, -0.25],
            q_max: [0.4, 0.25],
        }
    }
}

/// Nut travels and their derivatives at `(q_ankle, qd_ankle)`, (3.29)-(3.33).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnkleTransmission {
    /// Nut travels `l_i` \[m] (3.29).
    pub travel: Vector2<f64>,
    /// `d l_i / d q_j` (row `i` actuator, column `j` = flexion, adduction) (3.32).
    pub jacobian: Matrix2<f64>,
    /// `Jdot qd` (3.33).
    pub jdot_qd: Vector2<f64>,
    /// Motor angles `N_screw l_i + offset_i` \[rad] (3.22).
    pub motor_angles: Vector2<f64>,
}

/// The parts of one ankle slider-crank that move relative to the shank.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AnklePart {
    /// Roller-screw nut (translates along the screw).
    Nut,
    /// Motor rotor and screw (spins about the screw axis), (3.36)-(3.37).
    Rotor,
    /// Coupler rod between the nut and foot ball joints.
    Rod,
}

/// A validated ankle drive, (3.22)-(3.37).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnkleDrive {
    params: AnkleDriveParams,
    /// The two slider-cranks.
    cranks: [SliderCrank; 2],
}

/// One validated spatial slider-crank: everything its parts need, nothing more (small, so
/// that [`AnkleCoupling`] stays small).
#[derive(Debug, Clone, Copy)]
struct SliderCrank {
    /// Construction identity ([`super::cache::instance_id`]), the cache key; ignored by `==`.
    id: u64,
    /// Ankle centre `C` (shank frame).
    center: Vector3<f64>,
    /// Geometry (screw axis normalized).
    act: AnkleActuatorParams,
    /// Constant screw frame (columns x, y, z in shank coordinates), see the module doc.
    frame: Matrix3<f64>,
    /// `N_screw`.
    ratio: f64,
}

impl PartialEq for SliderCrank {
    /// Equal geometry (the construction identity is not compared).
    fn eq(&self, o: &Self) -> bool {
        (self.center, self.act, self.frame, self.ratio) == (o.center, o.act, o.frame, o.ratio)
    }
}

/// Per-actuator jets of one evaluation.
#[derive(Debug, Clone, Copy)]
struct Loop {
    /// Nut travel `l_i`.
    travel: SJet<2>,
    /// Foot ball centre `F_i` (shank frame).
    foot_ball: VJet<2>,
}

impl AnkleDrive {
    /// Validates the parameters: finite, positive lead and rod lengths, screw axes not along the
    /// shank y axis, and over the working range an assembled loop with an invertible Jacobian.
    pub fn new(mut params: AnkleDriveParams) -> Result<Self, MechanismError> {
        let p = &mut params;
        let vals = p.actuators.iter().flat_map(|a| {
            a.screw_top
                .iter()
                .chain(&a.screw_axis)
                .chain(&a.foot_ball)
                .copied()
                .chain([a.rod_length, a.motor_offset])
        });
        let finite = vals
            .chain(p.ankle_center.iter().copied())
            .chain(p.q_min)
            .chain(p.q_max)
            .chain([p.lead])
            .all(f64::is_finite);
        if !finite || p.lead <= 0.0 || p.actuators.iter().any(|a| a.rod_length <= 0.0) {
            return Err(bad_param(
                NAME,
                "all values finite, lead and rod lengths > 0",
            ));
        }
        if (0..2).any(|j| p.q_min[j] >= p.q_max[j]) {
            return Err(bad_param(NAME, "q_min < q_max"));
        }
        for a in p.actuators.iter_mut() {
            let n = a.screw_axis.norm();
            if n == 0.0 || a.screw_axis.cross(&Vector3::y()).norm() <= 1e-6 * n {
                return Err(bad_param(NAME, "screw axis zero or along the shank y axis"));
            }
            a.screw_axis /= n;
        }
        let crank = |act: AnkleActuatorParams| {
            let e = VJet::<2>::constant(act.screw_axis);
            let f = FrameJet::from_direction(e, &Vector3::y(), e);
            SliderCrank {
                id: instance_id(),
                center: params.ankle_center,
                act,
                frame: Matrix3::from_columns(&[f.x.v, f.y.v, f.z.v]),
                ratio: 2.0 * PI / params.lead,
            }
        };
        let drive = Self {
            params,
            cranks: params.actuators.map(crank),
        };
        drive.check_range()?;
        Ok(drive)
    }

    /// Checks assembly and Jacobian conditioning on a grid over the working range.
    fn check_range(&self) -> Result<(), MechanismError> {
        let (lo, hi) = (self.params.q_min, self.params.q_max);
        for i in 0..=GRID {
            for k in 0..=GRID {
                let t = |j: usize, s: usize| lo[j] + (hi[j] - lo[j]) * s as f64 / GRID as f64;
                let tr = self.transmission([t(0, i), t(1, k)], [0.0; 2])?;
                let jac = tr.jacobian;
                if jac.determinant().abs() <= 1e-3 * jac.norm_squared() {
                    return Err(bad_param(
                        NAME,
                        "Jacobian (3.32) singular in the working range",
                    ));
                }
            }
        }
        Ok(())
    }

    /// The parameters (screw axes normalized).
    pub fn params(&self) -> &AnkleDriveParams {
        &self.params
    }

    /// Screw ratio `N_screw = 2 pi / P_lead` \[rad/m] (3.22).
    pub fn screw_ratio(&self) -> f64 {
        2.0 * PI / self.params.lead
    }

    /// Nut travels, their 2x2 Jacobian, `Jdot qd` and the motor angles, (3.22)-(3.33).
    pub fn transmission(
        &self,
        q: [f64; 2],
        qd: [f64; 2],
    ) -> Result<AnkleTransmission, MechanismError> {
        let (q, qd) = input_arrays::<2>(NAME, &q, &qd)?;
        let t = trig(q);
        let l = [
            self.cranks[0].solve(q, t, qd)?,
            self.cranks[1].solve(q, t, qd)?,
        ];
        let n = self.screw_ratio();
        let acts = &self.params.actuators;
        Ok(AnkleTransmission {
            travel: Vector2::new(l[0].l, l[1].l),
            jacobian: Matrix2::new(l[0].l_q[0], l[0].l_q[1], l[1].l_q[0], l[1].l_q[1]),
            jdot_qd: Vector2::new(l[0].l_acc, l[1].l_acc),
            motor_angles: Vector2::new(
                n * l[0].l + acts[0].motor_offset,
                n * l[1].l + acts[1].motor_offset,
            ),
        })
    }

    /// Ankle angles `[q_flx, q_add]` from the two motor angles by damped Newton-Raphson with the
    /// 2x2 Jacobian (3.32) (footnote 5 of ch. 3), starting at `guess` (default: mid-range).
    /// `OutOfRange` if the solution leaves the working range, `NoConvergence` otherwise.
    pub fn ankle_angles(
        &self,
        motor_angles: [f64; 2],
        guess: Option<[f64; 2]>,
    ) -> Result<[f64; 2], MechanismError> {
        let p = &self.params;
        if motor_angles
            .iter()
            .chain(guess.iter().flatten())
            .any(|x| !x.is_finite())
        {
            return Err(MechanismError::BadInput {
                mechanism: NAME,
                reason: "non-finite motor angle or guess".into(),
            });
        }
        let n = self.screw_ratio();
        let target = Vector2::new(
            (motor_angles[0] - p.actuators[0].motor_offset) / n,
            (motor_angles[1] - p.actuators[1].motor_offset) / n,
        );
        let mid = [
            0.5 * (p.q_min[0] + p.q_max[0]),
            0.5 * (p.q_min[1] + p.q_max[1]),
        ];
        let mut q = Vector2::from(guess.unwrap_or(mid));
        let eval = |q: &Vector2<f64>| self.transmission([q.x, q.y], [0.0; 2]);
        let mut tr = eval(&q)?;
        let mut res = tr.travel - target;
        for _ in 0..MAX_ITER {
            let Some(step) = tr.jacobian.try_inverse().map(|inv| inv * res) else {
                break;
            };
            let (mut t, mut accepted) = (1.0, false);
            for _ in 0..30 {
                let cand = q - step * t;
                if let Ok(c) = eval(&cand) {
                    let cres = c.travel - target;
                    if cres.norm() < res.norm() || step.norm() * t <= 1e-14 {
                        (q, tr, res, accepted) = (cand, c, cres, true);
                        break;
                    }
                }
                t *= 0.5;
            }
            if !accepted {
                break;
            }
            if step.norm() * t <= 1e-15 * (1.0 + q.norm()) || res.norm() == 0.0 {
                return self.in_range(q, motor_angles);
            }
        }
        let scale = p.actuators[0].rod_length;
        if res.norm() <= 1e-14 * scale {
            return self.in_range(q, motor_angles);
        }
        Err(MechanismError::NoConvergence {
            mechanism: NAME,
            iterations: MAX_ITER,
            residual: res.norm(),
        })
    }

    /// Accepts a converged solution only inside the working range (with 1e-9 rad slack).
    fn in_range(
        &self,
        q: Vector2<f64>,
        motor_angles: [f64; 2],
    ) -> Result<[f64; 2], MechanismError> {
        let p = &self.params;
        if (0..2).all(|j| q[j] >= p.q_min[j] - 1e-9 && q[j] <= p.q_max[j] + 1e-9) {
            Ok([q.x, q.y])
        } else {
            Err(MechanismError::OutOfRange {
                mechanism: NAME,
                input: motor_angles.to_vec(),
                reason: "Newton-Raphson solution outside the ankle working range",
            })
        }
    }

    /// The [`Coupling`] of one part of actuator `actuator` (0 or 1).
    pub fn part(&self, actuator: usize, part: AnklePart) -> Result<AnkleCoupling, MechanismError> {
        if actuator > 1 {
            return Err(MechanismError::BadInput {
                mechanism: NAME,
                reason: format!("actuator {actuator} (0 or 1)"),
            });
        }
        Ok(AnkleCoupling {
            crank: self.cranks[actuator],
            part,
        })
    }
}

impl SliderCrank {
    /// Closes the loop (3.23)-(3.29) at the input jets `q = [q_flx, q_add]`.
    fn close_loop(&self, q: &[SJet<2>; 2]) -> Result<Loop, MechanismError> {
        let a = &self.act;
        let foot_ball = VJet::rotate_constant(&a.foot_ball, &Vector3::x_axis(), q[1])
            .rotate(&Vector3::y_axis(), q[0])
            .offset(&self.center);
        let r = foot_ball.offset(&-a.screw_top);
        let er = r.dot_const(&a.screw_axis);
        let d2 = er
            .mul(er)
            .sub(r.dot(&r))
            .add(SJet::constant(a.rod_length * a.rod_length));
        if d2.v <= 0.0 {
            return Err(MechanismError::OutOfRange {
                mechanism: NAME,
                input: vec![q[0].v, q[1].v],
                reason: "no real root of (3.25): d^2 <= 0 in (3.29)",
            });
        }
        Ok(Loop {
            travel: er.sub(d2.sqrt()),
            foot_ball,
        })
    }

    /// Frame jets of one part at the input jets `q`.
    fn frame(&self, part: AnklePart, q: &[SJet<2>; 2]) -> Result<FrameJet<2>, MechanismError> {
        Ok(self.frame_of(part, &self.close_loop(q)?))
    }

    /// Frame jets of one part from the closed loop `lp` (3.30)-(3.37).
    fn frame_of(&self, part: AnklePart, lp: &Loop) -> FrameJet<2> {
        let a = &self.act;
        let frame = &self.frame;
        let axis = VJet::constant(a.screw_axis);
        let top = VJet::constant(a.screw_top);
        let nut = top.add(axis.scale(lp.travel));
        match part {
            AnklePart::Nut => FrameJet::fixed_axes(frame, nut),
            AnklePart::Rotor => {
                let phi = lp
                    .travel
                    .scale(self.ratio)
                    .add(SJet::constant(a.motor_offset));
                FrameJet::fixed_axes(frame, top).spin_z(phi)
            }
            AnklePart::Rod => {
                let u = lp
                    .foot_ball
                    .sub(nut)
                    .scale(SJet::constant(1.0 / a.rod_length));
                FrameJet::from_direction(u, &Vector3::y(), nut)
            }
        }
    }
}

/// One part of one slider-crank of an [`AnkleDrive`] as a [`Coupling`] (inputs: flexion,
/// adduction).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnkleCoupling {
    crank: SliderCrank,
    part: AnklePart,
}

impl AnkleCoupling {
    /// Frame of a part that moves about or along the screw axis, at spin angle and travel
    /// zero, relative to the shank (rotation: the screw frame's axes as columns; origin: the
    /// screw top `T`), with the part: the rotor spins about its z axis by `N_screw l + offset`
    /// (3.22), the nut moves along it by `l` (3.29). `None` for the rod.
    pub fn axis_frame(&self) -> Option<(Matrix3<f64>, Vector3<f64>, AnklePart)> {
        (self.part != AnklePart::Rod).then_some((
            self.crank.frame,
            self.crank.act.screw_top,
            self.part,
        ))
    }

    /// Foot ball centre `F_i` and nut ball centre `N_i` in the shank frame (loop-closure check).
    pub fn ball_centres(
        &self,
        q: [f64; 2],
    ) -> Result<(Vector3<f64>, Vector3<f64>), MechanismError> {
        let (q, _) = input_arrays::<2>(NAME, &q, &[0.0; 2])?;
        let a = &self.crank.act;
        let c = self.crank.solve(q, trig(q), [0.0; 2])?;
        Ok((c.foot, a.screw_top + a.screw_axis * c.l))
    }
}

impl Coupling for AnkleCoupling {
    fn n_inputs(&self) -> usize {
        2
    }

    /// The screw's rotor spins and its nut slides along the screw axis (the part frame's z,
    /// [`Self::axis_frame`]); the rod moves generally.
    fn axial_role(&self) -> super::AxialRole {
        match self.axis_frame() {
            Some((_, _, AnklePart::Rotor)) => super::AxialRole::Spins,
            Some(_) => super::AxialRole::Slides,
            None => super::AxialRole::General,
        }
    }

    /// Pose, Jacobian and bias of the part relative to the shank, (3.30)-(3.37).
    fn motion(&self, q_in: &[f64], qd_in: &[f64]) -> Result<CoupledMotion, MechanismError> {
        let q = seed_inputs::<2>(NAME, q_in, qd_in)?;
        Ok(self.crank.frame(self.part, &q)?.motion())
    }
}
