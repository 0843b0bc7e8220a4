//! `include = ["parts.toml", …]`: files whose `[materials.NAME]`, `[[lights]]` and
//! `[[objects]]` join the scene's, read in the order listed (an included file may include
//! others), each once; their objects come before the including file's own. The files are joined into one text, every `include` line blanked, so
//! that the scene is read as one file; each place in it maps back to its own file, line and
//! column for errors. Names in `include` (and the images and meshes any file names) are
//! relative to the scene file's folder, as POV-Ray's `#include` reads from its own.

use super::error::{SceneError, line_column};
use super::sections;
use crate::input::{Input, open_regular};
use crate::limits::{MAX_DOCUMENT_TOKENS, MAX_FILE_BYTES, MAX_INCLUDES};
use std::io::Read;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// The scene's files as one text, and where each lies in it.
pub(crate) struct Joined {
    /// The files, one after another (each on its own lines), `include` lines blanked.
    pub text: String,
    /// `(where it starts in `text`, its name)` for each file, in the order joined: a file,
    /// then the files it includes.
    files: Vec<(usize, String)>,
    /// Each file's place in the order its objects are read: the files it includes first
    /// (in the order listed), then its own.
    rank: Vec<usize>,
}

impl Joined {
    /// The index in [`Joined::files`] of the file holding `offset`.
    fn file_at(&self, offset: usize) -> usize {
        self.files.partition_point(|&(start, _)| start <= offset).saturating_sub(1)
    }

    /// The file, 1-based line and column of `offset` in [`Joined::text`].
    pub(crate) fn locate(&self, offset: usize) -> (String, usize, usize) {
        let k = self.file_at(offset);
        let (start, file) = &self.files[k];
        let end = self.files.get(k + 1).map_or(self.text.len(), |&(next, _)| next);
        let (line, column) = line_column(&self.text[*start..end], offset - start);
        (file.clone(), line, column)
    }

    /// The files joined: the scene, then each included file.
    pub(crate) fn inputs(&self) -> Vec<Input> {
        let role = |k: usize| if k == 0 { "scene" } else { "included file" };
        self.files.iter().enumerate().map(|(k, (_, name))| Input { role: role(k), path: name.into() }).collect()
    }

    /// `objects` (sections of [`Joined::text`]) in reading order: an included file's
    /// objects before the including file's own, so that a scene can instance the templates
    /// of the files it includes.
    pub(crate) fn reading_order(&self, objects: &mut [Range<usize>]) {
        objects.sort_by_key(|r| self.rank[self.file_at(r.start)]);
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
    let mut joined = Joined { text: String::new(), files: Vec::new(), rank: Vec::new() };
    let mut reader = Reader { folder, read: Vec::new(), ranked: 0 };
    let scene = std::fs::canonicalize(file).ok();
    reader.add(&mut joined, text.to_string(), file, scene)?;
    Ok(joined)
}

/// What joining has read so far.
struct Reader {
    /// The scene's folder, which every name is relative to.
    folder: PathBuf,
    /// Each file read (canonical path), and whether it is still being read (its includes
    /// not all joined: naming it again is a cycle).
    read: Vec<(PathBuf, bool)>,
    /// How many files have their place in the reading order.
    ranked: usize,
}

impl Reader {
    /// One file's text, blanked, then the files it includes, in order.
    fn add(
        &mut self,
        joined: &mut Joined,
        text: String,
        file: &str,
        canonical: Option<PathBuf>,
    ) -> Result<(), SceneError> {
        let scene = joined.files.is_empty();
        let (list, blank) = includes(&text, file, scene)?;
        // Spaces keep every other byte, and so every line and column, where it was.
        let mut bytes = text.into_bytes();
        bytes[blank].iter_mut().filter(|b| **b != b'\n').for_each(|b| *b = b' ');
        let text = String::from_utf8(bytes).expect("ASCII put over whole characters");
        let index = joined.files.len();
        joined.files.push((joined.text.len(), file.to_string()));
        joined.rank.push(usize::MAX);
        joined.text.push_str(&text);
        joined.text.push('\n');
        let me = canonical.map(|c| {
            self.read.push((c, true));
            self.read.len() - 1
        });
        for (name, offset) in list {
            let here = |message| at(file, &text, offset, message);
            let (canonical, included) = self.open(joined, &name).map_err(here)?;
            self.add(joined, included, &self.folder.join(&name).display().to_string(), Some(canonical))?;
        }
        if let Some(me) = me {
            self.read[me].1 = false;
        }
        joined.rank[index] = self.ranked;
        self.ranked += 1;
        Ok(())
    }

    /// The file `name` includes, read (a leading byte-order mark dropped), and its canonical
    /// path; refused if read before, past [`MAX_INCLUDES`] files or [`MAX_FILE_BYTES`] in all.
    fn open(&self, joined: &Joined, name: &str) -> Result<(PathBuf, String), String> {
        let path = self.folder.join(name);
        let canonical = std::fs::canonicalize(&path).map_err(|e| format!("include `{name}`: {e}"))?;
        if let Some((_, open)) = self.read.iter().find(|(c, _)| *c == canonical) {
            return Err(if *open {
                format!("`{name}` is being read: including it here is a cycle")
            } else {
                format!("`{name}` is included already: each file is read once (include it in one place)")
            });
        }
        // The scene is the first file: the rest are included.
        if joined.files.len() > MAX_INCLUDES {
            return Err(format!("more than {MAX_INCLUDES} included files"));
        }
        let left = MAX_FILE_BYTES.saturating_sub(joined.text.len() as u64);
        let mut bytes = Vec::new();
        open_regular(&path)
            .and_then(|(f, _, _)| f.take(left + 1).read_to_end(&mut bytes))
            .map_err(|e| format!("include `{name}`: {e}"))?;
        if bytes.len() as u64 > left {
            return Err(format!("the scene's files hold more than the limit of {MAX_FILE_BYTES} bytes"));
        }
        let text = String::from_utf8(bytes).map_err(|_| format!("`{name}` is not UTF-8 text"))?;
        let text = text.strip_prefix('\u{feff}').map(str::to_string).unwrap_or(text);
        Ok((canonical, text))
    }
}

/// Names of included files, each with its offset in the including file.
type Names = Vec<(String, usize)>;

/// The files `text` includes (with the offset of each name) and the span of its `include`
/// line. The scene file's own mistakes are left for the scene's reader to report; an
/// included file must parse alone, give tables only (`[materials.NAME]`, `[[lights]]`,
/// `[[objects]]`: a key-value outside them would join the including file's last table) and
/// `include`.
fn includes(text: &str, file: &str, scene: bool) -> Result<(Names, Range<usize>), SceneError> {
    let none = Ok((Vec::new(), 0..0));
    let sections = match sections::split(text) {
        Ok(s) => s,
        Err(_) if scene => return none,
        Err(m) => return Err(at(file, text, m.at, m.message)),
    };
    let tokens = sections::significant_tokens(&sections.rest);
    if tokens > MAX_DOCUMENT_TOKENS {
        if scene {
            return none;
        }
        let message = format!(
            "the file outside its `[[objects]]` tables holds {tokens} values, keys and brackets, more than the {MAX_DOCUMENT_TOKENS} read at once"
        );
        return Err(at(file, text, 0, message));
    }
    let document = match toml::de::DeTable::parse(&sections.rest) {
        Ok(d) => d,
        Err(_) if scene => return none,
        Err(e) => {
            let offset = sections.file_offset(e.span().map_or(0, |s| s.start));
            return Err(at(file, text, offset, e.message().trim().to_string()));
        }
    };
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
            _ if scene => {}
            other @ ("materials" | "lights" | "objects") if offset < sections.root_end => {
                let message = format!(
                    "`{other}` is given as a key outside a table: an included file is joined after another file's tables, so write it as a table (`[materials.NAME]`, `[[lights]]`, `[[objects]]`)"
                );
                return Err(at(file, text, offset, message));
            }
            "materials" | "lights" | "objects" => {}
            other => {
                let message = format!(
                    "`{}` belongs in the scene file: an included file gives `[materials.NAME]`, `[[lights]]`, `[[objects]]` and `include`",
                    other.escape_debug()
                );
                return Err(at(file, text, offset, message));
            }
        }
    }
    Ok((list, blank))
}
