//! JSON Lines driver of the streaming commands (`biped ssv query`, `biped dynamics`): one
//! answer line per non-blank input line. A bad line (not UTF-8, longer than [`MAX_LINE`],
//! or a request the command rejects) is answered with `{"error": "line N: .."}` and
//! processing goes on; a UTF-8 byte-order mark at the start of the input is ignored.

use serde::Serialize;
use serde_json::json;
use std::io::{BufRead, ErrorKind, Write};

/// Longest input line read, in bytes: a longer line is answered with an error and skipped
/// without being held in memory, so memory stays bounded whatever the input.
pub const MAX_LINE: usize = 16 << 20;

/// The UTF-8 byte-order mark.
const BOM: &[u8] = b"\xef\xbb\xbf";

/// Answers every non-blank line of `input` with `answer(line)` on `output`; returns false if
/// any line was bad.
pub fn serve<T: Serialize>(
    mut input: impl BufRead,
    mut output: impl Write,
    mut answer: impl FnMut(&str) -> Result<T, String>,
) -> std::io::Result<bool> {
    let mut all_good = true;
    let mut buf = Vec::new();
    let mut line_no = 0usize;
    while let Some(complete) = read_line(&mut input, &mut buf)? {
        line_no += 1;
        let bytes = match line_no {
            1 => buf.strip_prefix(BOM).unwrap_or(&buf),
            _ => &buf,
        };
        let result = match (complete, std::str::from_utf8(bytes)) {
            (false, _) => Err(format!("longer than {MAX_LINE} bytes")),
            (true, Ok(text)) if text.trim().is_empty() => continue,
            (true, Ok(text)) => answer(text),
            (true, Err(e)) => Err(format!("not UTF-8 text: {e}")),
        };
        match result {
            Ok(value) => serde_json::to_writer(&mut output, &value)?,
            Err(msg) => {
                all_good = false;
                let error = json!({ "error": format!("line {line_no}: {msg}") });
                serde_json::to_writer(&mut output, &error)?;
            }
        }
        output.write_all(b"\n")?;
    }
    output.flush()?;
    Ok(all_good)
}

/// Reads the next line of `input` into `buf`, without its `\n`: `Some(true)` for a line,
/// `Some(false)` for a line longer than [`MAX_LINE`] (read to its end but not kept), `None`
/// at the end of the input.
fn read_line(input: &mut impl BufRead, buf: &mut Vec<u8>) -> std::io::Result<Option<bool>> {
    buf.clear();
    let (mut started, mut too_long) = (false, false);
    loop {
        let chunk = match input.fill_buf() {
            Ok(chunk) => chunk,
            Err(e) if e.kind() == ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if chunk.is_empty() {
            return Ok(started.then_some(!too_long));
        }
        started = true;
        let newline = chunk.iter().position(|&b| b == b'\n');
        let part = &chunk[..newline.unwrap_or(chunk.len())];
        too_long |= buf.len() + part.len() > MAX_LINE;
        if !too_long {
            buf.extend_from_slice(part);
        }
        let used = newline.map_or(chunk.len(), |i| i + 1);
        input.consume(used);
        if newline.is_some() {
            return Ok(Some(!too_long));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The answers of `serve` to `input` when every valid line is answered by its length.
    fn answers(input: &[u8]) -> (bool, String) {
        let mut out = Vec::new();
        let ok = serve(input, &mut out, |line| match line {
            "bad" => Err("rejected".to_string()),
            _ => Ok(line.len()),
        })
        .unwrap();
        (ok, String::from_utf8(out).unwrap())
    }

    #[test]
    fn bad_lines_are_answered_and_processing_goes_on() {
        let (ok, out) = answers(b"\xef\xbb\xbfab\n\n\xff\xfe\nbad\nabc\r\nabcde");
        assert!(!ok);
        let lines: Vec<&str> = out.lines().collect();
        assert_eq!(lines.len(), 5, "{out}");
        assert_eq!(lines[0], "2");
        assert!(
            lines[1].starts_with(r#"{"error":"line 3: not UTF-8 text"#),
            "{out}"
        );
        assert_eq!(lines[2], r#"{"error":"line 4: rejected"}"#);
        // `\r` before `\n` stays part of the line (JSON takes it as white space).
        assert_eq!(&lines[3..], ["4", "5"]);
        assert!(answers(b"ab\n").0);
        // A byte-order mark is only skipped at the start.
        assert!(answers(b"a\n\xef\xbb\xbfb\n").1.ends_with("4\n"));
    }

    #[test]
    fn overlong_lines_are_errors_without_being_kept() {
        let mut input = vec![b'x'; MAX_LINE + 1];
        input.extend_from_slice(b"\nabc\n");
        let (ok, out) = answers(&input);
        assert!(!ok);
        let expected = format!("{{\"error\":\"line 1: longer than {MAX_LINE} bytes\"}}\n3\n");
        assert_eq!(out, expected);
    }
}
