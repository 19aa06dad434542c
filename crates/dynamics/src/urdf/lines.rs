//! Line numbers of byte offsets, and reading a text file whose bytes may not be UTF-8, for the
//! located errors of the URDF and SRDF readers.

use std::path::Path;

/// The start offset of every line of a text, built in one pass: a byte offset's line is a
/// binary search, so locating many elements stays linear in the text (up to a log factor).
pub(super) struct LineIndex {
    /// Byte offset of the first byte of each line after the first.
    starts: Vec<usize>,
}

impl LineIndex {
    /// The index of `text`.
    pub(super) fn new(text: &str) -> Self {
        let starts = text
            .bytes()
            .enumerate()
            .filter(|&(_, b)| b == b'\n')
            .map(|(i, _)| i + 1)
            .collect();
        Self { starts }
    }

    /// 1-based line of byte `offset`.
    pub(super) fn line_of(&self, offset: usize) -> usize {
        1 + self.starts.partition_point(|&s| s <= offset)
    }
}

/// Why [`read_text`] failed.
pub(super) enum ReadError {
    /// The file could not be read.
    Io(std::io::Error),
    /// The bytes are not UTF-8 from this 1-based line on.
    NotUtf8 {
        /// Line of the first invalid byte.
        line: usize,
    },
}

/// The text of the file at `path`; invalid UTF-8 is reported with its line.
pub(super) fn read_text(path: &Path) -> Result<String, ReadError> {
    let bytes = std::fs::read(path).map_err(ReadError::Io)?;
    String::from_utf8(bytes).map_err(|e| {
        let valid = &e.as_bytes()[..e.utf8_error().valid_up_to()];
        ReadError::NotUtf8 {
            line: 1 + valid.iter().filter(|&&b| b == b'\n').count(),
        }
    })
}

/// `message` with control characters (newlines, tabs, ...) written as escapes, so that it
/// stays one line (XML readers quote the offending character).
pub(super) fn one_line(message: &str) -> String {
    message
        .chars()
        .map(|c| match c.is_control() {
            true => c.escape_default().to_string(),
            false => c.to_string(),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_of_offsets() {
        let index = LineIndex::new("ab\n\ncd\n");
        let lines: Vec<usize> = (0..8).map(|o| index.line_of(o)).collect();
        assert_eq!(lines, [1, 1, 1, 2, 3, 3, 3, 4]);
    }

    #[test]
    fn one_line_escapes_controls() {
        assert_eq!(one_line("not '\n' at 3"), "not '\\n' at 3");
    }
}
