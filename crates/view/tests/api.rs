//! The API over real HTTP on 127.0.0.1: scene, recording pages, distances and the SSV file's
//! checked, whole-file replacement.

mod support;

use biped_dynamics::{update_placements, Data};
use biped_robots::lola::{self, lola_collision_model, LolaType};
use biped_view::{RobotSource, ViewConfig};
use nalgebra::DVector;
use serde_json::Value;
use std::path::{Path, PathBuf};
use support::{lola_ssv, temp_dir, Running};

fn lola_config(ssv: Option<PathBuf>, recording: Option<PathBuf>) -> ViewConfig {
    ViewConfig {
        robot: RobotSource::Lola(LolaType::Type2),
        ssv,
        recording,
        web_dir: PathBuf::from("no-such-dir"),
    }
}

/// Root moves forward at 0.5 m/s, the right thigh and left shank turn; 1 kHz for 1 s.
fn write_recording(dir: &Path) -> PathBuf {
    let mut csv = String::from(
        "time,q[root.x],q[root.y],q[root.z],q[root.qx],q[root.qy],q[root.qz],q[root.qw],\
         q[r_thigh],q[l_shank],com.x,com.y,com.z,zmp.x,zmp.y\n",
    );
    for k in 0..=1000 {
        let t = k as f64 * 1e-3;
        csv += &format!(
            "{t},{},0,1,0,0,0,1,{},{},{},0,0.9,{},0\n",
            0.5 * t,
            -0.6 * t,
            0.8 * t,
            0.5 * t + 0.02,
            0.5 * t + 0.01
        );
    }
    let path = dir.join("minimization_trajectory.csv");
    std::fs::write(&path, csv).unwrap();
    // The walk's series file beside it, at 100 Hz: L_z = 10 t.
    let series: String = (0..=100)
        .map(|k| format!("{},{}\n", k as f64 / 100.0, k as f64 / 10.0))
        .collect();
    std::fs::write(dir.join("minimization.csv"), format!("time,L_z\n{series}")).unwrap();
    path
}

#[test]
fn scene_has_lola_boxes_and_every_segment() {
    let server = Running::start(&lola_config(Some(lola_ssv()), None));
    let (status, scene) = server.json("GET", "/api/scene", b"");
    assert_eq!(status, 200);
    let lola = lola::build(LolaType::Type2).unwrap();
    let bodies = scene["bodies"].as_array().unwrap();
    assert_eq!(bodies.len(), lola.model.nbodies());
    // lola.toml: the pelvis is a box 0.20 x 0.30 x 0.15 about its frame.
    assert_eq!(bodies[0]["name"], "pelvis");
    assert_eq!(bodies[0]["geometry"][0]["shape"]["type"], "box");
    assert_eq!(
        bodies[0]["geometry"][0]["shape"]["size"],
        serde_json::json!([0.2, 0.3, 0.15])
    );
    let text = std::fs::read_to_string(lola_ssv()).unwrap();
    let segments = scene["ssv"]["segments"].as_array().unwrap();
    assert_eq!(segments.len(), text.matches("[[segment]]").count());
    // An explicit segment's span is exactly its `ssvs = [...]` array in the file text.
    let explicit = segments
        .iter()
        .find(|s| s["source"]["kind"] == "ssvs")
        .unwrap();
    let span = &explicit["source"]["span"];
    let (a, b) = (
        span[0].as_u64().unwrap() as usize,
        span[1].as_u64().unwrap() as usize,
    );
    let utf16: Vec<u16> = text.encode_utf16().collect();
    let array = String::from_utf16(&utf16[a..b]).unwrap();
    assert!(array.starts_with('[') && array.ends_with(']'), "{array}");
    let entries = explicit["source"]["entries"].as_array().unwrap();
    assert_eq!(array.matches("radius").count(), entries.len());
    // A version's `keep` span holds its kept indices (lola_ssv.toml: r_thigh_inner keeps 0, 1, 3, 4).
    let inner = segments
        .iter()
        .find(|s| s["name"] == "r_thigh_inner")
        .unwrap();
    assert_eq!(inner["source"]["kind"], "version_of");
    let span = &inner["source"]["span"];
    let (a, b) = (
        span[0].as_u64().unwrap() as usize,
        span[1].as_u64().unwrap() as usize,
    );
    let keep: Vec<i64> = String::from_utf16(&utf16[a..b])
        .unwrap()
        .trim_matches(['[', ']'])
        .split(',')
        .map(|k| k.trim().parse().unwrap())
        .collect();
    assert_eq!(serde_json::json!(keep), inner["source"]["keep"]);
    assert_eq!(inner["ssvs"].as_array().unwrap().len(), keep.len());
    // The pairs array: its span holds exactly the pairs it lists, all of them the model's.
    let list = &scene["ssv"]["pair_list"];
    let (a, b) = (
        list["span"][0].as_u64().unwrap() as usize,
        list["span"][1].as_u64().unwrap() as usize,
    );
    let pairs_text = String::from_utf16(&utf16[a..b]).unwrap();
    let listed = list["pairs"].as_array().unwrap();
    assert_eq!(pairs_text.matches("\"]").count(), listed.len());
    assert_eq!(
        listed.len(),
        scene["ssv"]["pairs"].as_array().unwrap().len()
    );
    // Without a recording the robot stands at its neutral pose with the soles on the ground.
    let sole = lola.model.body_id("l_sole").unwrap();
    let z = scene["neutral"][sole]["position"][2].as_f64().unwrap();
    assert!(z.abs() < 1e-12, "sole at z = {z}");
}

#[test]
fn recording_is_paged_at_100_hz_with_poses_from_q() {
    let dir = temp_dir("recording");
    write_recording(&dir);
    let server = Running::start(&lola_config(None, Some(dir)));
    let (status, page) = server.json("GET", "/api/recording?from=0&count=40&signals=com.z", b"");
    assert_eq!(status, 200, "{page}");
    // 1001 rows at 1 kHz: every 10th kept, 0.00 s .. 1.00 s.
    assert_eq!(page["frames"], 101);
    assert_eq!(page["names"], serde_json::json!(["minimization"]));
    let time = page["time"].as_array().unwrap();
    assert!((time[37].as_f64().unwrap() - 0.37).abs() < 1e-12);
    assert_eq!(
        (page["count"].as_u64(), page["next"].as_u64()),
        (Some(40), Some(40))
    );
    // The pelvis is the floating base: its pose is q[root.*] of the row.
    let pelvis = &page["poses"][20][0];
    let x = pelvis[0].as_f64().unwrap();
    assert!((x - 0.1).abs() < 1e-6 && (pelvis[2].as_f64().unwrap() - 1.0).abs() < 1e-6);
    assert_eq!(page["signals"]["com.z"][5], 0.9);
    let (_, lz) = server.json("GET", "/api/recording?from=30&count=2&signals=L_z", b"");
    assert_eq!(lz["signals"]["L_z"], serde_json::json!([3.0, 3.1]));
    assert!((page["zmp"][20][0].as_f64().unwrap() - 0.11).abs() < 1e-12);
    let (_, last) = server.json("GET", "/api/recording?from=100&count=40", b"");
    assert_eq!(
        (last["count"].as_u64(), last["next"].as_u64()),
        (Some(1), None)
    );
    let (status, err) = server.json("GET", "/api/recording?from=102", b"");
    assert_eq!(status, 400);
    assert_eq!(
        err["error"],
        "from: 102 is past the last frame (101 frames)"
    );
    let (status, err) = server.json("GET", "/api/recording?signals=nope", b"");
    assert_eq!(status, 400);
    assert!(err["error"]
        .as_str()
        .unwrap()
        .starts_with("signals: no column `nope`"));
}

/// `NAME_recording.csv.gz` at 100 Hz for 0.5 s: `q[root.x] = t`, and body `k` at
/// `x = k + t` (unrelated to `q`, so that the test sees which the viewer uses), unless
/// `skip` names a body left out.
fn write_replay(dir: &Path, name: &str, skip: Option<&str>) {
    use std::io::Write;
    let lola = lola::build(LolaType::Type2).unwrap();
    let bodies: Vec<&str> = lola.model.body_names();
    let mut header = String::from("time,q[root.x],q[root.z],q[root.qw],L_z");
    for b in bodies.iter().filter(|b| Some(**b) != skip) {
        for f in ["x", "y", "z", "qx", "qy", "qz", "qw"] {
            header += &format!(",body[{b}].{f}");
        }
    }
    let mut text = header + "\n";
    for k in 0..=50 {
        let t = k as f64 / 100.0;
        text += &format!("{t},{t},1,1,{}", 2.0 * t);
        for (i, b) in bodies.iter().enumerate() {
            if Some(*b) != skip {
                text += &format!(",{},0,0.5,0,0,0,2", i as f64 + t);
            }
        }
        text += "\n";
    }
    let file = std::fs::File::create(dir.join(format!("{name}_recording.csv.gz"))).unwrap();
    let mut gz = flate2::write::GzEncoder::new(file, flate2::Compression::fast());
    gz.write_all(text.as_bytes()).unwrap();
    gz.finish().unwrap();
}

#[test]
fn recordings_for_replay_are_preferred_and_their_body_poses_used() {
    let dir = temp_dir("replay");
    write_recording(&dir);
    write_replay(&dir, "minimization", None);
    write_replay(&dir, "dynamic", Some("l_toe"));
    let server = Running::start(&lola_config(None, Some(dir)));
    let (status, page) = server.json("GET", "/api/recording?name=minimization&signals=L_z", b"");
    assert_eq!(status, 200, "{page}");
    assert_eq!(
        page["names"],
        serde_json::json!(["dynamic", "minimization"])
    );
    assert_eq!(page["frames"], 51);
    assert_eq!(page["signals"]["L_z"][10], 0.2);
    // Body k at x = k + t, the quaternion (0, 0, 0, 2) scaled to unit length.
    let frame = &page["poses"][10];
    for k in [0, 5, 20] {
        let x = frame[k][0].as_f64().unwrap();
        assert!((x - (k as f64 + 0.1)).abs() < 1e-5, "body {k}: {x}");
        assert_eq!(frame[k][6].as_f64(), Some(1.0));
    }
    let columns = page["columns"].as_array().unwrap();
    assert!(!columns
        .iter()
        .any(|c| c.as_str().unwrap().starts_with("body[")));
    // A recording without every body's pose is placed by forward kinematics of its q.
    let (_, dynamic) = server.json("GET", "/api/recording?name=dynamic&from=10&count=1", b"");
    let pelvis = &dynamic["poses"][0][0];
    assert!((pelvis[0].as_f64().unwrap() - 0.1).abs() < 1e-6);
    assert!((pelvis[2].as_f64().unwrap() - 1.0).abs() < 1e-6);
}

/// The pair distances at a frame, computed here through the Lola binding of biped_robots.
fn expected_distances(q_row: &[(String, f64)]) -> Vec<Option<f64>> {
    let lola = lola::build(LolaType::Type2).unwrap();
    let mut collision = lola_collision_model(&lola).unwrap();
    let names = lola.model.q_names();
    let mut q: DVector<f64> = lola.model.neutral();
    for (name, v) in q_row {
        q[names.iter().position(|n| n == name).unwrap()] = *v;
    }
    let mut data = Data::new(&lola.model);
    update_placements(&lola.model, &mut data, &q).unwrap();
    let poses: Vec<_> = collision
        .model_bodies
        .iter()
        .map(|&b| data.body_pose(b))
        .collect();
    collision.model.update(&poses).unwrap();
    collision
        .model
        .results()
        .iter()
        .map(|r| r.distance())
        .collect()
}

#[test]
fn distances_at_a_frame_match_the_robots_collision_binding() {
    let dir = temp_dir("distances");
    write_recording(&dir);
    let server = Running::start(&lola_config(Some(lola_ssv()), Some(dir)));
    let (status, answer) = server.json("GET", "/api/distances?frame=60", b"");
    assert_eq!(status, 200, "{answer}");
    let row = [
        ("root.x", 0.3),
        ("root.z", 1.0),
        ("r_thigh", -0.36),
        ("l_shank", 0.48),
    ];
    let row: Vec<(String, f64)> = row.iter().map(|(n, v)| (n.to_string(), *v)).collect();
    let expected = expected_distances(&row);
    let pairs = answer["pairs"].as_array().unwrap();
    assert_eq!(pairs.len(), expected.len());
    let mut computed = 0;
    for (pair, want) in pairs.iter().zip(&expected) {
        match (pair["distance"].as_f64(), want) {
            (Some(got), Some(want)) => {
                assert!((got - want).abs() < 1e-9, "{pair}: {got} vs {want}");
                computed += 1;
            }
            (None, None) => {}
            other => panic!("{pair}: {other:?}"),
        }
    }
    assert!(computed > 0);
    let (status, err) = server.json("GET", "/api/distances?frame=500", b"");
    assert_eq!(status, 400);
    assert_eq!(
        err["error"],
        "frame: 500 is out of range (the recording has 101 frames)"
    );
}

/// The shipped model with the first `radius = ` value of the file replaced; and its line.
fn with_first_radius(text: &str, value: &str) -> (String, usize) {
    let at = text.find("radius = ").unwrap() + "radius = ".len();
    let end = at
        + text[at..]
            .find(|c: char| c != '.' && !c.is_ascii_digit())
            .unwrap();
    let line = text[..at].matches('\n').count() + 1;
    (format!("{}{value}{}", &text[..at], &text[end..]), line)
}

#[test]
fn put_writes_a_model_that_loads_and_refuses_a_bad_one_leaving_the_file() {
    let dir = temp_dir("put");
    let file = dir.join("model.toml");
    let original = std::fs::read_to_string(lola_ssv()).unwrap();
    std::fs::write(&file, &original).unwrap();
    let server = Running::start(&lola_config(Some(file.clone()), None));
    let (status, text) = server.request("GET", "/api/ssv", b"");
    assert_eq!((status, text.as_slice()), (200, original.as_bytes()));

    let (good, _) = with_first_radius(&original, "0.123");
    let (status, answer) = server.json("PUT", "/api/ssv", good.as_bytes());
    assert_eq!(status, 200, "{answer}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), good);
    let loaded = biped_ssv::format::load(&file).unwrap();
    let radii = loaded
        .model
        .segments()
        .iter()
        .flat_map(|s| s.ssvs())
        .map(|s| s.radius());
    assert!(radii.into_iter().any(|r| r == 0.123));
    let no_leftovers = std::fs::read_dir(&dir).unwrap().count();
    assert_eq!(no_leftovers, 1, "only the model file remains");

    let (bad, line) = with_first_radius(&good, "-0.1");
    let (status, err) = server.json("PUT", "/api/ssv", bad.as_bytes());
    assert_eq!(status, 422);
    let msg = err["error"].as_str().unwrap();
    assert!(
        msg.starts_with(&format!("{}:{line}: ", file.display())),
        "{msg}"
    );
    assert!(msg.contains("radius"), "{msg}");
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        good,
        "file untouched"
    );
    let (_, text) = server.request("GET", "/api/ssv", b"");
    assert_eq!(text, good.as_bytes());

    let (status, err) = server.json("PUT", "/api/ssv", b"activation_distance = \"x\"");
    assert_eq!(status, 422);
    assert!(err["error"]
        .as_str()
        .unwrap()
        .starts_with(&format!("{}:1: ", file.display())));
    let unknown = good.replace("\"r_toe\"", "\"r_flipper\"");
    assert_ne!(unknown, good);
    let (status, err) = server.json("PUT", "/api/ssv", unknown.as_bytes());
    assert_eq!(status, 422);
    assert!(err["error"]
        .as_str()
        .unwrap()
        .contains("`r_flipper` is not a body or link of Lola Type2"));
    assert_eq!(std::fs::read_to_string(&file).unwrap(), good);
}

#[test]
fn check_answers_distances_of_a_candidate_without_writing() {
    let dir = temp_dir("check");
    let file = dir.join("model.toml");
    let original = std::fs::read_to_string(lola_ssv()).unwrap();
    std::fs::write(&file, &original).unwrap();
    let server = Running::start(&lola_config(Some(file.clone()), None));
    let (_, before) = server.json("GET", "/api/distances", b"");
    let (candidate, _) = with_first_radius(&original, "0.2");
    let (status, answer) = server.json("POST", "/api/ssv/check", candidate.as_bytes());
    assert_eq!(status, 200, "{answer}");
    assert_eq!(std::fs::read_to_string(&file).unwrap(), original);
    let min = |v: &Value| {
        let d = v["pairs"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|p| p["distance"].as_f64());
        d.fold(f64::INFINITY, f64::min)
    };
    // A larger radius on the pelvis brings some pair closer.
    assert!(
        min(&answer) < min(&before),
        "{} vs {}",
        min(&answer),
        min(&before)
    );
    let (status, err) = server.json("GET", "/api/distances?frame=3", b"");
    assert_eq!(status, 404);
    assert_eq!(
        err["error"],
        "no recording: start biped view with --recording DIR"
    );
    let (bad, line) = with_first_radius(&original, "-1");
    let (status, err) = server.json("POST", "/api/ssv/check", bad.as_bytes());
    assert_eq!(status, 422);
    assert!(err["error"]
        .as_str()
        .unwrap()
        .starts_with(&format!("{}:{line}: ", file.display())));
}

#[test]
fn urdf_visuals_are_placed_on_their_bodies_and_meshes_served() {
    let dir = temp_dir("urdf");
    let stl = "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n\
               endloop\nendfacet\nendsolid t\n";
    std::fs::write(dir.join("foot.stl"), stl).unwrap();
    let urdf = r#"<robot name="r">
  <link name="base"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><origin xyz="0 0 0.1"/><geometry><box size="0.1 0.2 0.3"/></geometry></visual></link>
  <link name="leg"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><mesh filename="foot.stl" scale="2 2 2"/></geometry></visual>
    <visual><geometry><mesh filename="missing.stl"/></geometry></visual></link>
  <link name="toe"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><mesh filename="gone.stl"/></geometry></visual>
    <collision><origin xyz="0.1 0 0"/><geometry><sphere radius="0.04"/></geometry></collision></link>
  <joint name="ankle" type="fixed"><parent link="leg"/><child link="toe"/><origin xyz="0 0 -0.4"/></joint>
  <joint name="hip" type="revolute"><parent link="base"/><child link="leg"/><origin xyz="0 0 -0.5"/>
    <axis xyz="0 1 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>"#;
    std::fs::write(dir.join("r.urdf"), urdf).unwrap();
    let config = ViewConfig {
        robot: RobotSource::Urdf {
            path: dir.join("r.urdf"),
            floating: true,
            package_path: Vec::new(),
        },
        ssv: None,
        recording: None,
        web_dir: PathBuf::from("no-such-dir"),
    };
    let server = Running::start(&config);
    let (_, scene) = server.json("GET", "/api/scene", b"");
    let bodies = scene["bodies"].as_array().unwrap();
    let base = bodies.iter().find(|b| b["name"] == "base").unwrap();
    assert_eq!(
        base["geometry"][0]["pose"]["position"],
        serde_json::json!([0.0, 0.0, 0.1])
    );
    let leg = bodies.iter().find(|b| b["name"] == "leg").unwrap();
    let mesh = &leg["geometry"][0]["shape"];
    assert_eq!(
        (&mesh["type"], &mesh["format"]),
        (&"mesh".into(), &"stl".into())
    );
    // The missing mesh is left out; the toe (merged into the leg 0.4 m below its frame) has no
    // drawable visual, so its collision sphere is drawn.
    let leg_geometry = leg["geometry"].as_array().unwrap();
    assert_eq!(leg_geometry.len(), 2, "{leg_geometry:?}");
    let sphere = serde_json::json!({"type": "sphere", "radius": 0.04});
    assert_eq!(leg_geometry[1]["shape"], sphere);
    let at = serde_json::json!([0.1, 0.0, -0.4]);
    assert_eq!(leg_geometry[1]["pose"]["position"], at);
    let warnings = scene["warnings"].as_array().unwrap();
    assert!(
        warnings
            .iter()
            .any(|w| w.as_str().unwrap().contains("missing.stl")),
        "{warnings:?}"
    );
    let (status, bytes) = server.request("GET", mesh["url"].as_str().unwrap(), b"");
    assert_eq!((status, bytes.as_slice()), (200, stl.as_bytes()));
    assert!(warnings.iter().any(|w| w
        .as_str()
        .unwrap()
        .contains("link \"toe\": drawn from its <collision>")));
    // The floating robot is lifted so that its lowest point is on the ground: the STL's
    // lowest vertex, z = 0 scaled by 2, is at the leg frame; the toe's sphere (merged into the
    // leg, 0.4 m below its frame, radius 0.04) is lower: the leg frame stands at 0.44 m.
    let leg_index = bodies.iter().position(|b| b["name"] == "leg").unwrap();
    let z = scene["neutral"][leg_index]["position"][2].as_f64().unwrap();
    assert!((z - 0.44).abs() < 1e-12, "leg frame at z = {z}");
    let (status, page) = server.request("GET", "/", b"");
    assert_eq!(status, 503);
    assert!(String::from_utf8_lossy(&page).contains("npm ci"));
    assert_eq!(server.request("GET", "/../Cargo.toml", b"").0, 404);
}
