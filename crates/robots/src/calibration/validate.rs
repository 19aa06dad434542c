//! Checks of a parsed calibration file that need no model: distinct names, and weights,
//! targets and frame offsets within their physical ranges ([`super::limits`]). Every error
//! names the file, the line of the offending element and the field.

use super::file::LoadedFile;
use super::limits::{first_repeat, Range, ANGLE, LENGTH, WEIGHT};
use super::locate::array_element;
use super::spec::PoseSpec;
use super::CalibrationError;

impl LoadedFile {
    /// Distinct joint, constraint and pose names; weights, jig targets and frame offsets in
    /// range.
    pub(crate) fn check_values(&self) -> Result<(), CalibrationError> {
        let s = &self.spec;
        self.distinct("joints", s.joints.iter().map(String::as_str), "joint")?;
        let names = s.constraints.iter().map(|c| c.name.as_str());
        self.distinct("constraints", names, "constraint name")?;
        self.distinct(
            "poses",
            s.poses.iter().map(|p| p.name.as_str()),
            "pose name",
        )?;
        for (i, c) in s.constraints.iter().enumerate() {
            let at = array_element(&self.text, "constraints", i);
            let weights = [
                ("position_weight", c.position_weight),
                ("orientation_weight", c.orientation_weight),
            ];
            for (key, w) in weights {
                WEIGHT.check(w).map_err(|m| {
                    let field = format!("constraints[{i}].{key}");
                    self.error_after(at, key, field, format!("weight {m}"))
                })?;
            }
            for (key, f) in [("frame_a", &c.frame_a), ("frame_b", &c.frame_b)] {
                let offset = PoseSpec {
                    xyz: f.xyz,
                    rpy: f.rpy,
                };
                let field = format!("constraints[{i}].{key}");
                self.pose_in_range(&offset, at, key, &field)?;
            }
        }
        for (i, p) in s.poses.iter().enumerate() {
            let at = array_element(&self.text, "poses", i);
            for (name, target) in &p.targets {
                let field = format!("poses[{i}].targets.{name}");
                self.pose_in_range(target, at, name, &field)?;
            }
        }
        Ok(())
    }

    /// `xyz` within [`LENGTH`], `rpy` within [`ANGLE`]; errors located at `needle` after
    /// byte `at`, the field extended by the component (`...xyz[0]`).
    fn pose_in_range(
        &self,
        pose: &PoseSpec,
        at: usize,
        needle: &str,
        field: &str,
    ) -> Result<(), CalibrationError> {
        let parts: [(&str, &[f64; 3], Range); 2] =
            [("xyz", &pose.xyz, LENGTH), ("rpy", &pose.rpy, ANGLE)];
        for (key, values, range) in parts {
            for (k, &x) in values.iter().enumerate() {
                range
                    .check(x)
                    .map_err(|m| self.error_after(at, needle, format!("{field}.{key}[{k}]"), m))?;
            }
        }
        Ok(())
    }

    /// A located error at the first name of the array `key` that repeats an earlier one.
    fn distinct<'a>(
        &self,
        key: &str,
        names: impl Iterator<Item = &'a str>,
        what: &str,
    ) -> Result<(), CalibrationError> {
        let names: Vec<&str> = names.collect();
        let Some((first, again)) = first_repeat(names.iter().copied()) else {
            return Ok(());
        };
        let name = names[again];
        let at = array_element(&self.text, key, again);
        let message = format!("duplicate {what} `{name}` (also {key}[{first}])");
        Err(self.error_after(at, name, format!("{key}[{again}]"), message))
    }
}
