//! Robot models built on `biped_dynamics`: the Lola-like biped of the thesis (Fig. 1.1,
//! Table 2.3) and kinematic calibration of joint encoders (3.5).

pub mod calibration;
pub mod lola;
