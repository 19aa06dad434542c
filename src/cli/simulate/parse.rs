//! Parsers of the non-numeric and named-value options of `biped simulate`; every error names
//! the option. Plain numbers and number lists are checked by [`crate::cli::range`].

use crate::cli::range::simulate::{ARMATURE, POSE_ANGLE};
use crate::cli::range::Quantity;

/// Exactly `n` comma-separated, non-empty and distinct names.
pub fn names(text: &str, n: usize, option: &str, shape: &str) -> Result<Vec<String>, String> {
    let v: Vec<String> = text.split(',').map(|s| s.trim().to_string()).collect();
    if v.len() != n || v.iter().any(String::is_empty) {
        return Err(format!("{option}: expected {shape}, got \"{text}\""));
    }
    if let Some((k, name)) = v.iter().enumerate().find(|(k, x)| v[..*k].contains(x)) {
        let first = v.iter().position(|x| x == name).unwrap_or(k);
        return Err(format!(
            "{option}: `{name}` is given twice (entries {} and {} of {shape}), each must be a \
             different one",
            first + 1,
            k + 1
        ));
    }
    Ok(v)
}

/// `JOINT=ANGLE` pairs separated by commas.
pub fn parse_pose(text: &str) -> Result<Vec<(String, f64)>, String> {
    named_values(text, "JOINT=ANGLE", &POSE_ANGLE)
}

/// `PATTERN=KG_M2` pairs separated by commas (reflected rotor inertias of URDF joints).
pub fn parse_armature(text: &str) -> Result<Vec<(String, f64)>, String> {
    named_values(text, "JOINT=KG_M2", &ARMATURE)
}

/// `NAME=VALUE` pairs separated by commas, each value a number in the range of `q`.
fn named_values(text: &str, shape: &str, q: &Quantity) -> Result<Vec<(String, f64)>, String> {
    text.split(',')
        .map(|item| {
            let bad = || {
                format!(
                    "{}: expected {shape} with a finite {}, got \"{item}\"",
                    q.flag, q.name
                )
            };
            let (name, value) = item.split_once('=').ok_or_else(bad)?;
            let value: f64 = value.trim().parse().map_err(|_| bad())?;
            let name = name.trim();
            if name.is_empty() || !value.is_finite() {
                return Err(bad());
            }
            q.check_as(&format!("`{name}`"), value)?;
            Ok((name.to_string(), value))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn option_values() {
        assert_eq!(
            names("a, b", 2, "--n", "A,B"),
            Ok(vec!["a".into(), "b".into()])
        );
        assert!(names("a,", 2, "--n", "A,B").is_err());
        let e = names("l,l", 2, "--feet", "LEFT,RIGHT").unwrap_err();
        assert!(
            e.starts_with("--feet: `l` is given twice (entries 1 and 2"),
            "{e}"
        );
        let pose = parse_pose("knee=0.4, hip = -0.2").unwrap();
        assert_eq!(pose, vec![("knee".into(), 0.4), ("hip".into(), -0.2)]);
        let arm = parse_armature("*_knee_joint=0.025").unwrap();
        assert_eq!(arm, vec![("*_knee_joint".into(), 0.025)]);
        assert!(parse_armature("*_knee_joint")
            .unwrap_err()
            .starts_with("--armature: expected JOINT=KG_M2"));
        let e = parse_armature("*_knee_joint=-0.02").unwrap_err();
        assert!(
            e.starts_with("--armature: `*_knee_joint` -0.02 kg m^2 is out of range"),
            "{e}"
        );
        let e = parse_pose("knee=100").unwrap_err();
        assert!(
            e.starts_with("--pose: `knee` 100 rad is out of range"),
            "{e}"
        );
        for bad in ["knee", "=1", "knee=x", "knee=inf", ""] {
            assert!(parse_pose(bad).is_err(), "{bad}");
        }
    }
}
