//! The JSON form of SSV primitives and distance queries shared by the command line
//! (`biped ssv query`) and the Python bindings: `{"point": [x, y, z], "radius": r}`,
//! `{"line": [p, q], "radius": r}` or `{"triangle": [p, q, s], "radius": r}`, and a query
//! `{"a": S, "b": S}`.

use crate::{distance, DistanceResult, Lss, Pss, Ssv, SsvError, Tss};
use nalgebra::Point3;
use serde::{Deserialize, Serialize};

/// One SSV as written in JSON: exactly one of `point`, `line`, `triangle`, plus `radius`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShapeJson {
    /// Centre of a point-swept sphere.
    pub point: Option<[f64; 3]>,
    /// End points of a line-swept sphere.
    pub line: Option<[[f64; 3]; 2]>,
    /// Corners of a triangle-swept sphere.
    pub triangle: Option<[[f64; 3]; 3]>,
    /// Radius (>= 0).
    pub radius: f64,
}

/// One query `{"a": S, "b": S}`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct QueryJson {
    /// First volume.
    pub a: ShapeJson,
    /// Second volume.
    pub b: ShapeJson,
}

/// One answer: signed distance and closest surface points.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct AnswerJson {
    /// Signed distance between the surfaces (negative on overlap).
    pub distance: f64,
    /// Closest point on the surface of `a`.
    pub point_a: [f64; 3],
    /// Closest point on the surface of `b`.
    pub point_b: [f64; 3],
}

impl From<&DistanceResult> for AnswerJson {
    fn from(r: &DistanceResult) -> Self {
        Self {
            distance: r.distance,
            point_a: r.point_a.coords.into(),
            point_b: r.point_b.coords.into(),
        }
    }
}

impl ShapeJson {
    /// The validated primitive; errors are prefixed with `"name": `.
    pub fn to_ssv(&self, name: &str) -> Result<Ssv, String> {
        let wrap = |e: SsvError| format!("\"{name}\": {e}");
        let pt = Point3::from;
        match (self.point, self.line, self.triangle) {
            (Some(p), None, None) => Pss::new(pt(p), self.radius).map(Ssv::from).map_err(wrap),
            (None, Some([a, b]), None) => Lss::new(pt(a), pt(b), self.radius)
                .map(Ssv::from)
                .map_err(wrap),
            (None, None, Some([a, b, c])) => Tss::new(pt(a), pt(b), pt(c), self.radius)
                .map(Ssv::from)
                .map_err(wrap),
            _ => Err(format!(
                "\"{name}\": needs exactly one of \"point\", \"line\", \"triangle\""
            )),
        }
    }
}

/// Parses one shape from JSON text; errors are prefixed with `"name": `.
pub fn parse_shape(text: &str, name: &str) -> Result<Ssv, String> {
    let shape: ShapeJson = serde_json::from_str(text).map_err(|e| format!("\"{name}\": {e}"))?;
    shape.to_ssv(name)
}

/// Parses one query line `{"a": S, "b": S}` into its two volumes.
pub fn parse_query(line: &str) -> Result<(Ssv, Ssv), String> {
    let q: QueryJson = serde_json::from_str(line).map_err(|e| e.to_string())?;
    Ok((q.a.to_ssv("a")?, q.b.to_ssv("b")?))
}

/// Answers one query line, or says what is wrong with it.
pub fn answer(line: &str) -> Result<AnswerJson, String> {
    let (a, b) = parse_query(line)?;
    Ok(AnswerJson::from(&distance(&a, &b)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_to_capsule_by_hand() {
        let line = r#"{"a": {"point": [0,0,0], "radius": 1}, "b": {"line": [[3,-1,0],[3,1,0]], "radius": 0.5}}"#;
        let r = answer(line).unwrap();
        assert!((r.distance - 1.5).abs() < 1e-15);
        assert_eq!(r.point_a, [1.0, 0.0, 0.0]);
        assert_eq!(r.point_b, [2.5, 0.0, 0.0]);
    }

    #[test]
    fn bad_shapes_name_the_field() {
        let two = r#"{"point": [0,0,0], "line": [[0,0,0],[1,0,0]], "radius": 1}"#;
        assert!(parse_shape(two, "a").unwrap_err().contains("exactly one"));
        let neg = r#"{"point": [0,0,0], "radius": -1}"#;
        assert!(parse_shape(neg, "b").unwrap_err().starts_with("\"b\": "));
    }
}
