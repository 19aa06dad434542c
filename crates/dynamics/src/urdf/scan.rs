//! One linear pass over URDF text before urdf-rs parses it. It reads the markup by the rules
//! of urdf-rs' XML reader (RustyXML: comments, CDATA, DOCTYPE, processing instructions,
//! quoted attribute values) and
//! - bounds the element nesting by [`MAX_DEPTH`]: urdf-rs and the XML readers under it recurse
//!   on the nesting, so a deeply nested file would overflow the stack;
//! - reports unterminated or mismatched markup at its line;
//! - finds the root element and the line of every `<link>` and `<joint>` child of it, by name,
//!   for the located errors of the conversion;
//! - removes comments and the elements the importer ignores (`<visual>`, `<collision>`,
//!   `<material>`), so that geometry urdf-rs cannot parse (e.g. iCub's `<texture/>` without a
//!   file name) does not stop a dynamics import. Removed text is replaced by its newlines,
//!   keeping line numbers.
//!
//! Like the XML reader, the pass ends with the root element; what follows it is not read.

use super::lines::LineIndex;
use super::markup::{markup, Markup};
use std::collections::HashMap;
use std::ops::Range;

/// Deepest element nesting accepted (the root element is level 1). URDF files nest about 6
/// levels (robot, link, visual, geometry, mesh); urdf-rs needs well under 1 KiB of stack per
/// level, so this stays far from any thread's stack size.
pub const MAX_DEPTH: usize = 100;

/// Elements dropped with their content.
const IGNORED: [&str; 3] = ["visual", "collision", "material"];

/// What the pass finds in a URDF text.
pub(super) struct Scanned {
    /// The text without comments and ignored elements (line structure preserved).
    pub stripped: String,
    /// Tag name and line of the root element (`None` if the text has no element).
    pub root: Option<(String, usize)>,
    /// Line of the first `<link>` child of the root with each name.
    pub links: HashMap<String, usize>,
    /// Line of the first `<joint>` child of the root with each name.
    pub joints: HashMap<String, usize>,
}

/// Why the pass rejected a text.
#[derive(Debug, PartialEq, Eq)]
pub(super) enum ScanError {
    /// Malformed markup: what is wrong, at a 1-based line.
    Malformed {
        /// Line of the markup at fault.
        line: usize,
        /// What is wrong with it.
        problem: String,
    },
    /// An element nested deeper than [`MAX_DEPTH`], at its line.
    TooDeep {
        /// Line of the element's start tag.
        line: usize,
    },
}

/// The state of the pass.
struct Scanner<'a> {
    xml: &'a str,
    lines: LineIndex,
    /// Open elements, outermost first: name and start offset (at most [`MAX_DEPTH`]).
    open: Vec<(&'a str, usize)>,
    /// Start offset and depth outside an ignored element being skipped.
    skip: Option<(usize, usize)>,
    /// Text up to `copied` has been written to `out`.
    out: String,
    copied: usize,
    found: Scanned,
}

/// Scans `xml` (see the module docs).
pub(super) fn scan(xml: &str) -> Result<Scanned, ScanError> {
    let mut s = Scanner {
        xml,
        lines: LineIndex::new(xml),
        open: Vec::new(),
        skip: None,
        out: String::with_capacity(xml.len()),
        copied: 0,
        found: Scanned {
            stripped: String::new(),
            root: None,
            links: HashMap::new(),
            joints: HashMap::new(),
        },
    };
    let mut pos = 0;
    while let Some(rel) = xml[pos..].find('<') {
        let start = pos + rel;
        let Some((item, end)) = markup(xml, start) else {
            return Err(s.malformed(start, "unterminated or malformed markup".into()));
        };
        match item {
            Markup::Comment => s.drop_range(start..end),
            Markup::Other => {}
            Markup::Start { name, attr_name } => s.start(start..end, name, attr_name, false)?,
            Markup::Empty { name, attr_name } => s.start(start..end, name, attr_name, true)?,
            Markup::End { name } => s.end(start..end, name)?,
        }
        pos = end;
        if s.open.is_empty() && s.found.root.is_some() {
            break;
        }
    }
    if let Some(&(name, at)) = s.open.last() {
        return Err(s.malformed(at, format!("<{name}> is not closed")));
    }
    s.out.push_str(&xml[s.copied..]);
    s.found.stripped = s.out;
    Ok(s.found)
}

impl<'a> Scanner<'a> {
    /// A [`ScanError::Malformed`] at byte `at`.
    fn malformed(&self, at: usize, problem: String) -> ScanError {
        ScanError::Malformed {
            line: self.lines.line_of(at),
            problem,
        }
    }

    /// Replaces `range` of the text by its newlines in the output.
    fn drop_range(&mut self, range: Range<usize>) {
        if self.skip.is_some() {
            return;
        }
        self.out.push_str(&self.xml[self.copied..range.start]);
        let dropped = &self.xml[range.clone()];
        self.out
            .extend(dropped.bytes().filter(|&b| b == b'\n').map(char::from));
        self.copied = range.end;
    }

    /// A start tag (`empty` for `<tag/>`) with the value of its `name` attribute.
    fn start(
        &mut self,
        tag: Range<usize>,
        name: &'a str,
        attr_name: Option<&'a str>,
        empty: bool,
    ) -> Result<(), ScanError> {
        self.open.push((name, tag.start));
        let depth = self.open.len();
        if depth > MAX_DEPTH {
            return Err(ScanError::TooDeep {
                line: self.lines.line_of(tag.start),
            });
        }
        let line = || self.lines.line_of(tag.start);
        match (depth, name) {
            (1, _) => self.found.root = Some((name.to_string(), line())),
            (2, "link" | "joint") if self.skip.is_none() => {
                if let Some(value) = attr_name {
                    let line = line();
                    let map = match name {
                        "link" => &mut self.found.links,
                        _ => &mut self.found.joints,
                    };
                    map.entry(value.to_string()).or_insert(line);
                }
            }
            _ => {}
        }
        if self.skip.is_none() && IGNORED.contains(&name) {
            self.skip = Some((tag.start, depth - 1));
        }
        if empty {
            self.end_element(tag.end);
        }
        Ok(())
    }

    /// An end tag `</name>`, which must close the innermost open element.
    fn end(&mut self, tag: Range<usize>, name: &str) -> Result<(), ScanError> {
        match self.open.last() {
            Some(&(open, _)) if open == name => {
                self.end_element(tag.end);
                Ok(())
            }
            Some(&(open, at)) => {
                let line = self.lines.line_of(at);
                let problem = format!("</{name}> does not close <{open}> (line {line})");
                Err(self.malformed(tag.start, problem))
            }
            None => Err(self.malformed(tag.start, format!("</{name}> closes no element"))),
        }
    }

    /// Closes the innermost element, whose markup ends at `end`; drops it if it is ignored.
    fn end_element(&mut self, end: usize) {
        self.open.pop();
        if let Some((start, depth)) = self.skip {
            if depth == self.open.len() {
                self.skip = None;
                self.drop_range(start..end);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drops_ignored_elements_and_keeps_lines() {
        let xml =
            "<robot>\n<link name=\"a\">\n<visual><material name=\"m\">\n<texture/></material>\
                   </visual>\n<collision/><!-- <joint>\n --><materials/></link>\n</robot>";
        let out = scan(xml).unwrap().stripped;
        assert_eq!(
            out,
            "<robot>\n<link name=\"a\">\n\n\n\n<materials/></link>\n</robot>"
        );
    }

    #[test]
    fn finds_links_and_joints_of_the_root_only() {
        let xml = "<robot name='r'>\n<!-- <joint name=\"a\" type=\"fixed\"> -->\n<link name='a'/>\n\
                   <transmission><joint name=\"a\"/></transmission>\n<joint name=\"a\" type=\"revolute\">\n\
                   </joint></robot>";
        let s = scan(xml).unwrap();
        assert_eq!(s.root, Some(("robot".to_string(), 1)));
        assert_eq!((s.links.get("a"), s.joints.get("a")), (Some(&3), Some(&5)));
        assert_eq!((s.joints.get("b"), s.links.get("ab")), (None, None));
    }

    #[test]
    fn malformed_and_deep_markup_is_located() {
        let err = |xml: &str| scan(xml).err().unwrap();
        let m = |line, problem: &str| ScanError::Malformed {
            line,
            problem: problem.into(),
        };
        assert_eq!(
            err("<robot>\n<a>\n</b>"),
            m(3, "</b> does not close <a> (line 2)")
        );
        assert_eq!(err("<robot>\n<a>"), m(2, "<a> is not closed"));
        assert_eq!(
            err("<robot>\n<!-- x"),
            m(2, "unterminated or malformed markup")
        );
        let deep = format!(
            "<r>\n{}{}</r>",
            "<a>".repeat(MAX_DEPTH),
            "</a>".repeat(MAX_DEPTH)
        );
        assert_eq!(err(&deep), ScanError::TooDeep { line: 2 });
        let ok = format!(
            "<r>{}{}</r>",
            "<a>".repeat(MAX_DEPTH - 1),
            "</a>".repeat(MAX_DEPTH - 1)
        );
        assert!(scan(&ok).is_ok());
    }
}
