//! `include = ["parts.toml", …]`: files whose `[materials.NAME]`, `[[lights]]` and
//! `[[objects]]` join the scene's, read in the order listed (an included file may include
//! others), each once. The files are joined into one text, every `include` line blanked, so
//! that the scene is read as one file; each place in it maps back to its own file, line and
//! column for errors. Names in `include` (and the images and meshes any file names) are
//! relative to the scene file's folder, as POV-Ray's `#include` reads from its own.

use super::sections;
use crate::limits::{MAX_FILE_BYTES, MAX_INCLUDES};
use crate::scene::{SceneError, line_column};
use std::io::Read;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// The scene's files as one text, and where each lies in it.
pub(crate) struct Joined {
    /// The files, one after another (each on its own lines), `include` lines blanked.
    pub text: String,
    /// `(where it starts in `text`, its name)` for each file, in order.
    files: Vec<(usize, String)>,
}

impl Joined {
    /// The file, 1-based line and column of `offset` in [`Joined::text`].
    pub(crate) fn locate(&self, offset: usize) -> (String, usize, usize) {
        let k = self.files.partition_point(|&(start, _)| start <= offset).saturating_sub(1);
        let (start, file) = &self.files[k];
        let end = self.files.get(k + 1).map_or(self.text.len(), |&(next, _)| next);
        let (line, column) = line_column(&self.text[*start..end], offset - start);
        (file.clone(), line, column)
    }
}

/// An error at `offset` of the file `file`'s `text`.
fn at(file: &str, text: &str, offset: usize, message: String) -> SceneError {
    let (line, column) = line_column(text, offset);
    SceneError::Syntax { file: file.into(), line, column, message }
}

/// `text` (the scene file `file`) with the files it includes.
pub(crate) fn join(text: &str, file: &str) -> Result<Joined, SceneError> {
    let folder = Path::new(file).parent().unwrap_or(Path::new("")).to_path_buf();
    let mut joined = Joined { text: String::new(), files: Vec::new() };
    let mut read = std::fs::canonicalize(file).into_iter().collect();
    add(&mut joined, text.to_string(), file, &folder, &mut read, true)?;
    Ok(joined)
}

/// One file's text, blanked, then the files it includes, in order.
fn add(
    joined: &mut Joined,
    mut text: String,
    file: &str,
    folder: &Path,
    read: &mut Vec<PathBuf>,
    scene: bool,
) -> Result<(), SceneError> {
    let (list, blank) = includes(&text, file, scene)?;
    // Spaces keep every other byte, and so every line and column, where it was.
    let mut bytes = std::mem::take(&mut text).into_bytes();
    bytes[blank].iter_mut().filter(|b| **b != b'\n').for_each(|b| *b = b' ');
    let text = String::from_utf8(bytes).expect("ASCII put over whole characters");
    joined.files.push((joined.text.len(), file.to_string()));
    joined.text.push_str(&text);
    joined.text.push('\n');
    for (name, offset) in list {
        let path = folder.join(&name);
        let here = |message| at(file, &text, offset, message);
        let canonical = std::fs::canonicalize(&path).map_err(|e| here(format!("include `{name}`: {e}")))?;
        if read.contains(&canonical) {
            return Err(here(format!("`{name}` is read already: each file is included once (no cycles)")));
        }
        if read.len() > MAX_INCLUDES {
            return Err(here(format!("more than {MAX_INCLUDES} included files")));
        }
        read.push(canonical);
        let left = MAX_FILE_BYTES.saturating_sub(joined.text.len() as u64);
        let mut bytes = Vec::new();
        std::fs::File::open(&path)
            .and_then(|f| f.take(left + 1).read_to_end(&mut bytes))
            .map_err(|e| here(format!("include `{name}`: {e}")))?;
        if bytes.len() as u64 > left {
            return Err(here(format!("the scene's files hold more than the limit of {MAX_FILE_BYTES} bytes")));
        }
        let included = String::from_utf8(bytes).map_err(|_| here(format!("`{name}` is not UTF-8 text")))?;
        add(joined, included, &path.display().to_string(), folder, read, false)?;
    }
    Ok(())
}

/// Names of included files, each with its offset in the including file.
type Names = Vec<(String, usize)>;

/// The files `text` includes (with the offset of each name) and the span of its `include`
/// line; in an included file, anything but `include`, `materials`, `lights` and `objects`
/// is an error. A file that does not parse is left for the scene's reader to report.
fn includes(text: &str, file: &str, scene: bool) -> Result<(Names, Range<usize>), SceneError> {
    let none = Ok((Vec::new(), 0..0));
    let Ok(sections) = sections::split(text) else { return none };
    let Ok(document) = toml::de::DeTable::parse(&sections.rest) else { return none };
    let mut list = Vec::new();
    let mut blank = 0..0;
    for (key, value) in document.get_ref() {
        let offset = sections.file_offset(key.span().start);
        match key.get_ref().as_ref() {
            "include" => {
                let toml::de::DeValue::Array(names) = value.get_ref() else {
                    return Err(at(file, text, offset, "`include`: give a list of file names".into()));
                };
                for name in names {
                    let toml::de::DeValue::String(s) = name.get_ref() else {
                        let offset = sections.file_offset(name.span().start);
                        return Err(at(file, text, offset, "`include`: give a list of file names".into()));
                    };
                    list.push((s.to_string(), sections.file_offset(name.span().start)));
                }
                blank = offset..sections.file_offset(value.span().end);
            }
            "materials" | "lights" | "objects" => {}
            other if !scene => {
                let message = format!(
                    "`{}` belongs in the scene file: an included file gives `[materials.NAME]`, `[[lights]]`, `[[objects]]` and `include`",
                    other.escape_debug()
                );
                return Err(at(file, text, offset, message));
            }
            _ => {}
        }
    }
    Ok((list, blank))
}
