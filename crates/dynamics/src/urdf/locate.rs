//! Cheap line lookup of URDF elements in the raw XML text (for error messages).

/// 1-based line of the first `<tag ... name="name" ...>` start tag outside comments.
/// For `joint`, start tags without a `type` attribute (e.g. inside `<transmission>`) are skipped.
pub fn element_line(xml: &str, tag: &str, name: &str) -> Option<usize> {
    let open = format!("<{tag}");
    let mut pos = 0;
    while let Some(rel) = xml[pos..].find('<') {
        let start = pos + rel;
        let rest = &xml[start..];
        if rest.starts_with("<!--") {
            pos = start + rest.find("-->").map_or(rest.len(), |e| e + 3);
            continue;
        }
        let end = start + rest.find('>').unwrap_or(rest.len());
        let head = &xml[start..end];
        if is_start_tag(head, &open)
            && has_name(head, name)
            && (tag != "joint" || has_attr(head, "type"))
        {
            return Some(1 + xml[..start].matches('\n').count());
        }
        pos = start + 1;
    }
    None
}

/// True if `head` (text from `<` up to `>`) opens the element `open` (`<tag`).
fn is_start_tag(head: &str, open: &str) -> bool {
    head.strip_prefix(open)
        .is_some_and(|r| r.starts_with(|c: char| c.is_whitespace()))
}

/// True if the tag text carries `name="name"` (either quote style).
fn has_name(head: &str, name: &str) -> bool {
    attr_value(head, "name").is_some_and(|v| v == name)
}

/// True if the tag text has attribute `attr`.
fn has_attr(head: &str, attr: &str) -> bool {
    attr_value(head, attr).is_some()
}

/// Value of attribute `attr` in a start tag's text.
fn attr_value<'a>(head: &'a str, attr: &str) -> Option<&'a str> {
    let mut search = 0;
    while let Some(rel) = head[search..].find(attr) {
        let at = search + rel;
        search = at + attr.len();
        let before_ok = head[..at].ends_with(|c: char| c.is_whitespace());
        let after = head[search..].trim_start();
        if !before_ok || !after.starts_with('=') {
            continue;
        }
        let value = after[1..].trim_start();
        let quote = value.chars().next()?;
        if quote != '"' && quote != '\'' {
            return None;
        }
        let body = &value[1..];
        return body.find(quote).map(|e| &body[..e]);
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_lines_and_skips_comments_and_transmissions() {
        let xml = "<robot>\n<!-- <joint name=\"a\" type=\"fixed\"> -->\n<link name='a'/>\n\
                   <transmission><joint name=\"a\"/></transmission>\n<joint name=\"a\" type=\"revolute\">\n";
        assert_eq!(element_line(xml, "link", "a"), Some(3));
        assert_eq!(element_line(xml, "joint", "a"), Some(5));
        assert_eq!(element_line(xml, "joint", "b"), None);
        assert_eq!(element_line(xml, "link", "ab"), None);
    }
}
