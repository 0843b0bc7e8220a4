//! What is wrong with a scene file: each error names the file, line and column and, for
//! invalid values or geometry, the table or object and a typed reason.

use crate::invalid::Invalid;

/// What is wrong with a scene file.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The file cannot be read.
    #[error("{file}: {source}")]
    Io {
        /// The file.
        file: String,
        /// Why.
        source: std::io::Error,
    },
    /// The TOML is malformed, or a field is unknown, missing or of the wrong type.
    #[error("{file}:{line}:{column}: {message}")]
    Syntax {
        /// The file.
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What and which field.
        message: String,
    },
    /// Well-formed, but the geometry or values are invalid.
    #[error("{file}:{line}:{column}: {what}: {reason}")]
    Invalid {
        /// The file.
        file: String,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The object (`object `disk`) or table (`camera`).
        what: String,
        /// Why.
        reason: Invalid,
    },
}

/// `text` with control characters escaped (`\t`, `\u{1b}`), as messages quote the file.
pub(crate) fn printable(text: &str) -> String {
    text.chars().map(|c| if c.is_control() { c.escape_debug().to_string() } else { c.to_string() }).collect()
}

/// 1-based line and column of a byte offset into bytes that are not all text.
pub(crate) fn line_column_bytes(bytes: &[u8], offset: usize) -> (usize, usize) {
    line_column(&String::from_utf8_lossy(&bytes[..offset]), offset)
}

/// 1-based line and column of a byte offset (inside a character: of that character).
pub(crate) fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}
