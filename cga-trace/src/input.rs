//! The files a scene reads, and how they are opened.
//!
//! Every file a scene names (an included file, a texture, an environment map, a mesh) is
//! opened through [`open_regular`], which looks at what the path names before opening it: a
//! named pipe with no writer would block `open` forever, and a device could be endless, so
//! anything but a regular file is refused by name. Each file read is recorded as an
//! [`Input`] with its role, so that an output can be refused when it is one of them
//! ([`crate::output::OutputFile`]), and identified by device and inode ([`Identity`]), so
//! that one file named several ways is read once.

use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// A file a scene read, and what it was to the scene.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Input {
    /// What the file is: `scene`, `included file`, `texture`, `environment image`, `mesh`.
    pub role: &'static str,
    /// The path it was read from.
    pub path: PathBuf,
}

/// What makes two names one file: the device and inode where the system has them (a hard
/// link or a symbolic link is the file it names), the canonical path elsewhere.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Identity {
    /// Device and inode.
    Inode(u64, u64),
    /// The canonical path.
    Path(PathBuf),
}

impl Identity {
    /// The identity of the existing file `path` names (links followed).
    pub fn of(path: &Path) -> io::Result<Identity> {
        let metadata = fs::metadata(path)?;
        Ok(Identity::from_metadata(path, &metadata))
    }

    /// The identity of the file `path` names, from its metadata (links followed).
    pub fn from_metadata(path: &Path, metadata: &fs::Metadata) -> Identity {
        #[cfg(unix)]
        {
            use std::os::unix::fs::MetadataExt;
            let _ = path;
            Identity::Inode(metadata.dev(), metadata.ino())
        }
        #[cfg(not(unix))]
        {
            let _ = metadata;
            Identity::Path(fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf()))
        }
    }
}

/// What a path names that is not a regular file, in words; `None` for a regular file.
pub fn not_regular(metadata: &fs::Metadata) -> Option<&'static str> {
    let t = metadata.file_type();
    if t.is_file() {
        return None;
    }
    if t.is_dir() {
        return Some("a directory");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return Some("a named pipe");
        }
        if t.is_socket() {
            return Some("a socket");
        }
        if t.is_char_device() || t.is_block_device() {
            return Some("a device");
        }
    }
    Some("not a regular file")
}

/// `path` opened for reading, with its identity and size, if it names a regular file (links
/// followed); anything else is refused before it is opened, so that a named pipe without a
/// writer cannot block and a device cannot be read without end.
pub fn open_regular(path: &Path) -> io::Result<(fs::File, Identity, u64)> {
    let metadata = fs::metadata(path)?;
    if let Some(kind) = not_regular(&metadata) {
        return Err(io::Error::new(io::ErrorKind::InvalidInput, format!("it is {kind}, not a regular file")));
    }
    let file = fs::File::open(path)?;
    // The file opened is the one looked at (not swapped for a pipe in between).
    let opened = file.metadata()?;
    if let Some(kind) = not_regular(&opened) {
        return Err(io::Error::new(io::ErrorKind::InvalidInput, format!("it is {kind}, not a regular file")));
    }
    Ok((file, Identity::from_metadata(path, &opened), opened.len()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_regular_files_are_opened() {
        let dir = std::env::temp_dir().join(format!("cga-trace-input-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        let file = dir.join("a.txt");
        fs::write(&file, b"abc").unwrap();
        let (_, identity, size) = open_regular(&file).unwrap();
        assert_eq!(size, 3);
        assert_eq!(identity, Identity::of(&dir.join(".").join("a.txt")).unwrap());
        let e = open_regular(&dir).unwrap_err();
        assert!(e.to_string().contains("a directory"), "{e}");
        #[cfg(unix)]
        {
            let e = open_regular(Path::new("/dev/zero")).unwrap_err();
            assert!(e.to_string().contains("a device"), "{e}");
            let pipe = dir.join("pipe");
            let made = std::process::Command::new("mkfifo").arg(&pipe).status();
            if made.is_ok_and(|s| s.success()) {
                // Would block forever if it were opened.
                let e = open_regular(&pipe).unwrap_err();
                assert!(e.to_string().contains("a named pipe"), "{e}");
            }
        }
        let _ = fs::remove_dir_all(&dir);
    }
}
