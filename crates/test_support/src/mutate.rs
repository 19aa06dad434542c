//! Random corruptions of a valid input file for the parsers' property tests ("bad input gets a
//! clear error, never a panic"): byte edits anywhere, or replacements by the characters that
//! carry a format's structure and numbers.

use proptest::prelude::*;
use proptest::sample::Index;

/// One byte edit: replace, insert or delete at a position scaled to the input's length.
#[derive(Debug, Clone)]
pub enum Edit {
    /// Replace the byte at the position.
    Replace(Index, u8),
    /// Insert a byte before the position.
    Insert(Index, u8),
    /// Delete the byte at the position.
    Delete(Index),
}

/// One to `max` random byte edits of any kind with any byte value.
pub fn byte_edits(max: usize) -> impl Strategy<Value = Vec<Edit>> {
    let edit = prop_oneof![
        (any::<Index>(), any::<u8>()).prop_map(|(i, b)| Edit::Replace(i, b)),
        (any::<Index>(), any::<u8>()).prop_map(|(i, b)| Edit::Insert(i, b)),
        any::<Index>().prop_map(Edit::Delete),
    ];
    prop::collection::vec(edit, 1..=max)
}

/// One to `max` replacements of a byte by one of `alphabet` (e.g. the characters of a format's
/// structure and numbers: brackets, quotes, signs, digits, exponent markers, newlines).
pub fn structural_edits(alphabet: &'static [u8], max: usize) -> impl Strategy<Value = Vec<Edit>> {
    let edit =
        (any::<Index>(), prop::sample::select(alphabet)).prop_map(|(i, b)| Edit::Replace(i, b));
    prop::collection::vec(edit, 1..=max)
}

/// `bytes` with `edits` applied in order (edits on an empty input are skipped).
pub fn apply(bytes: &[u8], edits: &[Edit]) -> Vec<u8> {
    let mut out = bytes.to_vec();
    for edit in edits {
        if out.is_empty() {
            if let Edit::Insert(_, b) = edit {
                out.push(*b);
            }
            continue;
        }
        match *edit {
            Edit::Replace(at, b) => {
                let i = at.index(out.len());
                out[i] = b;
            }
            Edit::Insert(at, b) => {
                let i = at.index(out.len() + 1);
                out.insert(i, b);
            }
            Edit::Delete(at) => {
                let i = at.index(out.len());
                out.remove(i);
            }
        }
    }
    out
}

/// Values a number of an input is replaced by in [`number_edits`]: zero of both signs, the
/// largest and a subnormal magnitude, a negative, a large and a fractional value.
pub const EDGE_NUMBERS: [&str; 9] = [
    "0", "-0", "1e308", "-1e308", "1e-320", "-1", "1e9", "0.5", "-3.7",
];

/// One to `max` replacements of a number of the input (chosen by position among its numbers)
/// by one of [`EDGE_NUMBERS`]: the file stays well-formed, so its values reach the checks
/// behind the parser.
pub fn number_edits(max: usize) -> impl Strategy<Value = Vec<(Index, &'static str)>> {
    prop::collection::vec(
        (any::<Index>(), prop::sample::select(&EDGE_NUMBERS[..])),
        1..=max,
    )
}

/// Byte ranges of the decimal numbers in `text` (an optional `-`, digits, then any of
/// `0-9 . e E + -`), not starting inside a word (so `x1` or `link2` are not numbers).
pub fn numbers(text: &str) -> Vec<std::ops::Range<usize>> {
    let b = text.as_bytes();
    let (mut out, mut i) = (Vec::new(), 0);
    let word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    while i < b.len() {
        let start = i;
        let sign = usize::from(b[i] == b'-');
        let digit = b.get(i + sign).is_some_and(u8::is_ascii_digit);
        if digit && (start == 0 || !word(b[start - 1])) {
            i += sign;
            while i < b.len() && (b[i].is_ascii_digit() || b".eE+-".contains(&b[i])) {
                i += 1;
            }
            out.push(start..i);
        } else {
            i += 1;
        }
    }
    out
}

/// `text` with the numbers chosen by `edits` replaced (each edit picks among the numbers of
/// the text as it is then); unchanged if it has none.
pub fn apply_numbers(text: &str, edits: &[(Index, &str)]) -> String {
    let mut out = text.to_string();
    for (at, value) in edits {
        let spans = numbers(&out);
        if spans.is_empty() {
            break;
        }
        let span = spans[at.index(spans.len())].clone();
        out.replace_range(span, value);
    }
    out
}

/// One corruption of a text file: byte edits (its bytes read back lossily as UTF-8), edge
/// values for its numbers, or the byte edits followed by number edits.
#[derive(Debug, Clone)]
pub enum Corruption {
    /// [`byte_edits`] or [`structural_edits`].
    Bytes(Vec<Edit>),
    /// [`number_edits`]: the file stays well-formed.
    Numbers(Vec<(Index, &'static str)>),
    /// Both, bytes first.
    Both(Vec<Edit>, Vec<(Index, &'static str)>),
}

impl Corruption {
    /// The corrupted `text`.
    pub fn apply(&self, text: &str) -> String {
        let bytes =
            |edits: &[Edit]| String::from_utf8_lossy(&apply(text.as_bytes(), edits)).into_owned();
        match self {
            Corruption::Bytes(edits) => bytes(edits),
            Corruption::Numbers(numbers) => apply_numbers(text, numbers),
            Corruption::Both(edits, numbers) => apply_numbers(&bytes(edits), numbers),
        }
    }
}

/// Corruptions of all three kinds, up to `max` edits each; structural edits draw from
/// `alphabet`.
pub fn corruptions(alphabet: &'static [u8], max: usize) -> impl Strategy<Value = Corruption> {
    let bytes = || prop_oneof![byte_edits(max), structural_edits(alphabet, max)];
    prop_oneof![
        bytes().prop_map(Corruption::Bytes),
        number_edits(max).prop_map(Corruption::Numbers),
        (bytes(), number_edits(max)).prop_map(|(b, n)| Corruption::Both(b, n)),
    ]
}

/// Number of lines of `bytes` (a final line without a newline counts).
pub fn line_count(bytes: &[u8]) -> usize {
    1 + bytes.iter().filter(|&&b| b == b'\n').count()
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest! {
        /// Lengths change by the inserts minus the deletes; replacements keep the length.
        #[test]
        fn edits_change_the_length_as_counted(edits in byte_edits(12), len in 1usize..40) {
            let bytes = vec![b'a'; len];
            let out = apply(&bytes, &edits);
            let mut expect = len as i64;
            for e in &edits {
                match e {
                    Edit::Insert(..) => expect += 1,
                    Edit::Delete(..) if expect > 0 => expect -= 1,
                    _ => {}
                }
            }
            prop_assert_eq!(out.len() as i64, expect);
        }
    }

    #[test]
    fn numbers_are_found_outside_words() {
        let text = "a = -1.5e3, x1 = 2 [3,-4] link2 0.25";
        let found: Vec<&str> = numbers(text).into_iter().map(|r| &text[r]).collect();
        assert_eq!(found, ["-1.5e3", "2", "3", "-4", "0.25"]);
    }

    proptest! {
        /// A replaced number is one of the edge values and the text keeps its other parts.
        #[test]
        fn number_edits_replace_whole_numbers(edits in number_edits(3)) {
            let text = "x = 1.25\ny = [2, -3e-2]\nname = \"j4\"\n";
            let out = apply_numbers(text, &edits);
            prop_assert!(out.starts_with("x = ") && out.ends_with("name = \"j4\"\n"), "{}", out);
            let found = numbers(&out);
            prop_assert_eq!(found.len(), 3);
            for r in found {
                let n = &out[r];
                prop_assert!(["1.25", "2", "-3e-2"].contains(&n) || EDGE_NUMBERS.contains(&n), "{}", n);
            }
        }
    }

    #[test]
    fn line_count_counts_the_last_line() {
        assert_eq!(line_count(b""), 1);
        assert_eq!(line_count(b"a\nb"), 2);
        assert_eq!(line_count(b"a\n"), 2);
    }
}
