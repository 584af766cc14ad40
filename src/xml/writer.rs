//! Element tree back to XML text (the model `mj_saveLastXML` writes).

use super::tree::Element;

fn escape(v: &str) -> String {
    let mut s = String::with_capacity(v.len());
    for ch in v.chars() {
        match ch {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            _ => s.push(ch),
        }
    }
    s
}

fn write_element(el: &Element, depth: usize, out: &mut String) {
    let indent = "  ".repeat(depth);
    out.push_str(&indent);
    out.push('<');
    out.push_str(&el.name);
    for (k, v) in &el.attrs {
        out.push_str(&format!(" {k}=\"{}\"", escape(v)));
    }
    if el.children.is_empty() {
        out.push_str("/>\n");
        return;
    }
    out.push_str(">\n");
    for c in &el.children {
        write_element(c, depth + 1, out);
    }
    out.push_str(&format!("{indent}</{}>\n", el.name));
}

/// The document text of `root`, two-space indented.
pub fn to_text(root: &Element) -> String {
    let mut out = String::new();
    write_element(root, 0, &mut out);
    out
}
