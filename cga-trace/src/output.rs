//! Output files that cannot cost the user a file.
//!
//! An output is written to a temporary file beside its target and renamed over the target
//! only once everything has been written and synced, so an existing file survives every
//! failure (a bad scene, a refused option, a full disk, an interrupted render). Before
//! anything is created, the target is resolved through its symbolic links and compared,
//! by device and inode, with every input: an output that *is* an input — by the same path,
//! a symbolic link or a hard link — is refused. A character device (`/dev/null`,
//! `/dev/full`) is written to directly and never removed; directories, pipes, sockets and
//! block devices are refused.

use crate::input::{Identity, Input};
use std::fs;
use std::io::{self, BufWriter, Cursor, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};
use tempfile::NamedTempFile;

/// Symbolic links followed to find an output's target before giving up (Linux's own limit).
const MAX_LINKS: usize = 40;

/// Why an output cannot be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputFileError {
    /// The output is one of the inputs.
    #[error("`{output}` is the same file as the {role} `{input}`: refusing to write over it")]
    SameFile {
        /// The output, as given.
        output: String,
        /// What the input is (`scene`, `texture`, `mesh`, …).
        role: &'static str,
        /// The input, as given.
        input: String,
    },
    /// Two outputs of one command are one file (numbered frames through links).
    #[error("`{first}` and `{second}` are the same file: one would be written over the other")]
    Aliased {
        /// The first output, as given.
        first: String,
        /// The later one.
        second: String,
    },
    /// The target is a directory, a pipe, a socket or a block device.
    #[error("cannot write `{path}`: it is {kind}")]
    NotAFile {
        /// The output, as given.
        path: String,
        /// What it is.
        kind: &'static str,
    },
    /// The target exists and is read-only.
    #[error("cannot write `{0}`: it is read-only")]
    ReadOnly(String),
    /// No temporary file can be made beside the target (the directory is not writable).
    #[error("cannot write `{path}`: no file can be made in `{dir}` to write it to first: {source}")]
    Directory {
        /// The output, as given.
        path: String,
        /// The directory.
        dir: String,
        /// Why.
        source: io::Error,
    },
    /// Creating, writing, syncing or renaming failed.
    #[error("cannot write `{path}`: {source}")]
    Io {
        /// The output, as given.
        path: String,
        /// Why.
        source: io::Error,
    },
}

/// An output being written: bytes go to a temporary file beside the target (or, for a
/// character device, to memory), and [`OutputFile::commit`] puts them in place.
#[derive(Debug)]
pub struct OutputFile {
    /// The path as the user gave it, for messages.
    shown: PathBuf,
    /// Where the bytes end up: `shown` with its symbolic links resolved.
    target: PathBuf,
    sink: Sink,
}

#[derive(Debug)]
enum Sink {
    /// A regular file: a temporary file in the target's directory.
    Temporary(BufWriter<NamedTempFile>),
    /// A character device: written once, whole, on commit.
    Device(Cursor<Vec<u8>>),
}

impl OutputFile {
    /// Prepare to write `path`: refused if it is the same file as any of `inputs` (each with
    /// what it is, for the message), a directory or another file that is not a regular file
    /// or a character device, read-only, or one this user may not replace (in a sticky
    /// directory); otherwise a temporary file is created beside it (so that a directory that
    /// cannot be written fails now, before any work).
    pub fn create(path: &Path, inputs: &[(&'static str, &Path)]) -> Result<Self, OutputFileError> {
        let shown = path.to_path_buf();
        let failed = |source| OutputFileError::Io { path: path.display().to_string(), source };
        // What the path names, through every link the system follows (`/dev/stdout` too).
        let existing = match fs::metadata(path) {
            Ok(m) => Some(m),
            Err(e) if e.kind() == io::ErrorKind::NotFound => None,
            Err(e) => return Err(failed(e)),
        };
        for &(role, input) in inputs {
            let same = existing.as_ref().is_some_and(|m| same_file(path, m, input));
            if same || path == input {
                let (output, input) = (path.display().to_string(), input.display().to_string());
                return Err(OutputFileError::SameFile { output, role, input });
            }
        }
        let not_a_file = |kind| OutputFileError::NotAFile { path: path.display().to_string(), kind };
        let (target, permissions) = match &existing {
            Some(m) if m.is_dir() => return Err(not_a_file("a directory")),
            Some(m) if m.is_file() && m.permissions().readonly() => {
                return Err(OutputFileError::ReadOnly(path.display().to_string()));
            }
            Some(m) if m.is_file() => (fs::canonicalize(path).map_err(failed)?, Some(m.permissions())),
            Some(m) => {
                return match special_kind(m) {
                    None => Ok(OutputFile {
                        shown: shown.clone(),
                        target: shown,
                        sink: Sink::Device(Cursor::new(Vec::new())),
                    }),
                    Some(kind) => Err(not_a_file(kind)),
                };
            }
            // A new file, or the one a dangling link names.
            None => (resolve(path).map_err(failed)?, new_file_permissions()),
        };
        let dir = match target.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let name = target.file_name().map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
        let prefix = format!(".{name}.");
        let mut builder = tempfile::Builder::new();
        builder.prefix(&prefix).suffix(".tmp");
        if let Some(p) = &permissions {
            builder.permissions(p.clone());
        }
        let temporary = builder.tempfile_in(dir).map_err(|source| OutputFileError::Directory {
            path: path.display().to_string(),
            dir: dir.display().to_string(),
            source,
        })?;
        if let Some(m) = &existing {
            replaceable(m, dir, temporary.as_file())
                .map_err(|why| OutputFileError::NotAFile { path: path.display().to_string(), kind: why })?;
        }
        // The mode asked for at creation is cut by the umask; an existing file's is kept.
        if let (Some(p), Some(_)) = (permissions, &existing) {
            temporary.as_file().set_permissions(p).map_err(failed)?;
        }
        Ok(OutputFile { shown, target, sink: Sink::Temporary(BufWriter::new(temporary)) })
    }

    /// Refuse the output if it is one of `inputs` (the files a scene was read from, found
    /// only once it is loaded): by path, symbolic link or hard link, as [`OutputFile::create`]
    /// refuses the inputs it is given. Nothing has been written yet, so nothing is lost.
    pub fn refuse(&self, inputs: &[Input]) -> Result<(), OutputFileError> {
        let existing = fs::metadata(&self.shown).ok();
        for input in inputs {
            let same = existing.as_ref().is_some_and(|m| same_file(&self.shown, m, &input.path));
            if same || self.shown == input.path || self.target == input.path {
                return Err(OutputFileError::SameFile {
                    output: self.shown.display().to_string(),
                    role: input.role,
                    input: input.path.display().to_string(),
                });
            }
        }
        Ok(())
    }

    /// Whether the output is a character device (written directly, with nothing beside it).
    pub fn is_device(&self) -> bool {
        matches!(self.sink, Sink::Device(_))
    }

    /// The path as given.
    pub fn path(&self) -> &Path {
        &self.shown
    }

    /// Put what was written in place: flush and sync the temporary file, then rename it over
    /// the target (or write the bytes to the device). On failure the target is as it was.
    pub fn commit(self) -> Result<(), OutputFileError> {
        let io = |source| OutputFileError::Io { path: self.shown.display().to_string(), source };
        match self.sink {
            Sink::Temporary(writer) => {
                let temporary = writer.into_inner().map_err(|e| io(e.into_error()))?;
                temporary.as_file().sync_all().map_err(io)?;
                temporary.persist(&self.target).map_err(|e| io(e.error))?;
            }
            Sink::Device(bytes) => {
                let mut device = fs::OpenOptions::new().write(true).open(&self.target).map_err(io)?;
                device.write_all(bytes.get_ref()).and_then(|()| device.flush()).map_err(io)?;
            }
        }
        Ok(())
    }
}

impl Write for OutputFile {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        match &mut self.sink {
            Sink::Temporary(w) => w.write(buf),
            Sink::Device(w) => w.write(buf),
        }
    }

    fn flush(&mut self) -> io::Result<()> {
        match &mut self.sink {
            Sink::Temporary(w) => w.flush(),
            Sink::Device(w) => w.flush(),
        }
    }
}

impl Seek for OutputFile {
    fn seek(&mut self, to: SeekFrom) -> io::Result<u64> {
        match &mut self.sink {
            Sink::Temporary(w) => w.seek(to),
            Sink::Device(w) => w.seek(to),
        }
    }
}

/// Refuse `outputs` (all that one command will write, such as an animation's frames) if
/// any two are one file: the same file by device and inode where they exist (hard links,
/// symbolic links), or the same path once their links are followed and their folders made
/// canonical (a dangling link to a file not yet written).
pub fn distinct(outputs: &[PathBuf]) -> Result<(), OutputFileError> {
    use std::collections::HashMap;
    let mut seen: HashMap<Identity, usize> = HashMap::with_capacity(2 * outputs.len());
    for (k, path) in outputs.iter().enumerate() {
        let failed = |source| OutputFileError::Io { path: path.display().to_string(), source };
        let target = resolve(path).map_err(failed)?;
        let folder = match target.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let name = target.file_name().map(PathBuf::from).unwrap_or_default();
        let place = fs::canonicalize(folder).map_or(target.clone(), |f| f.join(name));
        let keys = [Some(Identity::Path(place)), Identity::of(path).ok()];
        for key in keys.into_iter().flatten() {
            if let Some(&j) = seen.get(&key) {
                let (first, second) = (outputs[j].display().to_string(), path.display().to_string());
                return Err(OutputFileError::Aliased { first, second });
            }
            seen.insert(key, k);
        }
    }
    Ok(())
}

/// `path` with its symbolic links followed to the file they name (which need not exist).
fn resolve(path: &Path) -> io::Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let link = fs::read_link(&p)?;
                p = match p.parent() {
                    Some(dir) if link.is_relative() => dir.join(link),
                    _ => link,
                };
            }
            Ok(_) => return Ok(p),
            Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(p),
            Err(e) => return Err(e),
        }
    }
    Err(io::Error::other("too many levels of symbolic links"))
}

/// Whether the existing file at `a` (its metadata `ma`, links followed) is the file `b`
/// names: the same device and inode (canonical paths where there are none). Neither is
/// opened (opening a pipe could block).
fn same_file(a: &Path, ma: &fs::Metadata, b: &Path) -> bool {
    Identity::of(b).is_ok_and(|other| Identity::from_metadata(a, ma) == other)
}

/// Whether the renaming that puts the output in place will be allowed: in a sticky directory
/// (`/tmp`) only a file's owner, the directory's or root may replace it. The temporary file
/// just made tells who this process is.
fn replaceable(existing: &fs::Metadata, dir: &Path, ours: &fs::File) -> Result<(), &'static str> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::{MetadataExt, PermissionsExt};
        let (me, sticky) = (ours.metadata().map_or(0, |m| m.uid()), fs::metadata(dir));
        let sticky = sticky.is_ok_and(|d| d.permissions().mode() & 0o1000 != 0 && d.uid() != me);
        if sticky && me != 0 && existing.uid() != me {
            return Err("another user's file in a sticky directory (it cannot be replaced)");
        }
    }
    let _ = (existing, dir, ours);
    Ok(())
}

/// What a file that is neither a regular file nor a directory is, if it cannot take an
/// output; `None` for a character device, which can.
fn special_kind(m: &fs::Metadata) -> Option<&'static str> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        let t = m.file_type();
        if t.is_char_device() {
            None
        } else if t.is_fifo() {
            Some("a named pipe")
        } else if t.is_socket() {
            Some("a socket")
        } else if t.is_block_device() {
            Some("a block device")
        } else {
            Some("not a regular file")
        }
    }
    #[cfg(not(unix))]
    {
        let _ = m;
        Some("not a regular file")
    }
}

/// A new file's mode, where the system has modes: `rw-rw-rw-` less the umask, as
/// `File::create` gives (the temporary file's own default is `rw-------`).
fn new_file_permissions() -> Option<fs::Permissions> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        Some(fs::Permissions::from_mode(0o666))
    }
    #[cfg(not(unix))]
    {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh scratch directory for one test, removed when the test ends, pass or fail.
    fn scratch(name: &str) -> tempfile::TempDir {
        tempfile::Builder::new().prefix(&format!("cga-trace-output-{name}-")).tempdir().unwrap()
    }

    #[test]
    fn an_existing_file_is_replaced_only_on_commit() {
        let scratch_dir = scratch("commit");
        let dir = scratch_dir.path();
        let out = dir.join("out.png");
        fs::write(&out, b"old").unwrap();
        let mut file = OutputFile::create(&out, &[]).unwrap();
        file.write_all(b"new").unwrap();
        assert_eq!(fs::read(&out).unwrap(), b"old", "untouched while writing");
        drop(file);
        assert_eq!(fs::read(&out).unwrap(), b"old", "untouched when dropped");
        assert_eq!(fs::read_dir(dir).unwrap().count(), 1, "no temporary file left");
        let mut file = OutputFile::create(&out, &[]).unwrap();
        file.write_all(b"new").unwrap();
        file.commit().unwrap();
        assert_eq!(fs::read(&out).unwrap(), b"new");
    }

    #[cfg(unix)]
    #[test]
    fn links_to_an_input_are_refused_and_links_elsewhere_followed() {
        let scratch_dir = scratch("links");
        let dir = scratch_dir.path();
        let (scene, other) = (dir.join("scene.toml"), dir.join("v3.png"));
        fs::write(&scene, b"scene").unwrap();
        fs::write(&other, b"v3").unwrap();
        let (sym, hard, latest) = (dir.join("sym.png"), dir.join("hard.png"), dir.join("latest.png"));
        std::os::unix::fs::symlink("scene.toml", &sym).unwrap();
        fs::hard_link(&scene, &hard).unwrap();
        std::os::unix::fs::symlink("v3.png", &latest).unwrap();
        for path in [&scene, &sym, &hard] {
            let e = OutputFile::create(path, &[("scene", &scene)]).unwrap_err();
            assert!(matches!(e, OutputFileError::SameFile { .. }), "{e}");
        }
        let mut file = OutputFile::create(&latest, &[("scene", &scene)]).unwrap();
        file.write_all(b"v4").unwrap();
        file.commit().unwrap();
        assert!(fs::symlink_metadata(&latest).unwrap().file_type().is_symlink(), "the link is kept");
        assert_eq!((fs::read(&other).unwrap(), fs::read(&scene).unwrap()), (b"v4".to_vec(), b"scene".to_vec()));
    }
}
