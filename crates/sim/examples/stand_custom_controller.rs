//! The Lola-like biped (Type 2) standing for 2 s under a controller written here, by
//! implementing `biped_sim::controller::Controller`: a joint PD that holds the start pose and
//! keeps a log of its largest torque and of the vertical force its foot sensors read.
//!
//! Run with `cargo run -p biped_sim --example stand_custom_controller` (about 10 s in the
//! unoptimised debug build; add `--release` for the real-time factor of an optimised one).

use biped_robots::lola::LolaType;
use biped_robots::plant::lola_plant;
use biped_sim::controller::{Commands, Controller};
use biped_sim::drive::DriveMode;
use biped_sim::plant::PlantConfig;
use biped_sim::scenario::{self, ScenarioKind, ScenarioOptions};
use biped_sim::sensors::Sensors;
use biped_sim::simulation::Simulation;
use biped_sim::{Method, SimError};

/// `tau = k_p (q_ref - q) - k_d qdot` per joint, in torque mode, with a log.
struct HoldPose {
    period: f64,
    target: Vec<f64>,
    kp: Vec<f64>,
    kd: Vec<f64>,
    /// Largest |tau| commanded so far and its actuator.
    peak: (f64, usize),
    /// Vertical force on both feet at the last sample (foot F/T sensors, foot frames).
    feet_fz: f64,
}

impl Controller for HoldPose {
    fn period(&self) -> f64 {
        self.period
    }

    fn mode(&self) -> DriveMode {
        DriveMode::Torque
    }

    fn update(&mut self, _t: f64, s: &Sensors, c: &mut Commands) -> Result<(), SimError> {
        for (j, tau) in c.values.iter_mut().enumerate() {
            *tau = self.kp[j] * (self.target[j] - s.joint_positions[j])
                - self.kd[j] * s.joint_velocities[j];
            if tau.abs() > self.peak.0 {
                self.peak = (tau.abs(), j);
            }
        }
        self.feet_fz = s.foot_wrenches.iter().map(|w| w.lin.z).sum();
        Ok(())
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut lp = lola_plant(LolaType::Type2, PlantConfig::default())?;
    // The stand scenario places the robot on the ground in its bent-knee pose; its own PD
    // (biped_sim::controller::JointPd) is only used here for the gains it computed: scaled by
    // each joint's inertia for a 40 rad/s bandwidth and capped for the 1 kHz hold.
    let stand = scenario::build(ScenarioKind::Stand, &mut lp.plant, &ScenarioOptions::lola())?;
    let pd = &stand.controller;
    let ours = HoldPose {
        period: pd.period(),
        target: pd.target().to_vec(),
        kp: pd.kp().to_vec(),
        kd: pd.kd().to_vec(),
        peak: (0.0, 0),
        feet_fz: 0.0,
    };
    let names: Vec<String> = lp
        .plant
        .actuators()
        .iter()
        .map(|a| a.name.clone())
        .collect();
    println!(
        "Lola Type 2 on the ground: {} actuated joints, base at {:.4} m, RK4 at {} ms",
        names.len(),
        stand.q0[2],
        ours.period * 1e3
    );

    let mut sim = Simulation::new(lp.plant, ours, Method::Rk4, stand.z0.clone())?;
    for _ in 0..4 {
        let s = sim.run(0.5, &mut |_| Ok(()))?;
        println!(
            "t = {:.1} s: base height {:.4} m, foot sensors {:.1} N (weight {:.1} N), max |v| {:.2e}, realtime factor {:.1}",
            sim.time(),
            sim.state()[2],
            sim.controller().feet_fz,
            s.weight,
            s.final_max_speed,
            s.realtime_factor
        );
    }
    let (peak, j) = sim.controller().peak;
    println!("largest torque: {peak:.1} N m at `{}`", names[j]);
    Ok(())
}
