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
        attrs.push((key, attribute_value(&a.value)));
    }
    Ok(Element {
        name,
        attrs,
        children: Vec::new(),
        line,
    })
}

/// An attribute's value as tinyxml2 gives it: newlines normalized (CR LF, LF CR and CR become
/// LF), the five named entities and numeric character references replaced, in place; an `&`
/// starting neither is kept (as the byte left where it is written, as tinyxml2 leaves it); the
/// value ends at a NUL, as the C string MuJoCo reads.
fn attribute_value(raw: &[u8]) -> String {
    const NAMED: [(&[u8], u8); 5] = [
        (b"quot", b'"'),
        (b"amp", b'&'),
        (b"apos", b'\''),
        (b"lt", b'<'),
        (b"gt", b'>'),
    ];
    let mut b = raw.to_vec();
    let at = |b: &[u8], i: usize| b.get(i).copied().unwrap_or(0);
    let (mut p, mut q) = (0, 0);
    while p < raw.len() {
        match b[p] {
            c @ (b'\r' | b'\n') => {
                let pair = if c == b'\r' { b'\n' } else { b'\r' };
                p += if at(&b, p + 1) == pair { 2 } else { 1 };
                b[q] = b'\n';
                q += 1;
            }
            b'&' if at(&b, p + 1) == b'#' => match character_ref(&b[p..]) {
                Some((utf8, used)) => {
                    b[q..q + utf8.len()].copy_from_slice(&utf8);
                    (p, q) = (p + used, q + utf8.len());
                }
                None => {
                    b[q] = b'&';
                    (p, q) = (p + 1, q + 1);
                }
            },
            b'&' => match NAMED.iter().find(|(name, _)| {
                b[p + 1..].starts_with(name) && at(&b, p + 1 + name.len()) == b';'
            }) {
                Some(&(name, c)) => {
                    b[q] = c;
                    (p, q) = (p + name.len() + 2, q + 1);
                }
                None => (p, q) = (p + 1, q + 1),
            },
            c => {
                b[q] = c;
                (p, q) = (p + 1, q + 1);
            }
        }
    }
    b.truncate(q);
    if let Some(nul) = b.iter().position(|&c| c == 0) {
        b.truncate(nul);
    }
    String::from_utf8_lossy(&b).into_owned()
}

/// A numeric character reference at the start of `s` ("&#123;" or "&#x7b;"): its UTF-8 bytes
/// and the bytes it took, computed as tinyxml2 does (the digits read back from the value's next
/// `;` to the nearest `#`, or `x`, in 32-bit steps; no bytes for a code above 0x1FFFFF; "&#"
/// ending the value takes the `&` alone); None where tinyxml2 keeps the `&` (nothing after
/// "&#x", no `;`, a character that is not a digit).
fn character_ref(s: &[u8]) -> Option<(Vec<u8>, usize)> {
    if s.len() <= 2 {
        return Some((Vec::new(), 1));
    }
    let hex = s[2] == b'x';
    let (radix, stop) = if hex { (16u32, b'x') } else { (10, b'#') };
    if hex && s.len() <= 3 {
        return None;
    }
    let from = if hex { 3 } else { 2 };
    let semi = from + s[from..].iter().position(|&c| c == b';')?;
    let digits = 1 + s[..semi].iter().rposition(|&c| c == stop)?;
    let (mut code, mut mult) = (0u64, 1u32);
    for &c in s[digits..semi].iter().rev() {
        let digit = (c as char).to_digit(radix)?;
        code = code.wrapping_add(mult.wrapping_mul(digit) as u64);
        mult = mult.wrapping_mul(radix);
    }
    let n = match code {
        0..=0x7f => 1,
        0x80..=0x7ff => 2,
        0x800..=0xffff => 3,
        0x1_0000..=0x1f_ffff => 4,
        _ => 0,
    };
    let mut out = vec![0u8; n];
    let mut v = code;
    for i in (1..n).rev() {
        out[i] = ((v | 0x80) & 0xbf) as u8;
        v >>= 6;
    }
    if n > 0 {
        out[0] = (v | [0, 0, 0xc0, 0xe0, 0xf0][n]) as u8;
    }
    Some((out, semi + 1))
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
