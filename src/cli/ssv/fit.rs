//! `biped ssv fit ROBOT.urdf --out model.toml`: a first collision model from the collision
//! geometry of a URDF (SSVs containing each link's shapes, pairs chosen by sampling).

use crate::cli::files::WithPath;
use crate::cli::out::outln;
use crate::cli::{range, CliResult};
use biped_dynamics::urdf::{
    load_file, read_geometry_file, GeometryElement, PackagePath, Shape, UrdfModel, UrdfOptions,
};
use biped_dynamics::Model;
use biped_sim::record::write_whole;
use biped_ssv::fit::pairs::{candidates, count};
use biped_ssv::fit::{fit, Fitted, Geometry};
use biped_ssv::{format, mesh, CollisionModel, Segment};
use clap::Args;
use nalgebra::{Isometry3, Point3};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

mod sample;
use sample::Sampler;

/// Arguments of `biped ssv fit`.
#[derive(Args)]
pub struct FitArgs {
    /// URDF file whose `<collision>` elements are fitted.
    urdf: PathBuf,
    /// Collision-model file to write (TOML, the format `biped ssv model` reads).
    #[arg(long, allow_hyphen_values = true)]
    out: PathBuf,
    /// Folder to look up `package://PKG/...` mesh references in, before ROS_PACKAGE_PATH
    /// (repeatable).
    #[arg(long = "package-path", value_name = "DIR", allow_hyphen_values = true)]
    package_path: Vec<PathBuf>,
    /// Give the root link a free joint (its own body) instead of welding it to the world.
    #[arg(long)]
    floating: bool,
    /// Random configurations within the joint limits sampled to choose the pairs (1 to 10^6).
    #[arg(long, value_name = "N", default_value_t = 2000, allow_hyphen_values = true,
          value_parser = |s: &str| range::ssv_fit::SAMPLES.parse_whole(s).map(|n| n as u32))]
    samples: u32,
    /// Activation distance d_a of the model in metres: pairs that never come closer are left out
    /// (0.001 to 1).
    #[arg(long, value_name = "M", default_value_t = 0.05, allow_hyphen_values = true,
          value_parser = |s: &str| range::ssv_fit::ACTIVATION_DISTANCE.parse(s))]
    activation_distance: f64,
    /// Seed of the sampled configurations (a whole number >= 0).
    #[arg(long, default_value_t = 1, allow_hyphen_values = true)]
    seed: u64,
}

/// The inputs and outputs of `biped ssv fit`.
pub const FIT_HELP: &str = "\
Fit a first SSV collision model to the collision geometry of a URDF file.

Input: the URDF's <collision> elements (box, cylinder, sphere, capsule, mesh). Mesh files are
STL (binary or ASCII) or OBJ. package://PKG/rest resolves through --package-path DIR (DIR/PKG/rest,
or DIR/rest when DIR is named PKG), then ROS_PACKAGE_PATH (colon-separated); relative file names
resolve against the URDF's folder; file:// URIs are paths.

Each link with collision geometry becomes one segment on its body (links welded to the world: a
body named after the root link), in the body frame: per element a point SSV
(sphere), a line SSV (capsule, cylinder, long box or mesh) or a rectangle of two triangle SSVs
(flat box or mesh), whichever contains the shape with the least volume.

Pairs: every two segments on different bodies that are not parent and child, kept if they come closer than
the activation distance in at least one of --samples random configurations within the joint
limits (seeded) and are not in contact in 95 % or more of them.

Output: the model file (--out, written atomically) with the pose `zero` (all joints at 0), and one
line per link on stdout: the SSV kinds and the volume overhead (SSV volume / shape volume; n/a
for open meshes), then the number of pairs. Errors are one line (file, line, field) and exit 1.";

/// One link's fit: its segment, body and volumes.
struct LinkFit {
    link: String,
    body: usize,
    fits: Vec<Fitted>,
}

/// Fit, choose pairs, write and print.
pub fn run(args: FitArgs) -> CliResult {
    let d_a = args.activation_distance;
    if !(d_a.is_finite() && d_a >= 0.0) {
        return Err(format!("--activation-distance: {d_a} must be finite and >= 0").into());
    }
    let options = UrdfOptions {
        floating: args.floating,
        ..UrdfOptions::default()
    };
    let urdf = load_file(&args.urdf, &options)?;
    let search = PackagePath::from_env(args.package_path.clone());
    let base = args.urdf.parent().unwrap_or(Path::new("."));
    let links = fit_links(&urdf, &args.urdf, &search, base)?;
    let mut bodies: Vec<String> = urdf
        .model
        .body_names()
        .iter()
        .map(|s| s.to_string())
        .collect();
    if links.iter().any(|l| l.body == bodies.len()) {
        bodies.push(urdf.links[0].link.clone());
    }
    let mut model = CollisionModel::new(bodies.clone(), d_a)?;
    for l in &links {
        let ssvs = l.fits.iter().flat_map(|f| f.ssvs.iter().copied()).collect();
        model.add_segment(Segment::new(l.link.clone(), ssvs)?, l.body)?;
    }
    let all = model.clone();
    let adjacent = |child: usize, parent: usize| parent_of(&urdf.model, child) == Some(parent);
    for (a, b) in candidates(model.segment_bodies(), adjacent) {
        model.add_pair(a, b)?;
    }
    let samples = args.samples as usize;
    let mut sampler = Sampler::new(&urdf, args.seed);
    let counts = count::<Box<dyn std::error::Error>>(&mut model, samples, |_, poses| {
        sampler.random_poses(&urdf.model, poses)
    })?;
    let mut out = all;
    for c in counts.iter().filter(|c| c.kept(samples)) {
        out.add_pair(c.a, c.b)?;
    }
    let mut zero = vec![Isometry3::identity(); bodies.len()];
    sampler.poses(&urdf.model, &urdf.model.neutral(), &mut zero)?;
    let poses = BTreeMap::from([("zero".to_string(), zero)]);
    let text = format::to_toml_string(&out, &poses)?;
    // A reader never sees a partial file: a temporary sibling renamed over `--out`.
    write_whole(&args.out, |tmp| std::fs::write(tmp, &text)).with_path(&args.out)?;
    for l in &links {
        outln!("{}", link_line(l))?;
    }
    let never = counts.iter().filter(|c| c.close == 0).count();
    outln!(
        "{} pairs of {} candidates ({never} never within d_a = {d_a} m, {} always in contact; {samples} samples); wrote {}",
        out.pairs().len(),
        counts.len(),
        counts.len() - never - out.pairs().len(),
        args.out.display()
    )?;
    Ok(ExitCode::SUCCESS)
}

/// The parent body of `body`, with the world as body `nbodies` (where welded links go).
fn parent_of(model: &Model, body: usize) -> Option<usize> {
    let b = model.body(body)?;
    Some(b.parent().unwrap_or(model.nbodies()))
}

/// `link  kinds  overhead x` for one link.
fn link_line(l: &LinkFit) -> String {
    let kinds: Vec<String> = l.fits.iter().map(|f| f.kind.to_string()).collect();
    let volume: f64 = l.fits.iter().map(|f| f.volume).sum();
    let shapes: Option<f64> = l.fits.iter().map(|f| f.shape_volume).sum();
    let overhead = match shapes {
        Some(v) if v > 0.0 => format!("overhead {:.2}", volume / v),
        _ => "overhead n/a (open mesh)".to_string(),
    };
    format!("{:<28} {:<24} {overhead}", l.link, kinds.join(" + "))
}

/// The fits of every link with collision geometry, in the body frames of `urdf`'s model
/// (links welded to the world on body `nbodies`).
fn fit_links(
    urdf: &UrdfModel,
    file: &Path,
    search: &PackagePath,
    base: &Path,
) -> Result<Vec<LinkFit>, Box<dyn std::error::Error>> {
    let mut out = Vec::new();
    for geometry in read_geometry_file(file)? {
        if geometry.collisions.is_empty() {
            continue;
        }
        let frame = urdf
            .links
            .iter()
            .find(|l| l.link == geometry.link)
            .ok_or_else(|| {
                format!(
                    "{}: link {:?} is not in the kinematic tree",
                    file.display(),
                    geometry.link
                )
            })?;
        let mut fits = Vec::new();
        for element in &geometry.collisions {
            let pose = frame.pose * element.origin;
            fits.push(fit_element(element, &pose, search, base)?);
        }
        out.push(LinkFit {
            link: geometry.link.clone(),
            body: frame.body.unwrap_or(urdf.model.nbodies()),
            fits,
        });
    }
    Ok(out)
}

/// The fit of one collision element at `pose` (its origin in the body frame).
fn fit_element(
    element: &GeometryElement,
    pose: &Isometry3<f64>,
    search: &PackagePath,
    base: &Path,
) -> Result<Fitted, Box<dyn std::error::Error>> {
    let fitted = match &element.shape {
        Shape::Box { size } => fit(&Geometry::Cuboid { size: *size }, pose),
        Shape::Cylinder { radius, length } => fit(
            &Geometry::Cylinder {
                radius: *radius,
                length: *length,
            },
            pose,
        ),
        Shape::Sphere { radius } => fit(&Geometry::Sphere { radius: *radius }, pose),
        Shape::Capsule { radius, length } => fit(
            &Geometry::Capsule {
                radius: *radius,
                length: *length,
            },
            pose,
        ),
        Shape::Mesh { filename, scale } => {
            let path = search
                .resolve(filename, base)
                .map_err(|e| element.invalid("mesh filename", e.to_string()))?;
            let m = mesh::read_file(&path).map_err(|e| element.invalid("mesh", e.to_string()))?;
            let points: Vec<Point3<f64>> = m
                .vertices()
                .iter()
                .map(|p| Point3::new(p.x * scale[0], p.y * scale[1], p.z * scale[2]))
                .collect();
            let volume = m
                .volume()
                .map(|v| v * (scale[0] * scale[1] * scale[2]).abs());
            fit(
                &Geometry::Points {
                    points: &points,
                    volume,
                },
                pose,
            )
        }
    };
    Ok(fitted.map_err(|e| element.invalid("geometry", e.to_string()))?)
}
