//! Mesh files the test writes (box, prism, icosphere as binary STL, ASCII STL and OBJ): read
//! back, closed, volume by hand, and the fit contains every vertex; bad files are located.

use biped_ssv::fit::{fit, Geometry};
use biped_ssv::mesh::{self, Mesh, MeshError};
use biped_ssv::{distance, Pss, Ssv};
use nalgebra::{Isometry3, Point3, Vector3};
use std::f64::consts::PI;
use std::path::PathBuf;

type Soup = (Vec<[f64; 3]>, Vec<[usize; 3]>);

/// A box of `size` centred at the origin, outward triangles.
fn box_mesh(size: [f64; 3]) -> Soup {
    let v = (0..8)
        .map(|k| {
            [0, 1, 2].map(|a| {
                if k >> a & 1 == 1 {
                    size[a] / 2.0
                } else {
                    -size[a] / 2.0
                }
            })
        })
        .collect();
    // faces as quads (outward, counter-clockwise), each split in two
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let t = quads
        .iter()
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect();
    (v, t)
}

/// A regular `n`-gon prism of circumradius `r` and height `h` along z.
fn prism(n: usize, r: f64, h: f64) -> Soup {
    let mut v = Vec::new();
    for z in [-h / 2.0, h / 2.0] {
        v.extend((0..n).map(|k| {
            let phi = 2.0 * PI * k as f64 / n as f64;
            [r * phi.cos(), r * phi.sin(), z]
        }));
    }
    v.push([0.0, 0.0, -h / 2.0]);
    v.push([0.0, 0.0, h / 2.0]);
    let mut t = Vec::new();
    for k in 0..n {
        let j = (k + 1) % n;
        t.extend([
            [k, j + n, j],
            [k, k + n, j + n],
            [2 * n, k, j],
            [2 * n + 1, j + n, k + n],
        ]);
    }
    (v, t)
}

/// An icosahedron subdivided twice, vertices pushed onto the sphere of radius `r`.
fn icosphere(r: f64) -> Soup {
    let g = (1.0 + 5f64.sqrt()) / 2.0;
    let mut v: Vec<[f64; 3]> = vec![
        [-1.0, g, 0.0],
        [1.0, g, 0.0],
        [-1.0, -g, 0.0],
        [1.0, -g, 0.0],
        [0.0, -1.0, g],
        [0.0, 1.0, g],
        [0.0, -1.0, -g],
        [0.0, 1.0, -g],
        [g, 0.0, -1.0],
        [g, 0.0, 1.0],
        [-g, 0.0, -1.0],
        [-g, 0.0, 1.0],
    ];
    let mut t = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..2 {
        let mut mids = std::collections::HashMap::new();
        let mut mid = |a: usize, b: usize, v: &mut Vec<[f64; 3]>| {
            *mids.entry((a.min(b), a.max(b))).or_insert_with(|| {
                v.push([0, 1, 2].map(|i| (v[a][i] + v[b][i]) / 2.0));
                v.len() - 1
            })
        };
        t = t
            .iter()
            .flat_map(|&[a, b, c]| {
                let (ab, bc, ca) = (mid(a, b, &mut v), mid(b, c, &mut v), mid(c, a, &mut v));
                [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
            })
            .collect();
    }
    let v = v
        .iter()
        .map(|p| Vector3::from(*p).normalize() * r)
        .map(|p| [p.x, p.y, p.z])
        .collect();
    (v, t)
}

fn binary_stl((v, t): &Soup) -> Vec<u8> {
    let mut out = vec![0u8; 80];
    out.extend((t.len() as u32).to_le_bytes());
    for tri in t {
        out.extend([0f32; 3].iter().flat_map(|x| x.to_le_bytes()));
        for &i in tri {
            out.extend(v[i].iter().flat_map(|&x| (x as f32).to_le_bytes()));
        }
        out.extend([0u8; 2]);
    }
    out
}

fn ascii_stl((v, t): &Soup) -> Vec<u8> {
    let mut s = String::from("solid test\n");
    for tri in t {
        s += "  facet normal 0 0 0\n    outer loop\n";
        for &i in tri {
            s += &format!(
                "      vertex {} {} {}\n",
                v[i][0] as f32, v[i][1] as f32, v[i][2] as f32
            );
        }
        s += "    endloop\n  endfacet\n";
    }
    (s + "endsolid test\n").into_bytes()
}

fn obj((v, t): &Soup) -> Vec<u8> {
    let mut s = String::from("# test\no part\n");
    s += &v
        .iter()
        .map(|p| format!("v {} {} {}\n", p[0] as f32, p[1] as f32, p[2] as f32))
        .collect::<String>();
    s += &t
        .iter()
        .map(|f| format!("f {}/1/1 {} -{}\n", f[0] + 1, f[1] + 1, v.len() - f[2]))
        .collect::<String>();
    s.into_bytes()
}

fn tmp(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fit_meshes");
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// Every vertex's signed distance to the union of `ssvs`.
fn worst(ssvs: &[Ssv], points: &[Point3<f64>]) -> f64 {
    let d = |p: &Point3<f64>| {
        let probe = Ssv::from(Pss::new(*p, 0.0).unwrap());
        ssvs.iter()
            .map(|s| distance(&probe, s).distance)
            .fold(f64::INFINITY, f64::min)
    };
    points.iter().map(d).fold(f64::NEG_INFINITY, f64::max)
}

#[test]
fn written_meshes_read_back_closed_with_their_volume_and_are_contained() {
    let prism_volume = 12.0 / 2.0 * 0.05f64.powi(2) * (2.0 * PI / 12.0).sin() * 0.3;
    let shapes: [(&str, Soup, f64, f64); 3] = [
        ("box", box_mesh([0.3, 0.2, 0.05]), 0.3 * 0.2 * 0.05, 1e-7),
        ("prism", prism(12, 0.05, 0.3), prism_volume, 1e-6),
        // the inscribed polyhedron is slightly smaller than the ball
        ("icosphere", icosphere(0.1), 4.0 / 3.0 * PI * 1e-3, 0.05),
    ];
    let at = Isometry3::new(Vector3::new(0.1, -0.2, 0.3), Vector3::new(0.4, 0.5, -0.6));
    for (name, soup, volume, tol) in shapes {
        let files = [
            ("bin.stl", binary_stl(&soup)),
            ("ascii.STL", ascii_stl(&soup)),
            ("x.obj", obj(&soup)),
        ];
        for (ext, bytes) in files {
            let path = tmp(&format!("{name}_{ext}"));
            std::fs::write(&path, bytes).unwrap();
            let m: Mesh = mesh::read_file(&path).unwrap();
            assert_eq!(
                m.vertices().len(),
                soup.0.len(),
                "{name} {ext}: welded vertices"
            );
            assert_eq!(m.triangles().len(), soup.1.len());
            assert!(m.is_closed(), "{name} {ext}");
            let v = m.volume().unwrap();
            assert!(
                (v - volume).abs() <= tol * volume,
                "{name} {ext}: {v} vs {volume}"
            );
            let f = fit(
                &Geometry::Points {
                    points: m.vertices(),
                    volume: Some(v),
                },
                &at,
            )
            .unwrap();
            let placed: Vec<_> = m.vertices().iter().map(|p| at * p).collect();
            assert!(worst(&f.ssvs, &placed) <= 1e-9, "{name} {ext}");
            assert!(
                f.overhead().unwrap() >= 1.0,
                "{name} {ext}: {:?}",
                f.overhead()
            );
            if name == "box" {
                // the vertices' rectangle is the box's: 0.3 x 0.2 swept by 0.025 (f32 input)
                let r: f64 = 0.025;
                let by_hand = 2.0 * r * 0.06 + PI * r * r * 0.5 + 4.0 / 3.0 * PI * r.powi(3);
                assert!(
                    (f.volume - by_hand).abs() < 1e-6 * by_hand,
                    "{} {by_hand}",
                    f.volume
                );
            }
            println!(
                "{name} {ext}: {} overhead {:.3}",
                f.kind,
                f.overhead().unwrap()
            );
        }
    }
}

#[test]
fn open_meshes_have_no_volume() {
    let (v, mut t) = box_mesh([1.0; 3]);
    t.pop();
    let m = mesh::parse_stl(&binary_stl(&(v, t)), "open.stl").unwrap();
    assert!(!m.is_closed());
    assert_eq!(m.volume(), None);
    // two unit cubes touching along an edge (four triangles on it): closed, volume 2
    let (mut v, mut t) = box_mesh([1.0; 3]);
    let (w, u) = box_mesh([1.0; 3]);
    v.extend(w.iter().map(|p| [p[0] + 1.0, p[1] + 1.0, p[2]]));
    t.extend(u.iter().map(|f| f.map(|i| i + 8)));
    let m = mesh::parse_stl(&binary_stl(&(v, t)), "two.stl").unwrap();
    assert_eq!(m.vertices().len(), 14);
    assert!(m.is_closed());
    assert!((m.volume().unwrap() - 2.0).abs() < 1e-12);
}

#[test]
fn bad_files_are_located() {
    let err = |r: Result<Mesh, MeshError>| r.unwrap_err().to_string();
    let mut bin = binary_stl(&box_mesh([1.0; 3]));
    bin.pop();
    assert_eq!(
        err(mesh::parse_stl(&bin, "b.stl")),
        "b.stl: header: not ASCII STL (no `solid`) and not binary STL (12 triangles need 684 bytes, the file has 683)"
    );
    let ascii = "solid x\nfacet normal 0 0 0\nouter loop\nvertex 1 2\nendloop\n";
    assert_eq!(
        err(mesh::parse_stl(ascii.as_bytes(), "a.stl")),
        "a.stl: line 4: expected `vertex x y z` with finite numbers"
    );
    let short = "solid x\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n";
    assert_eq!(
        err(mesh::parse_stl(short.as_bytes(), "a.stl")),
        "a.stl: line 5: a loop of 2 vertices"
    );
    let open = "solid x\nouter loop\nvertex 0 0 0\n";
    assert_eq!(
        err(mesh::parse_stl(open.as_bytes(), "a.stl")),
        "a.stl: line 3: `outer loop` without `endloop`"
    );
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n";
    assert_eq!(
        err(mesh::parse_obj(obj.as_bytes(), "o.obj")),
        "o.obj: line 4: vertex index 4 is not among the 3 vertices defined above"
    );
    assert_eq!(
        err(mesh::parse_obj(b"v 0 0 nan\n", "o.obj")),
        "o.obj: line 1: expected `v x y z [w]` with finite numbers"
    );
    assert_eq!(
        err(mesh::parse_obj(b"v 0 0 0\nf 1 x 1\n", "o.obj")),
        "o.obj: line 2: face entry \"x\" is not a vertex index"
    );
    assert_eq!(
        err(mesh::read_file("/no/such.ply")),
        "/no/such.ply: unknown mesh format (expected .stl or .obj)"
    );
    assert!(
        err(mesh::read_file("/no/such.stl")).starts_with("/no/such.stl: cannot read mesh file: ")
    );
}

#[test]
fn mutated_mesh_bytes_never_panic() {
    let bytes = [
        binary_stl(&icosphere(1.0)),
        ascii_stl(&box_mesh([1.0; 3])),
        obj(&prism(5, 1.0, 1.0)),
    ];
    let mut cases = 0;
    for (k, original) in bytes.iter().enumerate() {
        for step in 0..700usize {
            let mut b = original.clone();
            let at = (step * 7919) % b.len();
            b[at] = (step * 31 % 256) as u8;
            b.truncate(b.len() - step % 3);
            let parsed = if k == 2 {
                mesh::parse_obj(&b, "m")
            } else {
                mesh::parse_stl(&b, "m")
            };
            if let Ok(m) = parsed {
                assert!(m.vertices().iter().all(|p| p.iter().all(|x| x.is_finite())));
                assert!(m.volume().is_none_or(|v| v.is_finite()));
            }
            cases += 1;
        }
    }
    assert_eq!(cases, 2100);
}
