//! OBJ reader: vertices (`v x y z [w]`) and faces (`f i j k ...`, indices `i`, `i/t`, `i//n`
//! or `i/t/n`, 1-based or negative = relative to the last vertex; polygons fanned into
//! triangles). Other statements (normals, texture coordinates, groups, materials) are skipped.

use super::{invalid, text, Mesh, MeshError};
use nalgebra::Point3;

/// Parses OBJ bytes; `file` labels errors.
pub(super) fn parse(data: &[u8], file: &str) -> Result<Mesh, MeshError> {
    let text = text(data, file)?;
    let mut vertices: Vec<Point3<f64>> = Vec::new();
    let mut triangles = Vec::new();
    let mut face = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let at = || format!("line {}", k + 1);
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let coords: Vec<&str> = words.collect();
                let p = (coords.len() <= 4)
                    .then(|| super::stl::point(coords.into_iter()))
                    .flatten();
                let p = p.ok_or_else(|| {
                    invalid(file, at(), "expected `v x y z [w]` with finite numbers")
                })?;
                vertices.push(p);
            }
            Some("f") => {
                face.clear();
                for word in words {
                    let index =
                        vertex_index(word, vertices.len()).map_err(|p| invalid(file, at(), p))?;
                    face.push(index);
                }
                if face.len() < 3 {
                    return Err(invalid(
                        file,
                        at(),
                        format!("a face of {} vertices", face.len()),
                    ));
                }
                triangles.extend((1..face.len() - 1).map(|i| [face[0], face[i], face[i + 1]]));
            }
            _ => {}
        }
    }
    Ok(Mesh::new(vertices, triangles))
}

/// The 0-based vertex index of the face entry `word` with `count` vertices defined so far.
fn vertex_index(word: &str, count: usize) -> Result<u32, String> {
    let first = word.split('/').next().unwrap_or_default();
    let Ok(i) = first.parse::<i64>() else {
        return Err(format!("face entry {word:?} is not a vertex index"));
    };
    let n = count as i64;
    let index = match i {
        _ if 1 <= i && i <= n => i - 1,
        _ if i < 0 && -i <= n => n + i,
        _ => {
            return Err(format!(
                "vertex index {i} is not among the {count} vertices defined above"
            ))
        }
    };
    u32::try_from(index).map_err(|_| "too many vertices".to_string())
}
