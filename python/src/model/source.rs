//! Where a `biped.Model` came from, kept so that the model can be pickled (sent to another
//! process, e.g. a Ray worker) and rebuilt there: the URDF text itself (not its path, which
//! another machine may not have), the Lola variant or the Dill level.

use super::{urdf_error, PyModel};
use crate::error::biped_err;
use biped_dynamics::urdf::{load_str, UrdfOptions};
use biped_robots::lola::{self, LolaType};
use pyo3::prelude::*;

/// The constructor arguments of a model.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    /// A URDF document with its file name (for messages) and import options.
    Urdf {
        text: String,
        file: String,
        floating: bool,
        reject_mimic: bool,
    },
    /// `Model.lola(kind)`.
    Lola(String),
    /// `Model.dill(level)`.
    Dill(i64),
}

/// The pickled form: a kind and its arguments.
pub type Pickled = (String, String, String, bool, bool);

impl Source {
    /// Builds the model.
    pub fn build(self, py: Python<'_>) -> PyResult<PyModel> {
        match &self {
            Source::Urdf {
                text,
                file,
                floating,
                reject_mimic,
            } => {
                let options = UrdfOptions {
                    floating: *floating,
                    reject_mimic: *reject_mimic,
                };
                let imported = py
                    .detach(|| load_str(text, file, &options))
                    .map_err(urdf_error)?;
                let warnings = imported.warnings.iter().map(|w| w.to_string()).collect();
                let label = file.clone();
                Ok(PyModel::new(imported.model, label, warnings, self))
            }
            Source::Lola(kind) => {
                let t: LolaType = kind.parse().map_err(biped_err)?;
                let built = lola::build(t).map_err(|e| biped_err(e.to_string()))?;
                Ok(PyModel::new(
                    built.model,
                    format!("Lola {t:?}"),
                    Vec::new(),
                    self,
                ))
            }
            Source::Dill(n) => {
                let max = biped_dynamics::dill::MAX_DILL_LEVEL;
                let level = u32::try_from(*n)
                    .ok()
                    .filter(|&l| l <= max)
                    .ok_or_else(|| biped_err(format!("dill: level {n} is not in 0..{max}")))?;
                let model =
                    biped_dynamics::dill::dill(level).map_err(|e| biped_err(e.to_string()))?;
                Ok(PyModel::new(model, format!("Dill({n})"), Vec::new(), self))
            }
        }
    }

    /// The arguments of `Model._restore`.
    pub fn pickled(&self) -> Pickled {
        match self {
            Source::Urdf {
                text,
                file,
                floating,
                reject_mimic,
            } => (
                "urdf".into(),
                text.clone(),
                file.clone(),
                *floating,
                *reject_mimic,
            ),
            Source::Lola(kind) => ("lola".into(), kind.clone(), String::new(), false, false),
            Source::Dill(n) => ("dill".into(), n.to_string(), String::new(), false, false),
        }
    }

    /// The inverse of [`Self::pickled`].
    pub fn unpickled((kind, a, b, floating, reject_mimic): Pickled) -> PyResult<Self> {
        match kind.as_str() {
            "urdf" => Ok(Source::Urdf {
                text: a,
                file: b,
                floating,
                reject_mimic,
            }),
            "lola" => Ok(Source::Lola(a)),
            "dill" => a
                .parse()
                .map(Source::Dill)
                .map_err(|_| biped_err(format!("pickled Dill level `{a}` is not a number"))),
            _ => Err(biped_err(format!("pickled model of unknown kind `{kind}`"))),
        }
    }
}
