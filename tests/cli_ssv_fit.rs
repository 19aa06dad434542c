//! End-to-end tests of `biped ssv fit`: a URDF the test writes (box, cylinder, sphere and mesh
//! links, meshes found through --package-path and relative to the URDF), the pairs chosen by
//! sampling, the written model loaded back, located errors, and the bundled G1 when
//! example-robot-data is installed (ROBOTS, see scripts/fetch_robots.sh).

mod common;

use biped_dynamics::urdf::{load_file, read_geometry_file, PackagePath, Shape, UrdfOptions};
use biped_ssv::{distance, format, mesh, Pss, Ssv};
use common::run;
use nalgebra::{Isometry3, Point3};
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A fresh folder for one test.
fn folder(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("ssv_fit_{name}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("pkgs/mypkg/meshes")).unwrap();
    dir
}

/// A unit cube as binary STL (12 triangles, outward).
fn cube_stl() -> Vec<u8> {
    let v = |k: usize| [0, 1, 2].map(|a| if k >> a & 1 == 1 { 0.5f32 } else { -0.5 });
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let mut out = vec![0u8; 80];
    out.extend(12u32.to_le_bytes());
    for q in quads {
        for t in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
            out.extend([0u8; 12]);
            t.iter()
                .for_each(|&i| out.extend(v(i).iter().flat_map(|x| x.to_le_bytes())));
            out.extend([0u8; 2]);
        }
    }
    out
}

/// A tetrahedron as OBJ (open: one face missing).
const OPEN_OBJ: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n";

fn link(name: &str, shape: &str) -> String {
    format!("  <link name=\"{name}\">\n    <collision>\n      <geometry>{shape}</geometry>\n    </collision>\n  </link>\n")
}

fn joint(name: &str, kind: &str, parent: &str, child: &str, xyz: &str, limit: &str) -> String {
    format!(
        "  <joint name=\"{name}\" type=\"{kind}\"><parent link=\"{parent}\"/><child link=\"{child}\"/>\
         <origin xyz=\"{xyz}\"/><axis xyz=\"0 0 1\"/><limit lower=\"{}\" upper=\"{}\" effort=\"1\" velocity=\"1\"/></joint>\n",
        limit.split(' ').next().unwrap(),
        limit.split(' ').nth(1).unwrap()
    )
}

/// Base (cube 0.2) welded to the world; a, b spheres inside it (b a grandchild: always in
/// contact with the base); c swings its sphere at 1 m by [0, pi/2] about z and meets d's at
/// (0, 1, 0); far and far2 (meshes) 10 m away on a prismatic joint.
fn robot(dir: &Path, far_mesh: &str) -> PathBuf {
    let sphere = "<sphere radius=\"0.1\"/>";
    let mut xml = String::from("<robot name=\"test\">\n");
    xml += &link("base", "<box size=\"0.2 0.2 0.2\"/>");
    xml += &link("a", "<sphere radius=\"0.05\"/>");
    xml += &link("b", "<capsule radius=\"0.02\" length=\"0.04\"/>");
    xml += &link("c", &format!("{sphere}</geometry></collision><collision><origin xyz=\"0 0 0.3\"/><geometry><cylinder radius=\"0.02\" length=\"0.1\"/>"));
    xml += &link("d", sphere);
    xml += &link(
        "far",
        &format!("<mesh filename=\"{far_mesh}\" scale=\"0.1 0.2 0.3\"/>"),
    );
    xml += &link("far2", "<mesh filename=\"meshes/open.obj\"/>");
    xml += &joint("ja", "continuous", "base", "a", "0 0 0", "0 0");
    xml += &joint("jb", "revolute", "a", "b", "0 0 0", "-1 1");
    xml += &joint(
        "jc",
        "revolute",
        "base",
        "c",
        "0 0 0",
        "0 1.5707963267948966",
    );
    xml += &joint("jd", "revolute", "base", "d", "0 1 0", "-0.01 0.01");
    xml += &joint("jfar", "prismatic", "base", "far", "10 0 0", "0 0.1");
    xml += &joint("jfar2", "revolute", "far", "far2", "0 0 0.5", "-1 1");
    xml += "</robot>\n";
    // c's sphere sits at 1 m along its x axis: move it with the collision origin
    let xml = xml.replacen(
        &format!("<link name=\"c\">\n    <collision>\n      <geometry>{sphere}"),
        &format!(
            "<link name=\"c\">\n    <collision>\n      <origin xyz=\"1 0 0\"/><geometry>{sphere}"
        ),
        1,
    );
    std::fs::write(dir.join("pkgs/mypkg/meshes/cube.stl"), cube_stl()).unwrap();
    std::fs::create_dir_all(dir.join("meshes")).unwrap();
    std::fs::write(dir.join("meshes/open.obj"), OPEN_OBJ).unwrap();
    let path = dir.join("robot.urdf");
    std::fs::write(&path, xml).unwrap();
    path
}

/// `biped ssv fit URDF --out OUT EXTRA...` with `ROS_PACKAGE_PATH` set to `ros` (unset if
/// `None`, so that the caller's environment does not change the search path).
fn fit_with(urdf: &Path, out: &Path, extra: &[&str], ros: Option<&str>) -> (i32, String, String) {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_biped"));
    cmd.args([
        "ssv",
        "fit",
        urdf.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    cmd.args(extra).current_dir(env!("CARGO_TARGET_TMPDIR"));
    match ros {
        Some(path) => cmd.env("ROS_PACKAGE_PATH", path),
        None => cmd.env_remove("ROS_PACKAGE_PATH"),
    };
    let o = cmd.output().unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (o.status.code().unwrap(), text(&o.stdout), text(&o.stderr))
}

/// `biped ssv fit` without `ROS_PACKAGE_PATH`.
fn fit(urdf: &Path, out: &Path, extra: &[&str]) -> (i32, String, String) {
    fit_with(urdf, out, extra, None)
}

#[test]
fn fits_shapes_and_chooses_pairs_by_sampling() {
    let dir = folder("shapes");
    let urdf = robot(&dir, "package://mypkg/meshes/cube.stl");
    let out = dir.join("model.toml");
    let pkgs = dir.join("pkgs");
    let (code, stdout, stderr) = fit(&urdf, &out, &["--package-path", pkgs.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let lines: Vec<&str> = stdout.lines().collect();
    let row = |name: &str| {
        *lines
            .iter()
            .find(|l| l.starts_with(&format!("{name} ")))
            .unwrap()
    };
    // a cube's smallest containing SSV is its circumscribed sphere: 4/3 pi (sqrt 3 / 2)^3 / 1
    let cube = 4.0 / 3.0 * PI * (3f64.sqrt() / 2.0).powi(3);
    assert!(row("base").contains("point") && row("base").contains(&format!("overhead {cube:.2}")));
    assert!(
        row("a").contains("point") && row("a").ends_with("overhead 1.00"),
        "{}",
        row("a")
    );
    assert!(row("b").contains("line") && row("b").ends_with("overhead 1.00"));
    assert!(row("c").contains("point + line"), "{}", row("c"));
    // the scaled cube mesh 0.1 x 0.2 x 0.3: rectangle 0.3 x 0.2 swept by 0.05
    let r: f64 = 0.05;
    let plate = (2.0 * r * 0.06 + PI * r * r * 0.5 + 4.0 / 3.0 * PI * r.powi(3)) / 0.006;
    assert!(row("far").contains("rectangle"), "{}", row("far"));
    assert!(
        row("far").ends_with(&format!("overhead {plate:.2}")),
        "{} {plate}",
        row("far")
    );
    assert!(row("far2").ends_with("overhead n/a (open mesh)"));
    // 7 segments, 21 pairs, 6 adjacent: 15 candidates; base-b always touching; c-d kept
    assert_eq!(
        lines.last().unwrap(),
        &format!("1 pairs of 15 candidates (13 never within d_a = 0.05 m, 1 always in contact; 2000 samples); wrote {}", out.display())
    );
    let loaded = format::load(&out).unwrap();
    let m = &loaded.model;
    let names = |i: usize| m.segments()[i].name();
    assert_eq!(
        m.pairs()
            .iter()
            .map(|p| (names(p.a), names(p.b)))
            .collect::<Vec<_>>(),
        [("c", "d")]
    );
    assert_eq!(m.segments().len(), 7);
    // base is welded to the world: its segment holds the cube's corners in the world frame
    let base = &m.segments()[m.segment_index("base").unwrap()];
    for k in 0..8 {
        let s = |bit: usize| if k >> bit & 1 == 1 { 0.1 } else { -0.1 };
        let probe = Ssv::from(Pss::new(Point3::new(s(0), s(1), s(2)), 0.0).unwrap());
        assert!(distance(&probe, &base.ssvs()[0]).distance <= 1e-9);
    }
    assert_eq!(loaded.poses["zero"].len(), m.bodies().len());
    let far = loaded.poses["zero"][m.body_index("far").unwrap()];
    assert!(
        (far.to_homogeneous() - Isometry3::translation(10.0, 0.0, 0.0).to_homogeneous()).norm()
            < 1e-12
    );
    // written through a temporary sibling, which is gone
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert!(
        !left.iter().any(|n| n.to_string_lossy().contains(".tmp")),
        "{left:?}"
    );
    // `biped ssv model` evaluates it
    let o = run(&["ssv", "model", out.to_str().unwrap()], "");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("c - d"));
    // the package found through ROS_PACKAGE_PATH instead of --package-path
    let ros = format!("/nonexistent:{}", pkgs.display());
    let (code, ros_stdout, stderr) = fit_with(&urdf, &out, &[], Some(&ros));
    assert_eq!(
        (code, ros_stdout.as_str()),
        (0, stdout.as_str()),
        "{stderr}"
    );
    // floating root: the base gets its own body, the same pairs
    let (code, stdout, _) = fit(
        &urdf,
        &out,
        &["--package-path", pkgs.to_str().unwrap(), "--floating"],
    );
    assert_eq!(code, 0);
    assert!(stdout
        .lines()
        .last()
        .unwrap()
        .starts_with("1 pairs of 15 candidates"));
}

#[test]
fn errors_are_one_line_and_name_the_place() {
    let dir = folder("errors");
    let out = dir.join("model.toml");
    let pkgs = dir.join("pkgs");
    let pkg = ["--package-path", pkgs.to_str().unwrap()];
    let cases = [
        ("package://mypkg/meshes/missing.stl", format!("mesh filename: file {} does not exist", pkgs.join("mypkg/meshes/missing.stl").display())),
        ("package://nopkg/cube.stl", format!("mesh filename: package \"nopkg\" not found in the package path [{}] (add --package-path DIR)", pkgs.display())),
        ("meshes/none.stl", format!("mesh filename: file {} does not exist", dir.join("meshes/none.stl").display())),
    ];
    for (mesh, expected) in cases {
        let urdf = robot(&dir, mesh);
        let (code, stdout, stderr) = fit(&urdf, &out, &pkg);
        assert_eq!((code, stdout.as_str()), (1, ""), "{stderr}");
        // the far link's <collision> is on line 28 of the written URDF (5 lines per link)
        let want = format!(
            "error: {}:28: link \"far\" collision: {expected}\n",
            urdf.display()
        );
        assert_eq!(stderr, want);
        assert!(!out.exists(), "no model written on error");
    }
    // a mesh file that is not a mesh: the mesh reader's message, located in the URDF
    std::fs::write(
        dir.join("meshes/bad.stl"),
        "solid x\nouter loop\nvertex 1 2\n",
    )
    .unwrap();
    let urdf = robot(&dir, "meshes/bad.stl");
    let (code, _, stderr) = fit(&urdf, &out, &pkg);
    assert_eq!(code, 1);
    let bad = dir.join("meshes/bad.stl");
    assert_eq!(stderr, format!("error: {}:28: link \"far\" collision: mesh: {}: line 3: expected `vertex x y z` with finite numbers\n", urdf.display(), bad.display()));
    // a failed fit leaves an existing model file as it was
    std::fs::write(&out, "previous").unwrap();
    let (code, _, _) = fit(&urdf, &out, &pkg);
    assert_eq!(
        (code, std::fs::read_to_string(&out).unwrap().as_str()),
        (1, "previous")
    );
    std::fs::remove_file(&out).unwrap();
    std::fs::write(dir.join("meshes/part.ply"), "ply\n").unwrap();
    let urdf = robot(&dir, "meshes/part.ply");
    let (code, _, stderr) = fit(&urdf, &out, &pkg);
    assert_eq!(code, 1);
    let ply = dir.join("meshes/part.ply");
    assert!(
        stderr.ends_with(&format!(
            "mesh: {}: unknown mesh format (expected .stl or .obj)\n",
            ply.display()
        )),
        "{stderr}"
    );
    assert!(!out.exists());
}

#[test]
fn fits_the_bundled_g1_when_its_meshes_are_installed() {
    let Some(robots) = std::env::var("ROBOTS").ok().filter(|r| !r.is_empty()) else {
        eprintln!("skipped: ROBOTS is not set (source scripts/fetch_robots.sh)");
        return;
    };
    let urdf =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/dynamics/data/g1_29dof_rev_1_0.urdf");
    let dir = folder("g1");
    let out = dir.join("g1.toml");
    let pkg = Path::new(&robots).join("..");
    let (code, stdout, stderr) = fit(&urdf, &out, &["--package-path", pkg.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let text = std::fs::read_to_string(&urdf).unwrap();
    let links_with_collision = text
        .split("<link ")
        .filter(|l| l.split("</link>").next().unwrap().contains("<collision"))
        .count();
    let loaded = format::load(&out).unwrap();
    assert_eq!(loaded.model.segments().len(), links_with_collision);
    assert_eq!(stdout.lines().count(), links_with_collision + 1);
    assert!(!loaded.model.pairs().is_empty());
    println!("{stdout}");
    // every mesh vertex, placed in its body frame here, is inside its link's segment
    let g1 = load_file(&urdf, &UrdfOptions::default()).unwrap();
    let search = PackagePath::new(vec![pkg], None);
    let mut checked = 0;
    for geometry in read_geometry_file(&urdf).unwrap() {
        let Some(segment) = loaded.model.segment_index(&geometry.link) else {
            continue;
        };
        let ssvs = loaded.model.segments()[segment].ssvs();
        let frame = g1.links.iter().find(|l| l.link == geometry.link).unwrap();
        for element in &geometry.collisions {
            let Shape::Mesh { filename, scale } = &element.shape else {
                continue;
            };
            let mesh = mesh::read_file(search.resolve(filename, Path::new(".")).unwrap()).unwrap();
            for p in mesh.vertices() {
                let local = Point3::new(p.x * scale[0], p.y * scale[1], p.z * scale[2]);
                let probe = Ssv::from(Pss::new(frame.pose * element.origin * local, 0.0).unwrap());
                let d = ssvs
                    .iter()
                    .map(|s| distance(&probe, s).distance)
                    .fold(f64::INFINITY, f64::min);
                assert!(d <= 1e-9, "{}: vertex {p:?} at {d}", geometry.link);
                checked += 1;
            }
        }
    }
    assert!(checked > 10_000, "{checked} vertices");
}
