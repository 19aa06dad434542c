//! Valid values of the numeric options: one [`Quantity`] (interval and unit) per number, one
//! [`List`] per comma-separated option, and one parser that checks a value against them, so
//! that every out-of-range value is rejected before any model is built, with one line naming
//! the option, the value and the valid range. The tables of the sub-commands are
//! [`simulate`] and [`walk`].

use std::fmt::Write;

/// A number's valid interval `min .. max` (closed at `max`; at `min` open or closed) and unit.
#[derive(Debug, Clone, Copy)]
pub struct Quantity {
    /// Option that sets it, e.g. `--step`.
    pub flag: &'static str,
    /// Name in messages, e.g. `damping` (empty: the option is the name).
    pub name: &'static str,
    /// Lower bound.
    pub min: f64,
    /// Whether `min` itself is excluded (`> min` rather than `>= min`).
    pub min_open: bool,
    /// Upper bound (included).
    pub max: f64,
    /// Unit in messages (may be empty).
    pub unit: &'static str,
    /// Whether only whole numbers are valid.
    pub whole: bool,
    /// Where a bound comes from, e.g. `at most the control period` (may be empty).
    pub note: &'static str,
}

/// A real quantity on `min..=max` (or `min < x <= max` with `min_open`).
const fn real(
    flag: &'static str,
    name: &'static str,
    min: f64,
    max: f64,
    unit: &'static str,
) -> Quantity {
    Quantity {
        flag,
        name,
        min,
        min_open: false,
        max,
        unit,
        whole: false,
        note: "",
    }
}

/// A real quantity on `min < x <= max`.
const fn above(
    flag: &'static str,
    name: &'static str,
    min: f64,
    max: f64,
    unit: &'static str,
) -> Quantity {
    Quantity {
        min_open: true,
        ..real(flag, name, min, max, unit)
    }
}

/// A whole number on `min..=max`.
const fn whole(flag: &'static str, min: f64, max: f64) -> Quantity {
    Quantity {
        whole: true,
        ..real(flag, "", min, max, "")
    }
}

/// A comma-separated option: its value shape (e.g. `K,D`) and one quantity per entry.
#[derive(Debug, Clone, Copy)]
pub struct List<const N: usize> {
    /// Option, e.g. `--contact`.
    pub flag: &'static str,
    /// Value shape in messages, e.g. `K,D`.
    pub shape: &'static str,
    /// The entries.
    pub parts: [Quantity; N],
}

/// `x` as written in messages: plain for 1e-3 <= |x| < 1e6 (and 0), else in e-notation.
pub fn show(x: f64) -> String {
    let a = x.abs();
    if a == 0.0 || (1e-3..1e6).contains(&a) || !a.is_finite() {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

impl Quantity {
    /// This quantity with the upper bound `max`, explained by `note`.
    pub fn at_most(self, max: f64, note: &'static str) -> Self {
        Self { max, note, ..self }
    }

    /// This quantity with the lower bound `min` (included), explained by `note`.
    pub fn at_least(self, min: f64, note: &'static str) -> Self {
        Self {
            min,
            min_open: false,
            note,
            ..self
        }
    }

    /// Whether `x` is valid.
    pub fn contains(&self, x: f64) -> bool {
        let low = if self.min_open {
            x > self.min
        } else {
            x >= self.min
        };
        low && x <= self.max && (!self.whole || x.fract() == 0.0)
    }

    /// The valid range in words, e.g. `> 0 and <= 0.001 s (at most the control period)`.
    pub fn describe(&self) -> String {
        let op = if self.min_open { ">" } else { ">=" };
        let mut s = String::new();
        if self.whole {
            s.push_str("a whole number ");
        }
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        let _ = write!(s, "{op} {} and <= {}{unit}", show(self.min), show(self.max));
        if !self.note.is_empty() {
            let _ = write!(s, " ({})", self.note);
        }
        s
    }

    /// Error line for the number `x`, called `what` (may be empty), outside the range.
    fn outside(&self, what: &str, x: f64) -> String {
        let what = if what.is_empty() {
            String::new()
        } else {
            format!("{what} ")
        };
        let unit = if self.unit.is_empty() {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        format!(
            "{}: {what}{}{unit} is out of range: must be {}",
            self.flag,
            show(x),
            self.describe()
        )
    }

    /// Checks the number `x`.
    pub fn check(&self, x: f64) -> Result<f64, String> {
        self.check_as(self.name, x)
    }

    /// Checks the number `x`, called `what` in the error (e.g. `` `knee` ``).
    pub fn check_as(&self, what: &str, x: f64) -> Result<f64, String> {
        match self.contains(x) {
            true => Ok(x),
            false => Err(self.outside(what, x)),
        }
    }

    /// Parses and checks one number.
    pub fn parse(&self, text: &str) -> Result<f64, String> {
        let t = text.trim();
        let what = if self.name.is_empty() {
            String::new()
        } else {
            format!("{} ", self.name)
        };
        let kind = if self.whole {
            "a whole number"
        } else {
            "a number"
        };
        let x: f64 = t
            .parse()
            .map_err(|_| format!("{}: {what}\"{text}\" is not {kind}", self.flag))?;
        self.check(x)
    }

    /// Parses and checks one whole number.
    pub fn parse_whole(&self, text: &str) -> Result<u64, String> {
        debug_assert!(self.whole && self.max < u64::MAX as f64);
        let x = self.parse(text)?;
        // In range, hence whole, >= 0 and small enough for u64.
        Ok(x as u64)
    }
}

impl<const N: usize> List<N> {
    /// Parses and checks exactly `N` comma-separated numbers.
    pub fn parse(&self, text: &str) -> Result<[f64; N], String> {
        let items: Vec<&str> = text.split(',').collect();
        if items.len() != N {
            return Err(format!(
                "{}: expected {N} comma-separated numbers {}, got \"{text}\"",
                self.flag, self.shape
            ));
        }
        let mut out = [0.0; N];
        for ((x, q), item) in out.iter_mut().zip(&self.parts).zip(items) {
            *x = q.parse(item)?;
        }
        Ok(out)
    }
}

/// The numeric options of `biped simulate`.
pub mod simulate {
    use super::{above, real, whole, List, Quantity};

    /// `--duration`: at least one control period (set when the model is known), at most
    /// 1e6 s (the recorded rows are also capped, see `--every`).
    pub const DURATION: Quantity = above("--duration", "", 0.0, 1e6, "s");
    /// `--step`: at most the control period (set when the model is known); 1 us and up.
    pub const STEP: Quantity = real("--step", "", 1e-6, 1e-3, "s");
    /// `--tolerances RTOL,ATOL` of dopri5.
    pub const TOLERANCES: List<2> = List {
        flag: "--tolerances",
        shape: "RTOL,ATOL",
        parts: [
            real("--tolerances", "rtol", 1e-12, 0.1, ""),
            real("--tolerances", "atol", 1e-14, 0.1, ""),
        ],
    };
    /// `--every N`.
    pub const EVERY: Quantity = whole("--every", 1.0, 1e9);
    /// `--bandwidth` of the joint PD controllers.
    pub const BANDWIDTH: Quantity = above("--bandwidth", "", 0.0, 1e3, "rad/s");
    /// `--contact K,D` per sole point (the damping is also the tangential bristle damper,
    /// which must be > 0).
    pub const CONTACT: List<2> = List {
        flag: "--contact",
        shape: "K,D",
        parts: [
            real("--contact", "stiffness", 1e2, 1e8, "N/m"),
            real("--contact", "damping", 1e-2, 1e5, "N s/m"),
        ],
    };
    /// `--friction MU`.
    pub const FRICTION: Quantity = real("--friction", "", 0.0, 5.0, "");
    /// Joint angles of `--pose` (one turn either way).
    pub const POSE_ANGLE: Quantity = real(
        "--pose",
        "angle",
        -std::f64::consts::TAU,
        std::f64::consts::TAU,
        "rad",
    );
    /// Reflected rotor inertias of `--armature`.
    pub const ARMATURE: Quantity = real("--armature", "inertia", 0.0, 100.0, "kg m^2");
    /// `--sway RAD,S`: lean amplitude and period.
    pub const SWAY: List<2> = List {
        flag: "--sway",
        shape: "RAD,S",
        parts: [
            above("--sway", "amplitude", 0.0, 1.0, "rad"),
            real("--sway", "period", 0.1, 100.0, "s"),
        ],
    };
    /// `--sole-center X,Y,Z` in the foot link's frame.
    pub const SOLE_CENTER: List<3> = List {
        flag: "--sole-center",
        shape: "X,Y,Z",
        parts: [
            real("--sole-center", "x", -1.0, 1.0, "m"),
            real("--sole-center", "y", -1.0, 1.0, "m"),
            real("--sole-center", "z", -1.0, 1.0, "m"),
        ],
    };
    /// `--sole-size LENGTH,WIDTH`.
    pub const SOLE_SIZE: List<2> = List {
        flag: "--sole-size",
        shape: "LENGTH,WIDTH",
        parts: [
            above("--sole-size", "length", 0.0, 1.0, "m"),
            above("--sole-size", "width", 0.0, 1.0, "m"),
        ],
    };
}

/// The numeric options of `biped walk` (Lola's legs: steps up to 0.6 m either way).
pub mod walk {
    use super::{real, whole, Quantity};

    /// `--steps`.
    pub const STEPS: Quantity = whole("--steps", 1.0, 100.0);
    /// `--step-length`.
    pub const STEP_LENGTH: Quantity = real("--step-length", "", -0.6, 0.6, "m");
    /// `--step-time`.
    pub const STEP_TIME: Quantity = real("--step-time", "", 0.2, 5.0, "s");
    /// `--friction`.
    pub const FRICTION: Quantity = real("--friction", "", 0.05, 3.0, "");
}

/// Options of `biped ssv fit`.
pub mod ssv_fit {
    use super::{real, whole, Quantity};

    /// `--samples`.
    pub const SAMPLES: Quantity = whole("--samples", 1.0, 1e6);
    /// `--activation-distance`.
    pub const ACTIVATION_DISTANCE: Quantity = real("--activation-distance", "", 0.001, 1.0, "m");
}

#[cfg(test)]
mod tests;
