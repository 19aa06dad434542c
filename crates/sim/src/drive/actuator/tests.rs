use super::*;
use proptest::prelude::*;

/// The drive law as one formula per mode (the pre-[`DriveHold`] implementation, with the
/// C library's `tanh`): the independent reference of [`Actuator::apply`].
fn reference(
    a: &Actuator,
    row: Option<&MotorRow>,
    mode: DriveMode,
    cmd: f64,
    i: f64,
    v: &[f64],
    gen: &mut [f64],
) -> DriveState {
    let cmd = a.limit(mode, cmd, 0.0, row.is_some());
    let Some(row) = row else {
        gen[a.joint_v] += cmd;
        return DriveState {
            torque: cmd,
            ..DriveState::default()
        };
    };
    let speed = row.rate(v);
    let m = &a.motor;
    let (torque, current, current_rate) = match mode {
        DriveMode::Torque => {
            match a.transmission {
                Transmission::Elastic { ratio, .. } => gen[row.idx[0]] += cmd / ratio,
                _ => gen[a.joint_v] += cmd,
            }
            let tau = cmd / a.nominal_ratio;
            (tau, tau / m.torque_constant, 0.0)
        }
        DriveMode::Current => (m.torque(cmd), cmd, 0.0),
        DriveMode::Voltage => (m.torque(i), i, m.current_rate(cmd, i, speed)),
    };
    let f = &a.friction;
    let level = f.coulomb + (1.0 - f.efficiency) * torque.abs();
    let friction = f.viscous * speed + level * (speed / f.smoothing).tanh();
    let drive = if mode == DriveMode::Torque {
        0.0
    } else {
        torque
    };
    row.apply(drive - friction, gen);
    DriveState {
        speed,
        torque,
        friction,
        current,
        current_rate,
    }
}

/// A direct, geared or elastic actuator on coordinate 0 (elastic motor: coordinate 1).
fn actuator(kind: usize, ratio: f64, friction: FrictionParams, effort: f64) -> Actuator {
    let transmission = match kind {
        0 => Transmission::Direct,
        1 => Transmission::Gear { ratio },
        _ => Transmission::Elastic {
            motor_q: 1,
            motor_v: 1,
            ratio,
        },
    };
    Actuator {
        name: "j".into(),
        joint_q: 0,
        joint_v: 0,
        transmission,
        motor: MotorParams::default(),
        friction,
        nominal_ratio: ratio.abs(),
        effort,
        velocity: 3.0,
    }
}

/// The motor row of `a` (not a rotor).
fn row(a: &Actuator) -> Option<MotorRow> {
    match a.transmission {
        Transmission::Gear { ratio } => Some(MotorRow::single(a.joint_v, ratio)),
        Transmission::Elastic { motor_v, .. } => Some(MotorRow::single(motor_v, 1.0)),
        _ => None,
    }
}

proptest! {
    /// [`Actuator::apply`] (hold, then forces) equals the one-formula reference up to
    /// rounding: forces, speed, torque, friction, current and its rate, in every mode and
    /// transmission, with commands beyond the limits.
    #[test]
    fn apply_matches_the_reference(
        kind in 0usize..3,
        mode in prop::sample::select(vec![DriveMode::Torque, DriveMode::Current, DriveMode::Voltage]),
        ratio in prop_oneof![1.0f64..200.0, -200.0f64..-1.0],
        viscous in 0.0f64..1e-3,
        coulomb in 0.0f64..0.1,
        smoothing in 0.1f64..3.0,
        efficiency in 0.5f64..=1.0,
        effort in prop_oneof![Just(f64::INFINITY), 1.0f64..100.0],
        cmd in -200.0f64..200.0,
        i in -30.0f64..30.0,
        v in prop::array::uniform2(-5.0f64..5.0),
    ) {
        let friction = FrictionParams { viscous, coulomb, smoothing, efficiency };
        let a = actuator(kind, ratio, friction, effort);
        let row = row(&a);
        let (mut got, mut want) = ([0.3, -0.2], [0.3, -0.2]);
        let ds = a.apply(row.as_ref(), mode, cmd, i, &v, &mut got);
        let rs = reference(&a, row.as_ref(), mode, cmd, i, &v, &mut want);
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * (1.0 + x.abs().max(y.abs()));
        for (x, y) in got.iter().zip(&want) {
            prop_assert!(close(*x, *y), "gen {got:?} vs {want:?}");
        }
        let pairs = [
            (ds.speed, rs.speed),
            (ds.torque, rs.torque),
            (ds.friction, rs.friction),
            (ds.current, rs.current),
            (ds.current_rate, rs.current_rate),
        ];
        for (x, y) in pairs {
            prop_assert!(close(x, y), "{ds:?} vs {rs:?}");
        }
    }
}
