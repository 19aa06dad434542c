//! Parsers of the option values of `biped simulate`; every error names the option.

/// A finite number > 0.
pub fn positive(option: &str, text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
        Ok(x) => Err(format!("{option}: must be finite and > 0, got {x}")),
        Err(e) => Err(format!("{option}: \"{text}\" is not a number ({e})")),
    }
}

/// A whole number >= 1.
pub fn count(option: &str, text: &str) -> Result<u64, String> {
    match text.trim().parse::<u64>() {
        Ok(n) if n >= 1 => Ok(n),
        _ => Err(format!(
            "{option}: expected a whole number >= 1, got \"{text}\""
        )),
    }
}

/// Exactly `n` comma-separated finite numbers.
pub fn numbers(text: &str, n: usize, option: &str) -> Result<Vec<f64>, String> {
    let parsed: Result<Vec<f64>, _> = text.split(',').map(|s| s.trim().parse::<f64>()).collect();
    match parsed {
        Ok(v) if v.len() == n && v.iter().all(|x| x.is_finite()) => Ok(v),
        _ => Err(format!(
            "{option}: expected {n} comma-separated finite numbers, got \"{text}\""
        )),
    }
}

/// Exactly `n` comma-separated non-empty names.
pub fn names(text: &str, n: usize, option: &str, shape: &str) -> Result<Vec<String>, String> {
    let v: Vec<String> = text.split(',').map(|s| s.trim().to_string()).collect();
    if v.len() != n || v.iter().any(String::is_empty) {
        return Err(format!("{option}: expected {shape}, got \"{text}\""));
    }
    Ok(v)
}

/// `JOINT=ANGLE` pairs separated by commas.
pub fn parse_pose(text: &str) -> Result<Vec<(String, f64)>, String> {
    named_values(text, "--pose", "JOINT=ANGLE", "angle")
}

/// `PATTERN=KG_M2` pairs separated by commas (reflected rotor inertias of URDF joints).
pub fn parse_armature(text: &str) -> Result<Vec<(String, f64)>, String> {
    named_values(text, "--armature", "JOINT=KG_M2", "inertia")
}

/// `NAME=VALUE` pairs separated by commas, each value a finite number (`quantity` in errors).
fn named_values(
    text: &str,
    option: &str,
    shape: &str,
    quantity: &str,
) -> Result<Vec<(String, f64)>, String> {
    text.split(',')
        .map(|item| {
            let bad =
                || format!("{option}: expected {shape} with a finite {quantity}, got \"{item}\"");
            let (name, value) = item.split_once('=').ok_or_else(bad)?;
            let value: f64 = value.trim().parse().map_err(|_| bad())?;
            if name.trim().is_empty() || !value.is_finite() {
                return Err(bad());
            }
            Ok((name.trim().to_string(), value))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn option_values() {
        assert_eq!(positive("--x", " 2.5 "), Ok(2.5));
        assert!(positive("--x", "0").is_err() && positive("--x", "nan").is_err());
        assert_eq!(count("--n", "12"), Ok(12));
        assert!(count("--n", "0").is_err() && count("--n", "-1").is_err());
        assert_eq!(numbers("1, -2,3e-1", 3, "--v"), Ok(vec![1.0, -2.0, 0.3]));
        assert!(numbers("1,2", 3, "--v")
            .unwrap_err()
            .starts_with("--v: expected 3"));
        assert!(numbers("1,inf", 2, "--v").is_err());
        assert_eq!(
            names("a, b", 2, "--n", "A,B"),
            Ok(vec!["a".into(), "b".into()])
        );
        assert!(names("a,", 2, "--n", "A,B").is_err());
        let pose = parse_pose("knee=0.4, hip = -0.2").unwrap();
        assert_eq!(pose, vec![("knee".into(), 0.4), ("hip".into(), -0.2)]);
        let arm = parse_armature("*_knee_joint=0.025").unwrap();
        assert_eq!(arm, vec![("*_knee_joint".into(), 0.025)]);
        assert!(parse_armature("*_knee_joint")
            .unwrap_err()
            .starts_with("--armature: expected JOINT=KG_M2"));
        for bad in ["knee", "=1", "knee=x", "knee=inf", ""] {
            assert!(parse_pose(bad).is_err(), "{bad}");
        }
    }
}
