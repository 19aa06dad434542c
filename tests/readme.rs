//! The shell examples of README.md and docs/**/*.md run as written.
//!
//! # Which blocks run
//!
//! A fenced code block whose language (the first word of its info string) is `sh`, `bash`,
//! `shell` or `console` is a shell block. The words after the language mark what this test does
//! with it (GitHub uses only the first word, so the marks do not show):
//!
//! - ` ```sh runnable ` / ` ```console runnable `: run on every `cargo test`;
//! - ` ```sh runnable robots `: needs the public robot models that `scripts/fetch_robots.sh`
//!   downloads (about 130 MB from PyPI, see docs/robots.md); run only when the environment
//!   variable `BIPED_ROBOTS_TEST=1` is set, e.g.
//!   `BIPED_ROBOTS_TEST=1 cargo test -p biped --test readme`;
//! - ` ```sh no-run `: shown only (it runs cargo itself, or fails on purpose).
//!
//! Every shell block must carry `runnable` or `no-run`, so that no example goes untested by
//! accident. In a `sh` block every line is script. In a `console` block the lines starting with
//! `$ ` are commands (a command ending in `\` continues on the next line) and the other lines
//! are the output shown to the reader.
//!
//! # How a block runs
//!
//! With `bash` (`set -eo pipefail`), standard input empty, the working directory the
//! repository's root (so that paths like `crates/dynamics/data/g1_29dof_rev_1_0.urdf` resolve),
//! and `cargo run --release --` replaced by this test's own `biped` binary, so the test never
//! runs cargo; a runnable block that still mentions cargo fails. The blocks write their results
//! under `out/` (git ignores it); a block that redirects into `out/` must create it first
//! (`mkdir -p out`), as on a fresh clone. The blocks run one after another: several write the
//! same default output folders.
//!
//! # What is checked
//!
//! Every command exits with status 0 (`set -e`), and every output line a `console` block shows
//! appears in the block's output (standard output and error together) up to its numbers: each
//! number is compared as "a number", because timings and the last digits of floating-point
//! results vary with the machine. `...` in a shown line stands for any text; a line that is just
//! `...` stands for lines left out. Also checked: relative links in these files point at files
//! (and headings) that exist.

use std::collections::BTreeSet;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The repository's root (the `biped` package's manifest directory).
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// README.md and every `.md` under docs/, as (path relative to the root, text).
fn documents() -> Vec<(String, String)> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    let root = root();
    let mut paths = vec![root.join("README.md")];
    let mut docs = Vec::new();
    walk(&root.join("docs"), &mut docs);
    docs.sort();
    paths.extend(docs);
    paths
        .into_iter()
        .map(|p| {
            let text =
                std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            let rel = p
                .strip_prefix(&root)
                .unwrap()
                .to_string_lossy()
                .into_owned();
            (rel, text)
        })
        .collect()
}

/// One fenced code block.
struct Block {
    /// `file:line` of the opening fence.
    at: String,
    lang: String,
    marks: Vec<String>,
    lines: Vec<String>,
}

impl Block {
    fn is_shell(&self) -> bool {
        matches!(self.lang.as_str(), "sh" | "bash" | "shell" | "console")
    }
    fn has(&self, mark: &str) -> bool {
        self.marks.iter().any(|m| m == mark)
    }
}

/// The fenced code blocks of a Markdown text (backtick or tilde fences at the line start).
fn blocks(file: &str, text: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut open: Option<(String, Block)> = None;
    for (i, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        let fence_len = |c: char| trimmed.chars().take_while(|&x| x == c).count();
        match &mut open {
            None => {
                for c in ['`', '~'] {
                    let n = fence_len(c);
                    if n >= 3 {
                        let info = &trimmed[n..];
                        let mut words = info
                            .split(|ch: char| ch.is_whitespace() || ch == ',')
                            .filter(|w| !w.is_empty())
                            .map(str::to_string);
                        let lang = words.next().unwrap_or_default();
                        let block = Block {
                            at: format!("{file}:{}", i + 1),
                            lang,
                            marks: words.collect(),
                            lines: Vec::new(),
                        };
                        open = Some((c.to_string().repeat(n), block));
                        break;
                    }
                }
            }
            Some((fence, block)) => {
                let c = fence.chars().next().unwrap();
                if fence_len(c) >= fence.len() && trimmed[fence_len(c)..].trim().is_empty() {
                    out.push(open.take().unwrap().1);
                } else {
                    block.lines.push(line.to_string());
                }
            }
        }
    }
    assert!(open.is_none(), "{file}: a code block is not closed");
    out
}

/// A runnable block split into its script and the output it shows.
struct Example {
    at: String,
    script: String,
    shown: Vec<String>,
}

fn example(block: &Block, biped: &str) -> Result<Example, String> {
    let mut commands = Vec::new();
    let mut shown = Vec::new();
    if block.lang == "console" {
        let mut continued = false;
        for line in &block.lines {
            if continued {
                commands.push(line.clone());
            } else if let Some(cmd) = line.strip_prefix("$ ") {
                commands.push(cmd.to_string());
            } else {
                shown.push(line.clone());
                continue;
            }
            continued = line.trim_end().ends_with('\\');
        }
    } else {
        commands = block.lines.clone();
    }
    let quoted = format!("'{}'", biped.replace('\'', r"'\''"));
    let body = commands
        .join("\n")
        .replace("cargo run --release --", &quoted);
    if body
        .split(|c: char| !c.is_alphanumeric() && c != '-' && c != '_')
        .any(|w| w == "cargo")
    {
        return Err(format!(
            "{}: a runnable block runs cargo other than `cargo run --release --`; mark it no-run",
            block.at
        ));
    }
    let redirects_into_out = body.contains("> out/") || body.contains(">out/");
    if redirects_into_out && !body.contains("mkdir -p out") {
        return Err(format!(
            "{}: the block redirects into out/ without `mkdir -p out` (a fresh clone has no out/)",
            block.at
        ));
    }
    Ok(Example {
        at: block.at.clone(),
        script: format!("set -eo pipefail\n{body}\n"),
        shown,
    })
}

/// A line with whitespace runs collapsed and every number replaced by `#`.
fn skeleton(line: &str) -> String {
    let chars: Vec<char> = line
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
        .chars()
        .collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let prev_word = i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
        let starts_number = !prev_word
            && (c.is_ascii_digit()
                || (c == '.' && chars.get(i + 1).is_some_and(|d| d.is_ascii_digit())));
        if !starts_number {
            out.push(c);
            i += 1;
            continue;
        }
        while i < chars.len() && chars[i].is_ascii_digit() {
            i += 1;
        }
        if i + 1 < chars.len() && chars[i] == '.' && chars[i + 1].is_ascii_digit() {
            i += 1;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
        }
        if i < chars.len() && (chars[i] == 'e' || chars[i] == 'E') {
            let mut j = i + 1;
            if j < chars.len() && (chars[j] == '-' || chars[j] == '+') {
                j += 1;
            }
            if j < chars.len() && chars[j].is_ascii_digit() {
                i = j;
                while i < chars.len() && chars[i].is_ascii_digit() {
                    i += 1;
                }
            }
        }
        out.push('#');
    }
    out
}

/// Whether an output line matches a shown line (numbers as `#`, `...` as any text).
fn matches(shown: &str, actual: &str) -> bool {
    let actual = skeleton(actual);
    let pieces: Vec<String> = shown
        .split("...")
        .map(|p| skeleton(p).trim().to_string())
        .collect();
    if pieces.len() == 1 {
        return actual.trim() == pieces[0];
    }
    let mut rest = actual.trim();
    let last = pieces.len() - 1;
    for (k, piece) in pieces.iter().enumerate() {
        if k == 0 {
            match rest.strip_prefix(piece.as_str()) {
                Some(r) => rest = r,
                None => return false,
            }
        } else if k == last {
            return rest.ends_with(piece.as_str());
        } else {
            match rest.find(piece.as_str()) {
                Some(p) => rest = &rest[p + piece.len()..],
                None => return false,
            }
        }
    }
    true
}

/// Runs one example; `Err` says what went wrong.
fn run(example: &Example, timeout: Duration) -> Result<Duration, String> {
    use std::os::unix::process::CommandExt;
    let start = Instant::now();
    let mut child = Command::new("bash")
        .arg("-c")
        .arg(&example.script)
        .current_dir(root())
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .process_group(0)
        .spawn()
        .map_err(|e| format!("{}: cannot start bash: {e}", example.at))?;
    let reader = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut s = Vec::new();
            let _ = r.read_to_end(&mut s);
            String::from_utf8_lossy(&s).into_owned()
        })
    };
    let stdout = reader(Box::new(child.stdout.take().unwrap()));
    let stderr = reader(Box::new(child.stderr.take().unwrap()));
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            break Some(status);
        }
        if start.elapsed() > timeout {
            // The whole process group: bash and the commands it started.
            let _ = Command::new("kill")
                .args(["-KILL", &format!("-{}", child.id())])
                .status();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let (stdout, stderr) = (stdout.join().unwrap(), stderr.join().unwrap());
    let output = format!("--- stdout:\n{stdout}--- stderr:\n{stderr}");
    let Some(status) = status else {
        return Err(format!(
            "{}: timed out after {timeout:?}\n{output}",
            example.at
        ));
    };
    if !status.success() {
        return Err(format!("{}: failed ({status})\n{output}", example.at));
    }
    let lines: Vec<&str> = stdout.lines().chain(stderr.lines()).collect();
    for shown in &example.shown {
        let t = shown.trim();
        if t.is_empty() || t == "..." || t == "…" {
            continue;
        }
        if !lines.iter().any(|l| matches(t, l)) {
            return Err(format!(
                "{}: the shown output line\n    {t}\nis not in the output (numbers aside)\n{output}",
                example.at
            ));
        }
    }
    Ok(start.elapsed())
}

/// The runnable blocks, with or without the ones that need the robot models.
fn examples(robots: bool) -> Vec<Example> {
    let biped = env!("CARGO_BIN_EXE_biped");
    let mut out = Vec::new();
    for (file, text) in documents() {
        for block in blocks(&file, &text) {
            if block.is_shell() && block.has("runnable") && block.has("robots") == robots {
                out.push(example(&block, biped).unwrap_or_else(|e| panic!("{e}")));
            }
        }
    }
    out
}

/// The blocks write into the same `out/` folders: one runner at a time.
static SERIAL: Mutex<()> = Mutex::new(());

fn run_all(examples: &[Example], timeout: Duration) {
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let mut failures = Vec::new();
    for example in examples {
        match run(example, timeout) {
            Ok(took) => eprintln!("ok   {} ({:.1} s)", example.at, took.as_secs_f64()),
            Err(e) => {
                eprintln!("FAIL {}", example.at);
                failures.push(e);
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} examples failed:\n\n{}",
        failures.len(),
        examples.len(),
        failures.join("\n\n")
    );
}

#[test]
fn runnable_blocks_run_as_written() {
    let examples = examples(false);
    assert!(
        examples.len() >= 10,
        "only {} runnable blocks found",
        examples.len()
    );
    assert!(
        examples.iter().any(|e| e.at.starts_with("README.md")),
        "README.md has no runnable block"
    );
    run_all(&examples, Duration::from_secs(120));
}

#[test]
fn robot_blocks_run_when_asked() {
    let examples = examples(true);
    assert!(!examples.is_empty(), "no `runnable robots` block found");
    if std::env::var("BIPED_ROBOTS_TEST").as_deref() != Ok("1") {
        eprintln!(
            "skipped {} block(s) that need scripts/fetch_robots.sh: set BIPED_ROBOTS_TEST=1",
            examples.len()
        );
        return;
    }
    run_all(&examples, Duration::from_secs(900));
}

#[test]
fn every_shell_block_is_marked() {
    let known = ["runnable", "no-run", "robots"];
    let mut problems = Vec::new();
    for (file, text) in documents() {
        for block in blocks(&file, &text) {
            if !block.is_shell() {
                continue;
            }
            for mark in &block.marks {
                if !known.contains(&mark.as_str()) {
                    problems.push(format!("{}: unknown mark `{mark}`", block.at));
                }
            }
            if block.has("runnable") == block.has("no-run") {
                problems.push(format!(
                    "{}: mark the block `runnable` or `no-run`",
                    block.at
                ));
            }
            if block.has("robots") && !block.has("runnable") {
                problems.push(format!("{}: `robots` goes with `runnable`", block.at));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// GitHub's anchor of a heading: lower case, punctuation dropped, spaces as hyphens.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            '-' | '_' => Some(c),
            c if c.is_alphanumeric() => Some(c.to_lowercase().next().unwrap()),
            _ => None,
        })
        .collect()
}

/// The anchors of a Markdown text's headings (outside code blocks).
fn anchors(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut in_code = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            in_code = !in_code;
        } else if !in_code && line.starts_with('#') {
            let a = anchor(line.trim_start_matches('#'));
            let mut name = a.clone();
            let mut k = 1;
            while out.contains(&name) {
                name = format!("{a}-{k}");
                k += 1;
            }
            out.insert(name);
        }
    }
    out
}

#[test]
fn relative_links_resolve() {
    let root = root();
    let mut problems = Vec::new();
    for (file, text) in documents() {
        let dir = root.join(&file).parent().unwrap().to_path_buf();
        let mut in_code = false;
        for (i, line) in text.lines().enumerate() {
            if line.trim_start().starts_with("```") {
                in_code = !in_code;
                continue;
            }
            if in_code {
                continue;
            }
            let mut rest = line;
            while let Some(p) = rest.find("](") {
                let after = &rest[p + 2..];
                let Some(end) = after.find(')') else { break };
                let target = &after[..end];
                rest = &after[end..];
                if target.contains("://") || target.starts_with("mailto:") {
                    continue;
                }
                let (path, fragment) = match target.split_once('#') {
                    Some((p, f)) => (p, Some(f)),
                    None => (target, None),
                };
                let resolved = if path.is_empty() {
                    root.join(&file)
                } else {
                    dir.join(path)
                };
                if !resolved.exists() {
                    problems.push(format!("{file}:{}: `{target}`: no such file", i + 1));
                    continue;
                }
                if let Some(fragment) = fragment {
                    let target_text = std::fs::read_to_string(&resolved).unwrap_or_default();
                    if !anchors(&target_text).contains(fragment) {
                        problems.push(format!("{file}:{}: `{target}`: no such heading", i + 1));
                    }
                }
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn skeletons_and_matching() {
    assert_eq!(skeleton("peak |L_z| 1.707 N m s"), "peak |L_z| # N m s");
    assert_eq!(
        skeleton("below 1.492e-7  (limit 1.000e-3)"),
        "below # (limit #)"
    );
    assert_eq!(skeleton("q[10] g1_29dof Type2"), "q[#] g1_29dof Type2");
    assert!(matches(
        "realtime factor 18.189; 3000 steps",
        "realtime factor 55.1; 3000 steps"
    ));
    assert!(!matches("ok: final max |v|", "FAILED: final max |v|"));
    assert!(matches(
        "{\"a\":[1, ...],\"b\":2}",
        "{\"a\":[1,2,3],\"b\":2}"
    ));
    assert!(!matches(
        "{\"a\":[1, ...],\"c\":2}",
        "{\"a\":[1,2,3],\"b\":2}"
    ));
}
