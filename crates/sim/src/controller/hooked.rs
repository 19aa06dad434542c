//! A controller followed by a user hook: each cycle the inner controller writes its commands,
//! then the hook sees the same sensor sample and may change them (or replace them outright).
//! This is how a script runs its own controller in a scenario: the scenario's joint PD gives
//! a starting point, the hook the user's law.

use super::{Commands, Controller};
use crate::drive::DriveMode;
use crate::error::SimError;
use crate::sensors::Sensors;

/// The hook: called once per control cycle after the inner controller, with the time, the
/// sensor sample and the inner controller's commands, which it may overwrite.
pub type Hook = Box<dyn FnMut(f64, &Sensors, &mut Commands) -> Result<(), SimError> + Send>;

/// Controller `C` whose commands pass through an optional [`Hook`] every cycle.
pub struct Hooked<C> {
    inner: C,
    hook: Option<Hook>,
}

impl<C: Controller> Hooked<C> {
    /// `inner` followed by `hook` (none: `inner` alone).
    pub fn new(inner: C, hook: Option<Hook>) -> Self {
        Self { inner, hook }
    }

    /// The inner controller.
    pub fn inner(&self) -> &C {
        &self.inner
    }
}

impl<C: Controller> Controller for Hooked<C> {
    fn period(&self) -> f64 {
        self.inner.period()
    }

    fn mode(&self) -> DriveMode {
        self.inner.mode()
    }

    fn update(
        &mut self,
        t: f64,
        sensors: &Sensors,
        commands: &mut Commands,
    ) -> Result<(), SimError> {
        self.inner.update(t, sensors, commands)?;
        let Some(hook) = self.hook.as_mut() else {
            return Ok(());
        };
        let n = commands.values.len();
        hook(t, sensors, commands)?;
        if commands.values.len() != n {
            return Err(SimError::Length {
                what: "controller hook commands",
                got: commands.values.len(),
                expected: n,
            });
        }
        match commands.values.iter().position(|x| !x.is_finite()) {
            Some(index) => Err(SimError::NonFinite {
                what: "controller hook commands",
                index,
            }),
            None => Ok(()),
        }
    }
}
