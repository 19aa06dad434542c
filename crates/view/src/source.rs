//! How each segment and pair is written in the model file, so that the page can edit a
//! segment's `ssvs = [...]` entries, a version's `keep`, the pairs (`pairs = [...]` or `[[pair]]`
//! tables) and detach a mirrored segment, splicing the change into the file text and leaving
//! every other line (comments, other segments, postures) as it was.

use serde::{Deserialize, Serialize};
use toml::Spanned;

/// One entry of a segment's `ssvs` array, as written (before `mirror_copy` expands it).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
pub struct EntryJson {
    /// Vertex of a point SSV.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub point: Option<[f64; 3]>,
    /// End points of a line SSV.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub line: Option<[[f64; 3]; 2]>,
    /// Vertices of a triangle SSV.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub triangle: Option<[[f64; 3]; 3]>,
    /// Radius.
    pub radius: f64,
    /// Plane of a mirrored copy added after the entry (`xy`, `yz`, `xz`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mirror_copy: Option<String>,
}

/// How a segment is defined in the file.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SegmentSource {
    /// Explicit entries; `span` is the `[start, end)` of the array's text in UTF-16 code
    /// units (JavaScript string indices), so the page can replace it.
    Ssvs {
        /// The entries as written.
        entries: Vec<EntryJson>,
        /// Where the array is in the text.
        span: [usize; 2],
        /// The entries are `[[segment.ssvs]]` tables: `span` covers their lines, from the
        /// first header to the end of the last one's last key line, and an edit replaces them
        /// by an `ssvs = [...]` key.
        tables: bool,
    },
    /// The mirror image of another segment.
    MirrorOf {
        /// The mirrored segment.
        of: String,
        /// The whole lines of its `mirror_of` and `plane` keys (UTF-16 `[start, end)`, each
        /// with its newline), which detaching replaces by an `ssvs` array; `null` when they
        /// are not written on lines of their own.
        lines: Option<[[usize; 2]; 2]>,
    },
    /// A version (subset) of another segment.
    VersionOf {
        /// The full segment.
        of: String,
        /// The kept SSV indices (of the full segment's expanded list).
        keep: Vec<i64>,
        /// Where the `keep` array is in the text (UTF-16 indices), `null` if it is missing.
        span: Option<[usize; 2]>,
    },
    /// Not found in the text (does not happen for a file that loaded).
    Unknown,
}

#[derive(Deserialize)]
struct SourceFile {
    #[serde(default)]
    segment: Vec<SourceSegment>,
    pairs: Option<Spanned<Vec<[String; 2]>>>,
    #[serde(default)]
    pair: Vec<Spanned<SourcePair>>,
}

#[derive(Deserialize)]
struct SourcePair {
    a: Spanned<String>,
    b: Spanned<String>,
}

/// One `[[pair]]` table of the file.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairTableJson {
    /// First segment.
    pub a: String,
    /// Second segment.
    pub b: String,
    /// The table's lines, from its header to the end of its last key's line with the
    /// newline (UTF-16 `[start, end)`): what removing the pair cuts out.
    pub span: [usize; 2],
}

/// The file's `pairs = [...]` array (pairs written as `[[pair]]` tables are not in it).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairListJson {
    /// The pairs of the array, by segment name.
    pub pairs: Vec<[String; 2]>,
    /// Where the array is in the text (UTF-16 indices, as for segments).
    pub span: [usize; 2],
}

fn utf16_span(text: &str, span: std::ops::Range<usize>) -> [usize; 2] {
    let utf16 = |byte: usize| text[..byte].encode_utf16().count();
    [utf16(span.start), utf16(span.end)]
}

/// The `pairs = [...]` array of the text, if it has one and parses.
pub fn pair_list(text: &str) -> Option<PairListJson> {
    let pairs = toml::from_str::<SourceFile>(text).ok()?.pairs?;
    let span = utf16_span(text, pairs.span());
    Some(PairListJson {
        pairs: pairs.into_inner(),
        span,
    })
}

/// Byte offset of the start of the line holding `at`.
fn line_start(text: &str, at: usize) -> usize {
    text[..at].rfind('\n').map_or(0, |i| i + 1)
}

/// Byte offset just past the newline ending the line holding `at` (or the text's end).
fn line_end(text: &str, at: usize) -> usize {
    text[at..].find('\n').map_or(text.len(), |i| at + i + 1)
}

/// The file's `[[pair]]` tables in file order (empty without any), or `None` when the text
/// does not parse or a pair is written otherwise (e.g. `pair = [{ a = .., b = .. }]`), so
/// that the page does not offer to cut it.
pub fn pair_tables(text: &str) -> Option<Vec<PairTableJson>> {
    let file = toml::from_str::<SourceFile>(text).ok()?;
    let table = |p: &Spanned<SourcePair>| {
        let header = p.span();
        if !text[header.clone()].starts_with("[[") {
            return None;
        }
        let SourcePair { a, b } = p.get_ref();
        let last = a.span().end.max(b.span().end);
        let span = line_start(text, header.start)..line_end(text, last);
        Some(PairTableJson {
            a: a.get_ref().clone(),
            b: b.get_ref().clone(),
            span: utf16_span(text, span),
        })
    };
    file.pair.iter().map(table).collect()
}

/// The whole line of a key whose value is `value`, if the line holds only that key.
fn key_line(text: &str, key: &str, value: &Spanned<String>) -> Option<std::ops::Range<usize>> {
    let start = line_start(text, value.span().start);
    let end = line_end(text, value.span().end);
    let line = text[start..end].trim_start();
    let after = line.strip_prefix(key)?.trim_start();
    after.starts_with('=').then_some(start..end)
}

/// The `mirror_of` and `plane` lines of a mirrored segment, if each is a line of its own.
fn mirror_lines(
    text: &str,
    of: &Spanned<String>,
    plane: Option<&Spanned<String>>,
) -> Option<[[usize; 2]; 2]> {
    let of = key_line(text, "mirror_of", of)?;
    let plane = key_line(text, "plane", plane?)?;
    (of != plane).then(|| [utf16_span(text, of), utf16_span(text, plane)])
}

#[derive(Deserialize)]
struct SourceSegment {
    name: String,
    ssvs: Option<Spanned<Vec<EntryJson>>>,
    mirror_of: Option<Spanned<String>>,
    plane: Option<Spanned<String>>,
    version_of: Option<String>,
    keep: Option<Spanned<Vec<i64>>>,
}

/// Every segment's name and source, in file order (empty if the text does not parse).
pub fn segment_sources(text: &str) -> Vec<(String, SegmentSource)> {
    let (Ok(file), Ok(tables)) = (
        toml::from_str::<SourceFile>(text),
        toml::from_str::<TableFile>(text),
    ) else {
        return Vec::new();
    };
    let mut tables = tables.segment.into_iter();
    let source = |s: SourceSegment| {
        let entry_spans = tables.next().and_then(|t| t.ssvs).unwrap_or_default();
        let src = match (s.ssvs, s.mirror_of, s.version_of) {
            (Some(ssvs), _, _) => {
                let (span, tables) = match table_lines(text, &entry_spans) {
                    Some(lines) => (lines, true),
                    None => (ssvs.span(), false),
                };
                SegmentSource::Ssvs {
                    entries: ssvs.into_inner(),
                    span: utf16_span(text, span),
                    tables,
                }
            }
            (None, Some(of), _) => SegmentSource::MirrorOf {
                lines: mirror_lines(text, &of, s.plane.as_ref()),
                of: of.into_inner(),
            },
            (None, None, Some(of)) => SegmentSource::VersionOf {
                span: s.keep.as_ref().map(|k| utf16_span(text, k.span())),
                keep: s.keep.map(Spanned::into_inner).unwrap_or_default(),
                of,
            },
            (None, None, None) => SegmentSource::Unknown,
        };
        (s.name, src)
    };
    file.segment.into_iter().map(source).collect()
}

/// The keys of one `ssvs` entry with their places in the text.
#[derive(Deserialize)]
struct EntrySpans {
    point: Option<Spanned<toml::Value>>,
    line: Option<Spanned<toml::Value>>,
    triangle: Option<Spanned<toml::Value>>,
    radius: Option<Spanned<toml::Value>>,
    mirror_copy: Option<Spanned<toml::Value>>,
}

#[derive(Deserialize)]
struct TableSegment {
    ssvs: Option<Vec<Spanned<EntrySpans>>>,
}

#[derive(Deserialize)]
struct TableFile {
    #[serde(default)]
    segment: Vec<TableSegment>,
}

/// The lines of a segment's `[[segment.ssvs]]` tables (byte range), if its entries are
/// written so.
fn table_lines(text: &str, entries: &[Spanned<EntrySpans>]) -> Option<std::ops::Range<usize>> {
    let first = entries.first()?.span();
    if !text[first.clone()].starts_with("[[") {
        return None;
    }
    let last = entries.last()?.get_ref();
    let keys = [&last.point, &last.line, &last.triangle, &last.radius];
    let keys = keys.into_iter().chain([&last.mirror_copy]).flatten();
    let end = keys.map(|k| k.span().end).max()?;
    Some(line_start(text, first.start)..line_end(text, end))
}
