//! `biped view` as a user runs it: the first stdout line is the address, the API answers
//! there, SIGINT ends it with status 0; bad inputs are one error line naming the option or
//! file, before anything listens.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

const LOLA_SSV: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/crates/robots/data/lola_ssv.toml"
);

fn temp(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli_view")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn biped(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(args)
        .stdin(Stdio::null())
        .output()
        .expect("binary runs")
}

fn get(addr: &str, path: &str) -> (String, String) {
    let mut s = TcpStream::connect(addr).unwrap();
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut raw = String::new();
    s.read_to_string(&mut raw).unwrap();
    let (head, body) = raw.split_once("\r\n\r\n").unwrap();
    (head.lines().next().unwrap().to_string(), body.to_string())
}

#[test]
fn serves_on_the_printed_address_and_stops_on_sigint() {
    let dir = temp("serve");
    let model = dir.join("model.toml");
    std::fs::copy(LOLA_SSV, &model).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(["view", "--port", "0", "--lola", "type2", "--ssv"])
        .arg(&model)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = BufReader::new(child.stdout.take().unwrap());
    let mut first = String::new();
    stdout.read_line(&mut first).unwrap();
    let addr = first
        .trim_end()
        .strip_prefix("serving http://")
        .and_then(|a| a.strip_suffix('/'))
        .unwrap_or_else(|| panic!("first line: {first:?}"))
        .to_string();
    assert!(addr.starts_with("127.0.0.1:"), "{addr}");
    let (status, body) = get(&addr, "/api/ssv");
    assert!(status.contains(" 200 "), "{status}");
    assert_eq!(body, std::fs::read_to_string(LOLA_SSV).unwrap());
    let (status, body) = get(&addr, "/api/recording");
    assert!(status.contains(" 404 "), "{status}");
    assert!(body.contains("--recording DIR"), "{body}");
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let status = child.wait().unwrap();
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    assert!(status.success(), "{status}: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

fn fails_with(args: &[&str], expected: &[&str]) {
    let out = biped(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} succeeded");
    assert!(out.stdout.is_empty(), "{args:?}: nothing served");
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "{args:?}: one line: {err}"
    );
    for e in expected {
        assert!(err.contains(e), "{args:?}: {err:?} lacks {e:?}");
    }
}

#[test]
fn bad_inputs_are_one_located_line() {
    let dir = temp("bad");
    let missing = dir.join("missing.toml");
    let missing = missing.to_str().unwrap();
    fails_with(&["view", "--ssv", missing], &[missing, "cannot read"]);
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "activation_distance = -1\nbodies = []\n").unwrap();
    let bad = bad.to_str().unwrap();
    fails_with(&["view", "--ssv", bad], &[&format!("{bad}:1: ")]);
    let empty = dir.to_str().unwrap();
    fails_with(
        &["view", "--recording", empty],
        &["--recording", "trajectory.csv"],
    );
    fails_with(&["view", "--floating"], &["--urdf"]);
    fails_with(&["view", "--lola", "type9"], &["--lola", "type9"]);
    fails_with(
        &["view", "--host", "no such host!"],
        &["--host: `no such host!` is not an IP address"],
    );
}

/// Starts `biped view --port 0 ARGS`; returns the child and the address it prints.
fn start(args: &[&str]) -> (std::process::Child, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_biped"))
        .args(["view", "--port", "0"])
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut first = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    let addr = first.trim_end().strip_prefix("serving http://");
    let addr = addr.and_then(|a| a.strip_suffix('/'));
    let addr = addr.unwrap_or_else(|| panic!("first line: {first:?}"));
    (child, addr.to_string())
}

#[test]
fn robot_g1_serves_its_urdf_bodies_and_ssv_model() {
    let (mut child, addr) = start(&["--robot", "g1"]);
    let (status, body) = get(&addr, "/api/scene");
    assert!(status.contains(" 200 "), "{status}");
    let scene: serde_json::Value = serde_json::from_str(&body).unwrap();
    let bodies = scene["bodies"].as_array().unwrap();
    assert_eq!(bodies.len(), 30, "the floating pelvis and 29 joints");
    assert!(bodies.iter().any(|b| b["name"] == "left_ankle_roll_link"));
    let segments = scene["ssv"]["segments"].as_array().unwrap();
    assert_eq!(segments.len(), 30);
    assert!(scene["ssv"]["file"]
        .as_str()
        .unwrap()
        .ends_with("g1_ssv.toml"));
    assert!(scene["ssv"]["read_only"]
        .as_str()
        .unwrap()
        .contains("--ssv"));
    let (status, body) = get(&addr, "/api/ssv");
    assert!(status.contains(" 200 "), "{status}");
    assert!(body.contains("[[segment]]"));
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    assert!(child.wait().unwrap().success());
}

#[test]
fn robot_conflicts_and_bad_descriptions_are_one_line() {
    fails_with(
        &["view", "--robot", "g1", "--lola", "type2"],
        &["--robot", "--lola"],
    );
    fails_with(
        &["view", "--robot", "g1", "--urdf", "x.urdf"],
        &["--robot", "--urdf"],
    );
    fails_with(&["view", "--robot", "h2"], &["--robot", "h2", "g1, talos"]);
    fails_with(&["view", "--package-path", "x"], &["--urdf", "--robot"]);
    let dir = temp("bad_robot");
    let bad = dir.join("bad.toml");
    std::fs::write(&bad, "name = \"x\"\nurdf = 3\n").unwrap();
    let bad = bad.to_str().unwrap();
    fails_with(&["view", "--robot", bad], &[&format!("{bad}:2: "), "urdf"]);
    let missing = dir.join("missing.toml");
    let missing = missing.to_str().unwrap();
    fails_with(&["view", "--robot", missing], &[missing]);
}
