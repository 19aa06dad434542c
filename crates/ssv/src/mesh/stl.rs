//! STL reader: binary (80-byte header, triangle count, 50 bytes per triangle) or ASCII
//! (`solid ... facet ... outer loop vertex x y z ... endloop ... endsolid`). A file whose size
//! matches its binary triangle count is binary, else one starting with `solid` is ASCII.

use super::{invalid, text, Mesh, MeshError, Welder};
use nalgebra::Point3;

/// Parses STL bytes; `file` labels errors.
pub(super) fn parse(data: &[u8], file: &str) -> Result<Mesh, MeshError> {
    let binary_count = data
        .get(80..84)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as u64);
    if let Some(n) = binary_count {
        if 84 + 50 * n == data.len() as u64 {
            return binary(data, n as usize, file);
        }
    }
    let text_start = data.iter().position(|b| !b.is_ascii_whitespace());
    if text_start.is_some_and(|s| data[s..].starts_with(b"solid")) {
        return ascii(data, file);
    }
    let problem = match binary_count {
        Some(n) => format!(
            "not ASCII STL (no `solid`) and not binary STL ({n} triangles need {} bytes, the file has {})",
            84 + 50 * n,
            data.len()
        ),
        None => format!("{} bytes are too few for an STL file", data.len()),
    };
    Err(invalid(file, "header".into(), problem))
}

/// A binary STL file of `n` triangles (the size was checked).
fn binary(data: &[u8], n: usize, file: &str) -> Result<Mesh, MeshError> {
    let mut weld = Welder::new();
    let mut triangles = Vec::with_capacity(n);
    for (k, record) in data[84..].chunks_exact(50).enumerate() {
        let mut tri = [0u32; 3];
        for (v, slot) in tri.iter_mut().enumerate() {
            // 12 bytes of normal, then three vertices of three little-endian f32 each
            let at = 12 + 12 * v;
            let c = |i: usize| {
                let b = &record[at + 4 * i..at + 4 * i + 4];
                f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64
            };
            let p = Point3::new(c(0), c(1), c(2));
            if !p.iter().all(|x| x.is_finite()) {
                return Err(invalid(
                    file,
                    format!("triangle {k}"),
                    "vertex is not finite",
                ));
            }
            *slot = weld
                .add(p)
                .ok_or_else(|| invalid(file, format!("triangle {k}"), "too many vertices"))?;
        }
        triangles.push(tri);
    }
    Ok(Mesh::new(weld.vertices, triangles))
}

/// An ASCII STL file: the vertices of each `outer loop` (three or more, fanned into
/// triangles).
fn ascii(data: &[u8], file: &str) -> Result<Mesh, MeshError> {
    let text = text(data, file)?;
    let mut weld = Welder::new();
    let mut triangles = Vec::new();
    let mut polygon: Option<Vec<u32>> = None;
    for (k, line) in text.lines().enumerate() {
        let at = || format!("line {}", k + 1);
        let mut words = line.split_whitespace();
        match (words.next(), &mut polygon) {
            (Some("outer"), None) => polygon = Some(Vec::new()),
            (Some("vertex"), Some(poly)) => {
                let p = point(words).ok_or_else(|| {
                    invalid(file, at(), "expected `vertex x y z` with finite numbers")
                })?;
                poly.push(
                    weld.add(p)
                        .ok_or_else(|| invalid(file, at(), "too many vertices"))?,
                );
            }
            (Some("endloop"), Some(poly)) => {
                if poly.len() < 3 {
                    return Err(invalid(
                        file,
                        at(),
                        format!("a loop of {} vertices", poly.len()),
                    ));
                }
                triangles.extend((1..poly.len() - 1).map(|i| [poly[0], poly[i], poly[i + 1]]));
                polygon = None;
            }
            (Some(w @ ("outer" | "vertex" | "endloop")), _) => {
                return Err(invalid(file, at(), format!("`{w}` out of place")));
            }
            _ => {}
        }
    }
    if polygon.is_some() {
        let line = text.lines().count();
        return Err(invalid(
            file,
            format!("line {line}"),
            "`outer loop` without `endloop`",
        ));
    }
    Ok(Mesh::new(weld.vertices, triangles))
}

/// Three finite numbers and nothing else.
pub(super) fn point<'a>(mut words: impl Iterator<Item = &'a str>) -> Option<Point3<f64>> {
    let mut c = [0.0; 3];
    for x in &mut c {
        *x = words
            .next()?
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())?;
    }
    Some(Point3::from(c))
}
