//! How each segment is written in the model file, so that the page can edit a segment's
//! `ssvs = [...]` entries and splice the new array into the file text, leaving every other
//! line (comments, mirrored segments, versions, pairs) as it was.

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
    },
    /// The mirror image of another segment.
    MirrorOf {
        /// The mirrored segment.
        of: String,
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

#[derive(Deserialize)]
struct SourceSegment {
    name: String,
    ssvs: Option<Spanned<Vec<EntryJson>>>,
    mirror_of: Option<String>,
    version_of: Option<String>,
    keep: Option<Spanned<Vec<i64>>>,
}

/// Every segment's name and source, in file order (empty if the text does not parse).
pub fn segment_sources(text: &str) -> Vec<(String, SegmentSource)> {
    let Ok(file) = toml::from_str::<SourceFile>(text) else {
        return Vec::new();
    };
    let source = |s: SourceSegment| {
        let src = match (s.ssvs, s.mirror_of, s.version_of) {
            (Some(ssvs), _, _) => {
                let span = utf16_span(text, ssvs.span());
                SegmentSource::Ssvs {
                    entries: ssvs.into_inner(),
                    span,
                }
            }
            (None, Some(of), _) => SegmentSource::MirrorOf { of },
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
