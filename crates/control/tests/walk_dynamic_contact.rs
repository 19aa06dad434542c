//! The dynamic walk's contact: toe-off on the toe segment, the slip verdict, and a diverging
//! simulation reported as a fall.

use biped_control::walk::dynamic::SLIP_DISTANCE;
use biped_control::walk::{run_dynamic_walk, DynamicWalkParams};

/// Four steps of 0.4 m on ground of friction `mu` (otherwise the default walk).
fn walk(mu: f64) -> biped_control::walk::DynamicWalkRun {
    let p = DynamicWalkParams {
        steps: 4,
        friction: mu,
        ..DynamicWalkParams::default()
    };
    run_dynamic_walk(&p).expect("dynamic walk")
}

/// In toe-off (heel lifted, the side still loaded) the toe segment carries the load: its own
/// contact points, not the foot's, hold the side's vertical force. A heel lift of 0.03 rad
/// puts the foot's remaining points (0.11 and 0.22 m behind the toe joint line) 3-7 mm above
/// the ground, beyond any penetration (~1 mm).
#[test]
fn toe_off_puts_the_load_on_the_toe() {
    let run = walk(0.8);
    let s = &run.series;
    assert!(run.summary.walked, "{:?}", run.summary);
    let mut seen = [0; 2];
    for k in 0..s.t.len() {
        for (side, n) in seen.iter_mut().enumerate() {
            let (lift, fz, toe) = (s.heel_lift[k][side], s.foot_fz[k][side], s.toe_fz[k][side]);
            if lift > 0.03 && fz > 100.0 {
                let t = s.t[k];
                assert!(toe > 0.0, "t = {t}: side {side} heel up, toe unloaded");
                assert!(toe > 0.99 * fz, "t = {t}: toe {toe} of {fz} N");
                *n += 1;
            }
        }
    }
    // Both feet push off on their toes, for tens of ms each.
    assert!(seen.iter().all(|&n| n > 20), "{seen:?} samples in toe-off");
    // Standing flat at the start the toes carry a share too.
    assert!(s.toe_fz[0].iter().all(|&f| f > 0.0), "{:?}", s.toe_fz[0]);
}

/// The slip verdict: on `mu = 0.8` touch-down and lift-off slide a millimetre at most and the
/// walk keeps its footing; on `mu = 0.2` the same walk's soles slide more than
/// [`SLIP_DISTANCE`] within one contact, and the summary says when.
#[test]
fn a_walk_on_slippery_ground_slips_and_says_so() {
    let firm = walk(0.8).summary;
    assert!(firm.friction_kept && firm.slip_at.is_none(), "{firm:?}");
    assert!(firm.max_slip_distance < 0.5 * SLIP_DISTANCE, "{firm:?}");
    // the measure is not zero by construction: impacts do slide a little
    assert!(firm.max_slip_speed > 0.01, "{firm:?}");
    assert!(firm.max_friction_usage > 0.0 && firm.max_friction_usage <= 1.0 + 1e-9);
    let ice = walk(0.2);
    let s = ice.summary;
    assert!(!s.friction_kept, "{s:?}");
    let t = s.slip_at.expect("slips");
    assert!(t > 0.0 && t < s.sim_time, "{t}");
    assert!(s.max_slip_distance >= SLIP_DISTANCE, "{s:?}");
    assert!(s.max_slip_speed > firm.max_slip_speed, "{s:?} vs {firm:?}");
    // independent of the fall verdict
    assert_eq!(s.walked, s.fell_at.is_none() && s.progress >= 0.8);
    // The slip happened while a side was in contact: the series show that side's slip speed
    // above zero at `slip_at`.
    let k = ice.series.t.iter().position(|&x| x == t).unwrap();
    assert!(ice.series.slip_speed[k].iter().any(|&v| v > 0.0));
}

/// Gains three times beyond the PD's stable scaling blow the simulation up within a few
/// control periods: reported as a fall at the last finite sample, with its summary, not as
/// an error. The same walk with the default gains does not diverge.
#[test]
fn a_diverging_walk_is_a_fall_at_the_divergence() {
    let p = DynamicWalkParams {
        steps: 2,
        step_length: 0.3,
        gain_scale: 3.0,
        ..DynamicWalkParams::default()
    };
    let run = run_dynamic_walk(&p).expect("a divergence is a verdict, not an error");
    let s = run.summary;
    assert!(s.diverged && !s.walked, "{s:?}");
    let t = s.fell_at.expect("fell");
    assert!(t > 0.0 && t < 0.5, "{t}");
    assert_eq!(run.series.t.last(), Some(&t));
    assert!((s.sim_time - t).abs() < 1e-12);
    assert!(run.series.base.iter().flatten().all(|x| x.is_finite()));
    let calm = run_dynamic_walk(&DynamicWalkParams {
        hold_time: 0.0,
        ..DynamicWalkParams {
            gain_scale: 1.0,
            ..p
        }
    })
    .unwrap()
    .summary;
    assert!(!calm.diverged && calm.fell_at.is_none(), "{calm:?}");
}
