//! Triangle meshes read from STL (binary and ASCII) and OBJ files, for fitting SSVs to them:
//! vertices, triangles, the enclosed volume (divergence theorem) and whether the surface is
//! closed. The readers are linear in the file and hold the file and the mesh only; files
//! above [`MAX_FILE_BYTES`] are refused before they are read.

mod obj;
mod stl;

use nalgebra::Point3;
use std::collections::HashMap;
use std::path::Path;

/// Largest mesh file read (bytes): 1 GiB, some 20 million STL triangles.
pub const MAX_FILE_BYTES: u64 = 1 << 30;

/// Why a mesh file could not be read.
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// The file could not be read.
    #[error("{file}: cannot read mesh file: {source}")]
    Io {
        /// File name.
        file: String,
        /// Underlying I/O error.
        source: std::io::Error,
    },
    /// The file is larger than [`MAX_FILE_BYTES`].
    #[error("{file}: mesh file of {bytes} bytes exceeds the limit of {MAX_FILE_BYTES} bytes")]
    TooLarge {
        /// File name.
        file: String,
        /// File size.
        bytes: u64,
    },
    /// The content is not a mesh of the expected format, at a place (`line 7`, `triangle 3`).
    #[error("{file}: {at}: {problem}")]
    Invalid {
        /// File name.
        file: String,
        /// Where in the file, e.g. `line 7` or `header`.
        at: String,
        /// What is wrong.
        problem: String,
    },
    /// The file name has no extension the readers know.
    #[error("{file}: unknown mesh format (expected .stl or .obj)")]
    UnknownFormat {
        /// File name.
        file: String,
    },
}

/// A triangle mesh: finite vertices and triangles as vertex indices (no degenerate ones).
#[derive(Debug, Clone, PartialEq)]
pub struct Mesh {
    vertices: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// The mesh of `vertices` and `triangles`; triangles that repeat a vertex index are
    /// dropped (they enclose nothing). The readers guarantee finite vertices and valid indices.
    fn new(vertices: Vec<Point3<f64>>, mut triangles: Vec<[u32; 3]>) -> Self {
        triangles.retain(|[a, b, c]| a != b && b != c && a != c);
        Self {
            vertices,
            triangles,
        }
    }

    /// The vertices.
    pub fn vertices(&self) -> &[Point3<f64>] {
        &self.vertices
    }

    /// The triangles, as indices into [`Self::vertices`].
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Whether the surface is closed and consistently oriented: every edge is used as often
    /// from `a` to `b` as from `b` to `a` (CAD exports often have bodies touching along an
    /// edge, used by four triangles; the divergence theorem holds for them too).
    pub fn is_closed(&self) -> bool {
        // +1 for a -> b with a < b, -1 for the reverse: closed iff every sum is zero
        let mut edges: HashMap<(u32, u32), i64> = HashMap::with_capacity(3 * self.triangles.len());
        for &[a, b, c] in &self.triangles {
            for (p, q) in [(a, b), (b, c), (c, a)] {
                let (key, sign) = if p < q { ((p, q), 1) } else { ((q, p), -1) };
                *edges.entry(key).or_insert(0) += sign;
            }
        }
        !edges.is_empty() && edges.values().all(|&n| n == 0)
    }

    /// The enclosed volume by the divergence theorem, `|sum (v0 . (v1 x v2)) / 6|` over the
    /// triangles (about the vertex centroid, for rounding); `None` if the mesh is not closed.
    pub fn volume(&self) -> Option<f64> {
        if !self.is_closed() {
            return None;
        }
        let n = self.vertices.len() as f64;
        let c = self
            .vertices
            .iter()
            .map(|p| p.coords)
            .sum::<nalgebra::Vector3<f64>>()
            / n;
        let six: f64 = self
            .triangles
            .iter()
            .map(|t| {
                let [a, b, d] = t.map(|i| self.vertices[i as usize].coords - c);
                a.dot(&b.cross(&d))
            })
            .sum();
        Some((six / 6.0).abs())
    }
}

/// Reads a mesh file, STL or OBJ by its extension (case-insensitive).
pub fn read_file(path: impl AsRef<Path>) -> Result<Mesh, MeshError> {
    let path = path.as_ref();
    let file = path.display().to_string();
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    let format = match ext.as_deref() {
        Some("stl") => stl::parse,
        Some("obj") => obj::parse,
        _ => return Err(MeshError::UnknownFormat { file }),
    };
    let io = |source| MeshError::Io {
        file: file.clone(),
        source,
    };
    let bytes = std::fs::metadata(path).map_err(io)?.len();
    if bytes > MAX_FILE_BYTES {
        return Err(MeshError::TooLarge { file, bytes });
    }
    let data = std::fs::read(path).map_err(io)?;
    format(&data, &file)
}

/// Parses STL bytes (binary or ASCII); `file` labels errors.
pub fn parse_stl(data: &[u8], file: &str) -> Result<Mesh, MeshError> {
    stl::parse(data, file)
}

/// Parses OBJ bytes; `file` labels errors.
pub fn parse_obj(data: &[u8], file: &str) -> Result<Mesh, MeshError> {
    obj::parse(data, file)
}

/// Merges equal vertices (bit-identical coordinates) into one index, so that the triangle
/// soup of an STL file becomes a mesh whose closedness can be checked.
struct Welder {
    index: HashMap<[u64; 3], u32>,
    vertices: Vec<Point3<f64>>,
}

impl Welder {
    fn new() -> Self {
        Self {
            index: HashMap::new(),
            vertices: Vec::new(),
        }
    }

    /// The index of vertex `p` (`-0.0` is `0.0`); `None` beyond `u32` indices.
    fn add(&mut self, p: Point3<f64>) -> Option<u32> {
        let key = [p.x, p.y, p.z].map(|x| (x + 0.0).to_bits());
        if let Some(&i) = self.index.get(&key) {
            return Some(i);
        }
        let i = u32::try_from(self.vertices.len()).ok()?;
        self.index.insert(key, i);
        self.vertices.push(p);
        Some(i)
    }
}

/// A [`MeshError::Invalid`].
fn invalid(file: &str, at: String, problem: impl Into<String>) -> MeshError {
    MeshError::Invalid {
        file: file.to_string(),
        at,
        problem: problem.into(),
    }
}

/// `data` as UTF-8 text, or an error naming the first line that is not.
fn text<'a>(data: &'a [u8], file: &str) -> Result<&'a str, MeshError> {
    std::str::from_utf8(data).map_err(|e| {
        let line = 1 + data[..e.valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        invalid(file, format!("line {line}"), "not UTF-8 text")
    })
}
