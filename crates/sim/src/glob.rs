//! Name patterns with `*` as the only wildcard (joint patterns of `--armature`, signal
//! selections of `--plot`).

/// True if `name` matches `pattern`, where `*` matches any run of characters (none included)
/// and everything else matches itself; a pattern without `*` matches only itself.
pub fn glob_match(pattern: &str, name: &str) -> bool {
    let mut parts = pattern.split('*');
    let first = parts.next().unwrap_or("");
    let Some(mut rest) = name.strip_prefix(first) else {
        return false;
    };
    let parts: Vec<&str> = parts.collect();
    let Some((last, middle)) = parts.split_last() else {
        return rest.is_empty(); // No `*`: exact match.
    };
    for part in middle {
        match rest.find(part) {
            Some(at) => rest = &rest[at + part.len()..],
            None => return false,
        }
    }
    rest.len() >= last.len() && rest.ends_with(last)
}

#[cfg(test)]
mod tests {
    use super::glob_match as matches;

    #[test]
    fn glob_patterns() {
        assert!(matches("left_knee_joint", "left_knee_joint"));
        assert!(!matches("left_knee_joint", "left_knee_joint2"));
        assert!(matches("*_knee_joint", "left_knee_joint"));
        assert!(matches("*knee*", "left_knee_joint"));
        assert!(matches("*", ""));
        assert!(matches("left_*_joint", "left_hip_pitch_joint"));
        assert!(!matches("left_*_joint", "right_hip_pitch_joint"));
        assert!(!matches("*_ankle_*_joint", "left_knee_joint"));
        assert!(matches("a*a", "aa"));
        assert!(!matches("a*a", "a"));
        assert!(matches("*_hip_*", "left_hip_roll_joint"));
    }
}
