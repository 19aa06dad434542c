//! Positions in the calibration file's text for located errors: the line of a value, the
//! start of an array element, the field name before a parser error.

/// 1-based line and column -> byte offset.
pub(crate) fn offset_of(text: &str, line: usize, column: usize) -> usize {
    let start: usize = text
        .split_inclusive('\n')
        .take(line.saturating_sub(1))
        .map(str::len)
        .sum();
    (start + column.saturating_sub(1)).min(text.len())
}

/// The last JSON object key (`"key":`) that starts before byte `offset`, if it is a field
/// name of the format (letters, digits, `_`; a damaged file can put the quotes elsewhere).
pub(crate) fn key_before(text: &str, offset: usize) -> Option<String> {
    quoted_before(text, offset)
        .filter(|k| !k.is_empty() && k.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))
}

/// The text between the last pair of quotes followed by `:` before byte `offset`.
fn quoted_before(text: &str, offset: usize) -> Option<String> {
    let head = &text[..offset.min(text.len())];
    let bytes = head.as_bytes();
    let mut i = head.len();
    while i > 0 {
        i -= 1;
        if bytes[i] != b':' {
            continue;
        }
        let before = head[..i].trim_end();
        if let Some(stripped) = before.strip_suffix('"') {
            if let Some(q) = stripped.rfind('"') {
                return Some(stripped[q + 1..].to_string());
            }
        }
    }
    None
}

/// 1-based line of the first occurrence of `"needle"` in `text` at or after byte `from`,
/// else of the first occurrence anywhere (0 if absent).
pub(crate) fn line_of(text: &str, needle: &str, from: usize) -> usize {
    let quoted = format!("\"{needle}\"");
    let from = from.min(text.len());
    text[from..]
        .find(&quoted)
        .map(|p| p + from)
        .or_else(|| text.find(&quoted))
        .map(|p| text[..p].matches('\n').count() + 1)
        .unwrap_or(0)
}

/// Byte offset of element `index` (any JSON value: object, array, string or number) of the
/// array `"key": [...]` at its first occurrence, 0 if not found. One linear scan that tracks
/// nesting depth and strings (no recursion).
pub(crate) fn array_element(text: &str, key: &str, index: usize) -> usize {
    let quoted = format!("\"{key}\"");
    let Some(k) = text.find(&quoted) else {
        return 0;
    };
    let Some(open) = text[k..].find('[').map(|p| p + k) else {
        return 0;
    };
    let (mut depth, mut in_str, mut escaped) = (0usize, false, false);
    let (mut seen, mut expect_item) = (0usize, false);
    for (p, ch) in text[open..].char_indices() {
        if in_str {
            (escaped, in_str) = match (escaped, ch) {
                (true, _) => (false, true),
                (false, '\\') => (true, true),
                (false, '"') => (false, false),
                _ => (false, true),
            };
            continue;
        }
        if expect_item && !ch.is_whitespace() && ch != ']' {
            if seen == index {
                return open + p;
            }
            (seen, expect_item) = (seen + 1, false);
        }
        match ch {
            '"' => in_str = true,
            '[' | '{' => {
                depth += 1;
                expect_item |= depth == 1;
            }
            ']' | '}' => {
                depth = depth.saturating_sub(1);
                if depth == 0 {
                    return 0;
                }
            }
            ',' if depth == 1 => expect_item = true,
            _ => {}
        }
    }
    0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Elements of every kind are found at their first character, nested ones skipped.
    #[test]
    fn array_elements_of_any_kind() {
        let text = r#"{"a": [1, "x,]", {"b": [2, 3]}, [4], "y"], "c": ["z"]}"#;
        let at = |i| &text[array_element(text, "a", i)..][..3];
        assert_eq!(
            [at(0), at(1), at(2), at(3), at(4)],
            ["1, ", "\"x,", "{\"b", "[4]", "\"y\""]
        );
        assert_eq!(array_element(text, "a", 5), 0);
        assert_eq!(&text[array_element(text, "c", 0)..][..3], "\"z\"");
        assert_eq!(array_element(text, "missing", 0), 0);
    }
}
