//! Where a model comes from (`--urdf`, `--dill`, `--lola`): one enum, one loader, one JSON
//! description.

use crate::cli::out::errln;
use biped_dynamics::urdf::{load_file, UrdfOptions};
use biped_dynamics::Model;
use biped_robots::lola::{self, LolaType};
use clap::Args;
use serde::Serialize;
use std::path::PathBuf;

/// Command-line options selecting a model (the callers declare which are mutually exclusive).
#[derive(Args)]
pub struct SourceArgs {
    /// Load a URDF file.
    #[arg(long, value_name = "FILE")]
    urdf: Option<PathBuf>,
    /// Give the URDF root link a free-flyer joint named "root" (q: xyz + quaternion xyzw).
    #[arg(long)]
    floating: bool,
    /// Reject URDF `<mimic>` joints instead of ignoring them with a warning.
    #[arg(long)]
    reject_mimic: bool,
    /// Use Featherstone's Dill(N) benchmark tree (2^N revolute bodies, thesis 2.10.1).
    #[arg(long, value_name = "N", allow_hyphen_values = true)]
    dill: Option<u32>,
    /// Use the Lola-like biped (thesis Table 2.3): `type2` rigid drives, `type3` elastic gears.
    #[arg(long, value_name = "TYPE", group = "source")]
    lola: Option<LolaType>,
}

/// A model source; adding one is one variant here and one arm in [`ModelSource::load`].
pub enum ModelSource {
    /// A URDF file with import options.
    Urdf(PathBuf, UrdfOptions),
    /// Dill(n).
    Dill(u32),
    /// The Lola-like biped of `crates/robots/data/lola.toml`.
    Lola(LolaType),
}

/// A loaded model and a short label for reports.
pub struct Loaded {
    /// The model.
    pub model: Model,
    /// E.g. `Dill(4)` or the URDF path.
    pub label: String,
}

impl SourceArgs {
    /// Rejects the URDF import options without `--urdf` (they would be ignored).
    pub fn check_urdf_only(&self) -> Result<(), String> {
        if self.urdf.is_some() {
            return Ok(());
        }
        let given = [
            ("--floating", self.floating),
            ("--reject-mimic", self.reject_mimic),
        ];
        match given.iter().find(|(_, on)| *on) {
            Some((option, _)) => Err(format!("{option}: only applies with --urdf FILE")),
            None => Ok(()),
        }
    }

    /// The selected source (clap guarantees at most one; none is an error).
    pub fn to_source(&self) -> Result<ModelSource, String> {
        self.check_urdf_only()?;
        match (&self.urdf, self.dill, self.lola) {
            (Some(path), None, None) => Ok(ModelSource::Urdf(
                path.clone(),
                UrdfOptions {
                    floating: self.floating,
                    reject_mimic: self.reject_mimic,
                },
            )),
            (None, Some(n), None) if n > biped_dynamics::dill::MAX_DILL_LEVEL => Err(format!(
                "--dill: level {n} is too large (valid levels are 0..{})",
                biped_dynamics::dill::MAX_DILL_LEVEL
            )),
            (None, Some(n), None) => Ok(ModelSource::Dill(n)),
            (None, None, Some(t)) => Ok(ModelSource::Lola(t)),
            _ => Err(
                "give exactly one model source: --urdf FILE, --dill N or --lola type2|type3".into(),
            ),
        }
    }
}

impl ModelSource {
    /// Builds the model; URDF warnings go to stderr.
    pub fn load(&self) -> Result<Loaded, Box<dyn std::error::Error>> {
        Ok(match self {
            ModelSource::Urdf(path, options) => {
                let imported = load_file(path, options)?;
                for w in &imported.warnings {
                    errln!("warning: {w}");
                }
                Loaded {
                    model: imported.model,
                    label: path.display().to_string(),
                }
            }
            ModelSource::Dill(n) => Loaded {
                model: biped_dynamics::dill::dill(*n)?,
                label: format!("Dill({n})"),
            },
            ModelSource::Lola(t) => Loaded {
                model: lola::build(*t)?.model,
                label: format!("Lola {t:?}"),
            },
        })
    }
}

/// One joint of `biped model --json`.
#[derive(Serialize)]
pub struct JointJson<'a> {
    name: &'a str,
    nq: usize,
    nv: usize,
}

/// The `biped model --json` object.
#[derive(Serialize)]
pub struct ModelJson<'a> {
    nq: usize,
    nv: usize,
    joints: Vec<JointJson<'a>>,
    bodies: Vec<&'a str>,
    neutral: Vec<f64>,
    /// Member bodies of every sub-system (2.9); empty for loop-free models.
    subsystems: Vec<Vec<&'a str>>,
}

/// The JSON description of a model: sizes, joints in coordinate order, bodies, neutral q,
/// sub-systems.
pub fn describe(model: &Model) -> ModelJson<'_> {
    ModelJson {
        nq: model.nq(),
        nv: model.nv(),
        joints: model
            .joints()
            .iter()
            .map(|j| JointJson {
                name: &j.name,
                nq: j.nq,
                nv: j.nv,
            })
            .collect(),
        bodies: model.body_names(),
        neutral: model.neutral().iter().copied().collect(),
        subsystems: model.subsystem_names(),
    }
}
