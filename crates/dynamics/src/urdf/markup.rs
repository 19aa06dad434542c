//! One item of XML markup (a tag, comment, CDATA section, DOCTYPE or processing instruction)
//! read by the rules of urdf-rs' XML reader (RustyXML), so that [`scan`](super::scan) sees
//! the elements that reader will build.

/// A markup item starting at a `<`.
#[derive(Debug, PartialEq, Eq)]
pub(super) enum Markup<'a> {
    /// `<!-- .. -->`.
    Comment,
    /// `<![CDATA[ .. ]]>`, `<!DOCTYPE .. >` or `<? .. ?>`: no element.
    Other,
    /// `<name ..>` with the value of its `name` attribute (as written).
    Start {
        /// Tag name.
        name: &'a str,
        /// Value of the `name` attribute.
        attr_name: Option<&'a str>,
    },
    /// `<name ../>`.
    Empty {
        /// Tag name.
        name: &'a str,
        /// Value of the `name` attribute.
        attr_name: Option<&'a str>,
    },
    /// `</name>`.
    End {
        /// Tag name.
        name: &'a str,
    },
}

/// XML white space as the reader knows it.
fn is_space(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | b'\n')
}

/// The item starting at the `<` at byte `start` of `xml` and the offset just after it; `None`
/// if it is not terminated or malformed (the XML reader fails there).
pub(super) fn markup(xml: &str, start: usize) -> Option<(Markup<'_>, usize)> {
    let rest = &xml[start..];
    let after =
        |from: usize, pat: &str| rest[from..].find(pat).map(|i| start + from + i + pat.len());
    if rest.starts_with("<!--") {
        // The first `--` must end the comment.
        let dashes = after(4, "--")?;
        return (xml.as_bytes().get(dashes) == Some(&b'>'))
            .then_some((Markup::Comment, dashes + 1));
    }
    if rest.starts_with("<![CDATA[") {
        return Some((Markup::Other, after(9, "]]>")?));
    }
    if rest.starts_with("<!DOCTYPE") && rest.as_bytes().get(9).copied().is_some_and(is_space) {
        return Some((Markup::Other, after(10, ">")?));
    }
    if rest.starts_with("<!") {
        return None;
    }
    if rest.starts_with("<?") {
        // The reader ends a processing instruction at the first `>` after a `?`.
        let question = after(2, "?")? - start;
        return Some((Markup::Other, after(question, ">")?));
    }
    if rest.starts_with("</") {
        return end_tag(xml, start);
    }
    start_tag(xml, start)
}

/// `</name>` (white space allowed before the `>`).
fn end_tag(xml: &str, start: usize) -> Option<(Markup<'_>, usize)> {
    let b = xml.as_bytes();
    let name_end = start
        + 2
        + b[start + 2..]
            .iter()
            .position(|&c| is_space(c) || c == b'>')?;
    let close = name_end + b[name_end..].iter().position(|&c| !is_space(c))?;
    let name = &xml[start + 2..name_end];
    (b[close] == b'>').then_some((Markup::End { name }, close + 1))
}

/// Where a start tag's reading is.
#[derive(Clone, Copy)]
enum State {
    /// In the tag name.
    Name,
    /// Between attributes.
    Tag,
    /// In an attribute name starting at the first offset; the second is its end once white
    /// space followed it.
    AttrName(usize, Option<usize>),
    /// After `=`, before the quote; the attribute is `name`.
    Delimiter(bool),
    /// In a value quoted by the byte, starting at the offset; the attribute is `name`.
    Value(u8, usize, bool),
}

/// `<name attr="value" ..>` or `<name ../>`. As in the reader, the first byte after `<`
/// always belongs to the name, and quotes start values only after `=`.
fn start_tag(xml: &str, start: usize) -> Option<(Markup<'_>, usize)> {
    let b = xml.as_bytes();
    let (mut state, mut name_end, mut attr_name) = (State::Name, None, None);
    let mut i = start + 2;
    while i < b.len() {
        let c = b[i];
        state = match (state, c) {
            (State::Name | State::Tag, b'/' | b'>') => {
                let name = &xml[start + 1..name_end.unwrap_or(i)];
                if c == b'>' {
                    return Some((Markup::Start { name, attr_name }, i + 1));
                }
                return (b.get(i + 1) == Some(&b'>'))
                    .then_some((Markup::Empty { name, attr_name }, i + 2));
            }
            (State::Name, c) if is_space(c) => {
                name_end = Some(i);
                State::Tag
            }
            (State::Name, _) => State::Name,
            (State::Tag, c) if is_space(c) => State::Tag,
            (State::Tag, _) => State::AttrName(i, None),
            (State::AttrName(from, end), b'=') => {
                State::Delimiter(&xml[from..end.unwrap_or(i)] == "name")
            }
            (State::AttrName(from, end), c) if is_space(c) => {
                State::AttrName(from, Some(end.unwrap_or(i)))
            }
            (State::AttrName(_, Some(_)), _) => return None,
            (State::AttrName(..), _) => state,
            (State::Delimiter(is_name), b'"' | b'\'') => State::Value(c, i + 1, is_name),
            (State::Delimiter(_), c) if is_space(c) => state,
            (State::Delimiter(_), _) => return None,
            (State::Value(q, from, is_name), c) if c == q => {
                if is_name {
                    attr_name = Some(&xml[from..i]);
                }
                State::Tag
            }
            (State::Value(..), _) => state,
        };
        i += 1;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(xml: &str) -> Option<(Markup<'_>, usize)> {
        markup(xml, 0)
    }

    #[test]
    fn reads_tags_comments_and_the_rest() {
        let start = |name, attr_name| Markup::Start { name, attr_name };
        assert_eq!(one("<a>x"), Some((start("a", None), 3)));
        assert_eq!(
            one("<link a='>' name = \"l<1>\" >"),
            Some((start("link", Some("l<1>")), 27))
        );
        assert_eq!(
            one("<a\nname='b'/>"),
            Some((
                Markup::Empty {
                    name: "a",
                    attr_name: Some("b")
                },
                13
            ))
        );
        assert_eq!(one("</a >"), Some((Markup::End { name: "a" }, 5)));
        assert_eq!(one("<!-- <a> - -->"), Some((Markup::Comment, 14)));
        assert_eq!(one("<![CDATA[<a>]]>"), Some((Markup::Other, 15)));
        assert_eq!(one("<!DOCTYPE robot>"), Some((Markup::Other, 16)));
        assert_eq!(one("<?xml version='1.0'?>"), Some((Markup::Other, 21)));
        for bad in [
            "<!-- a -- b -->",
            "<!x>",
            "<a b>",
            "<a b c='d'>",
            "<a b=c>",
            "<a/ >",
            "<a",
        ] {
            assert_eq!(one(bad), None, "{bad}");
        }
    }
}
