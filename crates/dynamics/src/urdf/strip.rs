//! Removes the elements the importer ignores (`<visual>`, `<collision>`, `<material>`) and
//! comments from URDF text before parsing, so that geometry urdf-rs cannot parse (e.g. iCub's
//! `<texture/>` without a file name) does not stop a dynamics import. Removed text is replaced
//! by its newlines, keeping line numbers.

/// Elements dropped with their content.
const IGNORED: [&str; 3] = ["visual", "collision", "material"];

/// The URDF text without comments and ignored elements (line structure preserved).
pub fn strip_ignored(xml: &str) -> String {
    let mut out = String::with_capacity(xml.len());
    let mut pos = 0;
    while let Some(rel) = xml[pos..].find('<') {
        let start = pos + rel;
        out.push_str(&xml[pos..start]);
        let end = ignored_end(xml, start).unwrap_or(start);
        if end > start {
            out.extend(xml[start..end].chars().filter(|&c| c == '\n'));
            pos = end;
        } else {
            out.push('<');
            pos = start + 1;
        }
    }
    out.push_str(&xml[pos..]);
    out
}

/// End (exclusive) of a comment or ignored element starting at `start`, if it is one.
fn ignored_end(xml: &str, start: usize) -> Option<usize> {
    let rest = &xml[start..];
    if rest.starts_with("<!--") {
        return Some(start + rest.find("-->").map_or(rest.len(), |e| e + 3));
    }
    let tag = IGNORED.iter().find(|t| {
        rest[1..].starts_with(*t)
            && rest[1 + t.len()..].starts_with(|c: char| c.is_whitespace() || c == '>' || c == '/')
    })?;
    let head_end = rest.find('>')?;
    if rest[..head_end].ends_with('/') {
        return Some(start + head_end + 1);
    }
    let close = format!("</{tag}>");
    let body_end = rest.find(&close)?;
    Some(start + body_end + close.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drops_ignored_elements_and_keeps_lines() {
        let xml =
            "<robot>\n<link name=\"a\">\n<visual><material name=\"m\">\n<texture/></material>\
                   </visual>\n<collision/><!-- <joint>\n --><materials/></link>\n</robot>";
        let out = strip_ignored(xml);
        assert_eq!(
            out,
            "<robot>\n<link name=\"a\">\n\n\n\n<materials/></link>\n</robot>"
        );
        assert_eq!(out.matches('\n').count(), xml.matches('\n').count());
    }
}
