//! XML text to an element tree that remembers the line of every element.

use quick_xml::events::{BytesStart, Event};
use quick_xml::Reader;

/// One XML element: name, attributes in document order, child elements, line (1-based).
#[derive(Debug, Clone)]
pub struct Element {
    pub name: String,
    pub attrs: Vec<(String, String)>,
    pub children: Vec<Element>,
    pub line: i32,
}

impl Element {
    /// Value of attribute `key`, if present.
    pub fn attr(&self, key: &str) -> Option<&str> {
        self.attrs
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

/// Line numbers from byte offsets.
struct Lines(Vec<usize>);

impl Lines {
    fn new(text: &str) -> Self {
        Lines(
            text.bytes()
                .enumerate()
                .filter(|(_, b)| *b == b'\n')
                .map(|(i, _)| i)
                .collect(),
        )
    }
    fn line(&self, offset: usize) -> i32 {
        (self.0.partition_point(|&nl| nl < offset) + 1) as i32
    }
}

fn element(e: &BytesStart, line: i32) -> Result<Element, String> {
    let name = String::from_utf8_lossy(e.name().as_ref()).into_owned();
    let mut attrs: Vec<(String, String)> = Vec::new();
    // malformed or repeated attributes are reported as tinyxml2 reports them
    let bad = || {
        format!(
            "XML parse error 7:\nError=XML_ERROR_PARSING_ATTRIBUTE ErrorID=7 (0x7) \
             Line number={line}: XMLElement name={name}\n"
        )
    };
    for a in e.attributes().with_checks(true) {
        let a = a.map_err(|_| bad())?;
        let key = String::from_utf8_lossy(a.key.as_ref()).into_owned();
        let value = a.unescape_value().map_err(|_| bad())?;
        attrs.push((key, value.into_owned()));
    }
    Ok(Element {
        name,
        attrs,
        children: Vec::new(),
        line,
    })
}

/// Blanks the nodes tinyxml2 parses as "unknown" and skips: `<!` not opening a comment or
/// CDATA (DOCTYPE included) up to the next `>`. Newlines stay, so line numbers hold.
fn blank_unknown_nodes(text: &str) -> std::borrow::Cow<'_, str> {
    let b = text.as_bytes();
    let mut out: Option<Vec<u8>> = None;
    let find = |from: usize, pat: &[u8]| {
        b[from.min(b.len())..]
            .windows(pat.len())
            .position(|w| w == pat)
            .map(|p| from + p + pat.len())
    };
    let mut i = 0;
    while i < b.len() {
        if b[i] != b'<' {
            i += 1;
            continue;
        }
        let rest = &b[i..];
        if rest.starts_with(b"<!--") {
            i = find(i + 4, b"-->").unwrap_or(b.len());
        } else if rest.starts_with(b"<![CDATA[") {
            i = find(i + 9, b"]]>").unwrap_or(b.len());
        } else if rest.starts_with(b"<!") {
            let end = find(i, b">").unwrap_or(b.len());
            let o = out.get_or_insert_with(|| b.to_vec());
            for c in &mut o[i..end] {
                if *c != b'\n' {
                    *c = b' ';
                }
            }
            i = end;
        } else {
            // a tag: skip to its end, over quoted attribute values
            let mut quote = 0u8;
            i += 1;
            while i < b.len() && (quote != 0 || b[i] != b'>') {
                if quote == 0 && (b[i] == b'"' || b[i] == b'\'') {
                    quote = b[i];
                } else if b[i] == quote {
                    quote = 0;
                }
                i += 1;
            }
        }
    }
    match out {
        // only whole ASCII-delimited runs were replaced by ASCII: still UTF-8
        Some(o) => std::borrow::Cow::Owned(String::from_utf8(o).unwrap_or_default()),
        None => std::borrow::Cow::Borrowed(text),
    }
}

/// Parses a whole document; returns its root element or a message naming the problem and line.
pub fn parse(text: &str) -> Result<Element, String> {
    // tinyxml2 parses a C string: a NUL byte ends the document
    let text = text.split('\0').next().unwrap_or("");
    let text = &*blank_unknown_nodes(text);
    let lines = Lines::new(text);
    let mut reader = Reader::from_str(text);
    reader.config_mut().trim_text(true);
    let mut stack: Vec<Element> = Vec::new();
    let mut root: Option<Element> = None;
    loop {
        let before = reader.buffer_position() as usize;
        let ev = match reader.read_event() {
            Ok(ev) => ev,
            Err(quick_xml::Error::IllFormed(
                quick_xml::errors::IllFormedError::MismatchedEndTag { .. },
            )) => {
                let (name, line) = stack.last().map_or(("", 0), |e| (e.name.as_str(), e.line));
                return Err(format!(
                    "XML parse error 14:\nError=XML_ERROR_MISMATCHED_ELEMENT ErrorID=14 (0xe) \
                     Line number={line}: XMLElement name={name}\n"
                ));
            }
            // a stray end tag after the root is ignored, as tinyxml2 does
            Err(quick_xml::Error::IllFormed(
                quick_xml::errors::IllFormedError::UnmatchedEndTag(_),
            )) if stack.is_empty() && root.is_some() => {
                continue;
            }
            Err(err) => {
                let at = lines.line(reader.error_position() as usize);
                return Err(format!("XML parse error: {err}\nLine number={at}\n"));
            }
        };
        // the tag starts at the first '<' of the bytes this event consumed
        let tag_line = || {
            lines.line(
                text.as_bytes()[before.min(text.len())..]
                    .iter()
                    .position(|&b| b == b'<')
                    .map_or(before, |p| before + p),
            )
        };
        match ev {
            // later top-level elements are parsed and dropped: tinyxml2's root is the first
            Event::Start(e) => stack.push(element(&e, tag_line())?),
            Event::Empty(e) => {
                let el = element(&e, tag_line())?;
                match stack.last_mut() {
                    Some(parent) => parent.children.push(el),
                    None => {
                        root.get_or_insert(el);
                    }
                }
            }
            Event::End(_) => {
                let el = stack.pop().ok_or("XML parse error: unmatched end tag")?;
                match stack.last_mut() {
                    Some(parent) => parent.children.push(el),
                    None => {
                        root.get_or_insert(el);
                    }
                }
            }
            Event::Eof => break,
            // text outside elements is skipped, as tinyxml2 does, unless nothing follows it:
            // tinyxml2 then reports text without its closing '<'
            Event::Text(t)
                if stack.is_empty()
                    && reader.buffer_position() as usize >= text.len()
                    && !t.iter().all(|b| b.is_ascii_whitespace()) =>
            {
                let start = before + text[before..].len() - text[before..].trim_start().len();
                return Err(format!(
                    "XML parse error 8:\nError=XML_ERROR_PARSING_TEXT ErrorID=8 (0x8) Line number={}\n",
                    lines.line(start)
                ));
            }
            _ => {}
        }
    }
    // an unclosed element after the first root is ignored, as tinyxml2 does
    // tinyxml2 names the innermost element left open
    if let Some(open) = stack.last().filter(|_| root.is_none()) {
        return Err(format!(
            "XML parse error 15:\nError=XML_ERROR_PARSING ErrorID=15 (0xf) Line number={}\n",
            open.line
        ));
    }
    root.ok_or_else(|| {
        "XML parse error 13:\nError=XML_ERROR_EMPTY_DOCUMENT ErrorID=13 (0xd) Line number=0\n"
            .to_string()
    })
}
