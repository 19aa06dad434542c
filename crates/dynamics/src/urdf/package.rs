//! Finding the files a URDF refers to (meshes): `package://PKG/rest` through a search path of
//! folders, `file://` URIs, and paths relative to the URDF's folder.
//!
//! Search path, in order: the explicit folders (e.g. `--package-path DIR`), then the entries
//! of `ROS_PACKAGE_PATH` (colon-separated, empty entries skipped). For each folder `DIR`,
//! `package://PKG/rest` is `DIR/PKG/rest` when `DIR/PKG` is a folder, and `DIR/rest` when
//! `DIR`'s last component is `PKG`. The first candidate that is a file wins.

use std::path::{Path, PathBuf};

/// Why a file reference could not be resolved.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ResolveError {
    /// A `package://` URI without package or path, or another URI scheme.
    #[error("{0:?} is not package://PKG/path, file://path or a file path")]
    BadUri(String),
    /// No folder of the search path holds the package.
    #[error(
        "package {package:?} not found in the package path [{searched}] (add --package-path DIR)"
    )]
    PackageNotFound {
        /// Package name.
        package: String,
        /// The search path, `:`-separated.
        searched: String,
    },
    /// The reference resolved to a path that is not a file.
    #[error("file {} does not exist", path.display())]
    Missing {
        /// The resolved path.
        path: PathBuf,
    },
}

/// The folders `package://` URIs are looked up in (see the module docs).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct PackagePath {
    dirs: Vec<PathBuf>,
}

impl PackagePath {
    /// The explicit folders followed by the entries of `ros_package_path` (colon-separated).
    pub fn new(explicit: Vec<PathBuf>, ros_package_path: Option<&str>) -> Self {
        let mut dirs = explicit;
        let ros = ros_package_path.unwrap_or_default();
        dirs.extend(ros.split(':').filter(|d| !d.is_empty()).map(PathBuf::from));
        Self { dirs }
    }

    /// The explicit folders followed by the `ROS_PACKAGE_PATH` environment variable.
    pub fn from_env(explicit: Vec<PathBuf>) -> Self {
        let ros = std::env::var("ROS_PACKAGE_PATH").ok();
        Self::new(explicit, ros.as_deref())
    }

    /// The search path, in order.
    pub fn dirs(&self) -> &[PathBuf] {
        &self.dirs
    }

    /// The file `reference` names: a `package://` URI through the search path, a `file://`
    /// URI, or a path (relative ones against `base`, the URDF's folder). The file must exist.
    pub fn resolve(&self, reference: &str, base: &Path) -> Result<PathBuf, ResolveError> {
        if let Some(rest) = reference.strip_prefix("package://") {
            return self.resolve_package(reference, rest);
        }
        let path = match reference.strip_prefix("file://") {
            Some(path) if !path.is_empty() => base.join(path),
            Some(_) => return Err(ResolveError::BadUri(reference.to_string())),
            None if reference.contains("://") => {
                return Err(ResolveError::BadUri(reference.to_string()))
            }
            None => base.join(reference),
        };
        existing(path)
    }

    /// `package://PKG/rest` (`rest` is the text after the scheme).
    fn resolve_package(&self, reference: &str, rest: &str) -> Result<PathBuf, ResolveError> {
        let bad = || ResolveError::BadUri(reference.to_string());
        let (package, file) = rest.split_once('/').ok_or_else(bad)?;
        if package.is_empty() || file.is_empty() {
            return Err(bad());
        }
        let mut first = None;
        for dir in &self.dirs {
            let mut roots = Vec::with_capacity(2);
            if dir.join(package).is_dir() {
                roots.push(dir.join(package));
            }
            // the folder's own name, also for `DIR/..` or a symbolic link
            let real = dir.canonicalize().unwrap_or_else(|_| dir.clone());
            if real.file_name().is_some_and(|n| n == package) && dir.is_dir() {
                roots.push(dir.clone());
            }
            for root in roots {
                let path = root.join(file);
                if path.is_file() {
                    return Ok(path);
                }
                first.get_or_insert(path);
            }
        }
        match first {
            Some(path) => Err(ResolveError::Missing { path }),
            None => Err(ResolveError::PackageNotFound {
                package: package.to_string(),
                searched: self
                    .dirs
                    .iter()
                    .map(|d| d.display().to_string())
                    .collect::<Vec<_>>()
                    .join(":"),
            }),
        }
    }
}

/// `path` if it is a file.
fn existing(path: PathBuf) -> Result<PathBuf, ResolveError> {
    match path.is_file() {
        true => Ok(path),
        false => Err(ResolveError::Missing { path }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn package_uris_resolve_in_search_order() {
        let tmp = std::env::temp_dir().join(format!("biped_pkg_{}", std::process::id()));
        let (a, b) = (tmp.join("a"), tmp.join("b"));
        std::fs::create_dir_all(a.join("pkg/meshes")).unwrap();
        std::fs::create_dir_all(b.join("pkg/meshes")).unwrap();
        std::fs::write(b.join("pkg/meshes/m.stl"), "x").unwrap();
        std::fs::write(tmp.join("rel.stl"), "x").unwrap();
        let path = PackagePath::new(vec![a.clone()], Some(&format!(":{}", b.display())));
        assert_eq!(path.dirs(), [a.clone(), b.clone()]);
        let got = path.resolve("package://pkg/meshes/m.stl", &tmp).unwrap();
        assert_eq!(got, b.join("pkg/meshes/m.stl"));
        // a folder named like the package is the package root itself
        let direct = PackagePath::new(vec![b.join("pkg/meshes/..")], None);
        let got = direct.resolve("package://pkg/meshes/m.stl", &tmp).unwrap();
        assert_eq!(got, b.join("pkg/meshes/../meshes/m.stl"));
        // found package, missing file: the first resolved candidate is named
        let err = path.resolve("package://pkg/x.stl", &tmp).unwrap_err();
        assert_eq!(
            err,
            ResolveError::Missing {
                path: a.join("pkg/x.stl")
            }
        );
        let err = path.resolve("package://nope/x.stl", &tmp).unwrap_err();
        assert!(
            matches!(err, ResolveError::PackageNotFound { ref package, .. } if package == "nope")
        );
        assert_eq!(path.resolve("rel.stl", &tmp).unwrap(), tmp.join("rel.stl"));
        let abs = format!("file://{}", tmp.join("rel.stl").display());
        assert_eq!(path.resolve(&abs, &a).unwrap(), tmp.join("rel.stl"));
        for bad in ["package://pkg", "package:///x", "http://x/y.stl", "file://"] {
            assert_eq!(
                path.resolve(bad, &tmp),
                Err(ResolveError::BadUri(bad.into()))
            );
        }
        std::fs::remove_dir_all(&tmp).unwrap();
    }
}
