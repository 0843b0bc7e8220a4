//! A scene file cut at its top-level table headers by TOML's own lexer, without building
//! the document: a parsed TOML document costs some fifty bytes of memory for every byte of
//! text (its tokens, events and tables), so a file of a million objects would need gigabytes
//! at once. Each `[[objects]]` section (with the sub-tables it opens, `[objects.material]`)
//! is parsed on its own, one at a time; the rest of the file as one small document, its
//! offsets mapped back to the file's.

use std::ops::Range;
use toml_parser::Source;
use toml_parser::lexer::TokenKind;

/// The file's `[[objects]]` sections and everything else.
pub(crate) struct Sections {
    /// The file without its object sections, the rest joined end to end.
    pub rest: String,
    /// Where each piece of `rest` starts, in `rest` and in the file.
    pieces: Vec<(usize, usize)>,
    /// Where each `[[objects]]` section lies in the file, in order.
    pub objects: Vec<Range<usize>>,
    /// Where the outermost bracket or brace left open at the end of the file opened, if one
    /// was (everything after it is inside a value, so no header is seen there).
    pub unclosed: Option<usize>,
    /// Where the file's first table header starts (its end, if it has none): the root
    /// table's key-values lie before it.
    pub root_end: usize,
}

/// A header this reader cannot place: where it is and why.
pub(crate) struct Misplaced {
    /// Its offset in the file.
    pub at: usize,
    /// What to write instead.
    pub message: String,
}

impl Sections {
    /// The offset in the file of the byte at `offset` in [`Sections::rest`].
    pub(crate) fn file_offset(&self, offset: usize) -> usize {
        let k = self.pieces.partition_point(|&(at, _)| at <= offset).saturating_sub(1);
        self.pieces.get(k).map_or(offset, |&(at, file)| file + (offset - at))
    }
}

/// A top-level table header: where it starts, whether it opens an array element
/// (`[[…]]`), whether its first key is `objects`, and whether that is its only key (a new
/// object, as against `[objects.material]` or `[[objects.circles]]` inside the last one).
struct Header {
    start: usize,
    array: bool,
    objects: bool,
    only: bool,
}

/// The sections of `text` ([`Sections`]); `Err` for a table under `objects` written away
/// from its object (after another table, or before any `[[objects]]`) (TOML allows it; this reader keeps each object's
/// tables together), and for an `include` after the first table header (TOML reads it as
/// a field of that table).
pub(crate) fn split(text: &str) -> Result<Sections, Misplaced> {
    let mut objects: Vec<Range<usize>> = Vec::new();
    let mut open: Option<usize> = None;
    let Scan { headers, unclosed, include } = scan(text);
    if let Some(at) = include {
        let message = "`include` comes before the first table (`[camera]`, `[render]`, `[[lights]]`, `[[objects]]`, `[materials.NAME]`, …): after a table's header it is read as a field of that table; move it to the top of the file".into();
        return Err(Misplaced { at, message });
    }
    let root_end = headers.first().map_or(text.len(), |h| h.start);
    for header in headers {
        // (A lone `[objects]` before any object is left for the reader's own message.)
        let away = !header.only || !objects.is_empty();
        if header.objects && !(header.array && header.only) && open.is_none() && away {
            let message = "a table under `objects` away from its object: write it right after the `[[objects]]` table it belongs to (each object's tables are read together; an included file's cannot add to another file's object)".into();
            return Err(Misplaced { at: header.start, message });
        }
        // An `[[objects]]` header opens a section; a header under `objects` stays in it;
        // any other header closes it.
        match (header.objects, header.array && header.objects && header.only, open) {
            (true, true, Some(start)) => {
                objects.push(start..header.start);
                open = Some(header.start);
            }
            (true, true, None) => open = Some(header.start),
            (true, false, _) => {}
            (false, _, Some(start)) => {
                objects.push(start..header.start);
                open = None;
            }
            (false, _, None) => {}
        }
    }
    if let Some(start) = open {
        objects.push(start..text.len());
    }
    let (mut rest, mut pieces, mut from) = (String::new(), Vec::new(), 0);
    for range in objects.iter().chain([&(text.len()..text.len())]) {
        pieces.push((rest.len(), from));
        rest.push_str(&text[from..range.start]);
        from = range.end;
    }
    Ok(Sections { rest, pieces, objects, unclosed, root_end })
}

/// How many tokens of `text` are not whitespace, newlines or comments: what parsing it as
/// one document costs memory for (comments and blank lines next to nothing).
pub(crate) fn significant_tokens(text: &str) -> usize {
    let trivia = |k| matches!(k, TokenKind::Whitespace | TokenKind::Newline | TokenKind::Comment);
    Source::new(text).lex().filter(|t| !trivia(t.kind())).count()
}

/// What [`scan`] finds in a file.
struct Scan {
    /// The top-level table headers, in order.
    headers: Vec<Header>,
    /// Where the outermost bracket or brace left open at the end opened, if one was.
    unclosed: Option<usize>,
    /// Where the first key `include` after a table header starts, if one does.
    include: Option<usize>,
}

/// The top-level table headers of `text`, in order: a `[` at the start of a line outside
/// any value (brackets and braces of values counted, strings and comments whole tokens);
/// where the outermost bracket left open at the end opened; and the first `include = …`
/// after a header.
fn scan(text: &str) -> Scan {
    let source = Source::new(text);
    let mut out: Vec<Header> = Vec::new();
    let mut include = None;
    let (mut depth, mut line_start, mut opened) = (0usize, true, 0usize);
    let mut tokens = source.lex().peekable();
    while let Some(token) = tokens.next() {
        match token.kind() {
            TokenKind::Whitespace | TokenKind::Comment => {}
            TokenKind::Newline => line_start = depth == 0,
            TokenKind::LeftSquareBracket if depth == 0 && line_start => {
                let start = token.span().start();
                let array = tokens.peek().is_some_and(|t| t.kind() == TokenKind::LeftSquareBracket);
                if array {
                    tokens.next();
                }
                // The first key: a bare word or a quoted one.
                let first = tokens.by_ref().find(|t| t.kind() != TokenKind::Whitespace);
                let objects = first.is_some_and(|t| {
                    let raw = text.get(t.span().start()..t.span().end()).unwrap_or("");
                    raw.trim_matches(['"', '\'']) == "objects"
                        && matches!(t.kind(), TokenKind::Atom | TokenKind::BasicString | TokenKind::LiteralString)
                });
                // The rest of the header, to its closing bracket(s): a dot means more keys.
                let mut only = true;
                for t in tokens.by_ref() {
                    match t.kind() {
                        TokenKind::RightSquareBracket | TokenKind::Newline => break,
                        TokenKind::Whitespace => {}
                        _ => only = false,
                    }
                }
                out.push(Header { start, array, objects, only });
                line_start = false;
            }
            TokenKind::Atom | TokenKind::BasicString | TokenKind::LiteralString
                if depth == 0 && line_start && !out.is_empty() && include.is_none() =>
            {
                let (start, end) = (token.span().start(), token.span().end());
                let key = text.get(start..end).unwrap_or("").trim_matches(['"', '\'']);
                let assigned =
                    text.get(end..).is_some_and(|after| after.trim_start_matches([' ', '\t']).starts_with('='));
                if key == "include" && assigned {
                    include = Some(start);
                }
                line_start = false;
            }
            TokenKind::LeftSquareBracket | TokenKind::LeftCurlyBracket => {
                if depth == 0 {
                    opened = token.span().start();
                }
                depth += 1;
                line_start = false;
            }
            TokenKind::RightSquareBracket | TokenKind::RightCurlyBracket => {
                depth = depth.saturating_sub(1);
                line_start = false;
            }
            _ => line_start = false,
        }
    }
    Scan { headers: out, unclosed: (depth > 0).then_some(opened), include }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn object_sections_are_cut_at_their_headers_and_nowhere_else() {
        let text = "[camera]\nwidth = 8 # [[objects]] in a comment\n\
                    [[objects]]\nname = \"[[objects]]\"\npoints = [\n[0.0, 0.0, 0.0],\n[1.0, 0.0, 0.0]]\n\
                    [objects.material]\ncolour = [1.0, 0.0, 0.0]\n[[objects.circles]]\nradius = 1.0\n\
                    [[lights]]\nposition = [0.0, 0.0, 9.0]\n\
                    [[ 'objects' ]]\ntype = \"sphere\"\n";
        let s = split(text).ok().unwrap();
        assert_eq!(s.objects.len(), 2);
        let first = &text[s.objects[0].clone()];
        assert!(first.starts_with("[[objects]]") && first.contains("[objects.material]") && !first.contains("lights"));
        assert!(first.contains("[[objects.circles]]"), "a sub-array stays in its object");
        assert!(text[s.objects[1].clone()].starts_with("[[ 'objects' ]]"));
        assert!(s.rest.contains("[camera]") && s.rest.contains("[[lights]]") && !s.rest.contains("sphere"));
        for needle in ["[camera]", "width", "[[lights]]", "position"] {
            let at = s.rest.find(needle).unwrap();
            assert_eq!(&text[s.file_offset(at)..s.file_offset(at) + needle.len()], needle, "{needle} maps back");
        }
        assert_eq!(s.unclosed, None);
        // A sub-table away from its object is refused where it is; an open bracket is found.
        let away = "[[objects]]\ntype = \"sphere\"\n[[lights]]\n[objects.material]\n";
        assert_eq!(split(away).err().map(|m| m.at), away.find("[objects.material]"));
        // Before any object, too: it would add to another file's last object once joined.
        let first = "[objects.material]\ncolour = [1.0, 0.0, 0.0]\n[[objects]]\n";
        assert_eq!(split(first).err().map(|m| m.at), Some(0));
        let open = "[camera]\nx = [1,\n[[objects]]\n";
        assert_eq!(split(open).ok().unwrap().unclosed, open.find("[1"));
    }

    #[test]
    fn an_include_after_a_table_is_refused_where_it_is() {
        for late in ["[camera]\nwidth = 8\n  include = [\"a.toml\"]\n", "[[objects]]\n\"include\" = []\n"] {
            let at = late.find("include").map(|k| k - usize::from(late.contains("\"include\"")));
            let refused = split(late).err();
            assert_eq!(refused.as_ref().map(|m| m.at), at, "{late}");
            assert!(refused.is_some_and(|m| m.message.contains("before the first table")));
        }
        // Before any table, in a value, a comment or a string, or as part of a dotted key, it is no include after a table.
        for fine in [
            "include = [\"a.toml\"]\n[camera]\n",
            "[camera]\nx = [\ninclude]\n",
            "[camera]\n# include = []\nname = \"\"\"\ninclude = 1\"\"\"\n",
            "[camera]\ninclude.x = 1\n",
        ] {
            assert!(split(fine).is_ok(), "{fine}");
        }
    }
}
