//! The files a scene names besides itself (airfoil coordinate files), read through a small
//! trait so that a scene held in memory needs no disk: the command line reads the scene
//! file's folder ([`Folder`]), a program may hand the files over ([`MemoryFiles`]) or none
//! ([`NoFiles`]: NACA sections and the bundled airfoils only).

use std::collections::BTreeMap;
use std::io;
use std::path::{Path, PathBuf};

/// Reads a file the scene names, by the name the scene gives it.
pub trait FileSource: Sync + std::fmt::Debug {
    /// The file's bytes; `None` when there is no such file (the bundled airfoils are tried
    /// next).
    fn read(&self, name: &str) -> Option<io::Result<Vec<u8>>>;

    /// Where the file lies on disk, if it does (the command line never writes over a file
    /// the scene reads).
    fn path_of(&self, _name: &str) -> Option<PathBuf> {
        None
    }
}

/// No files: NACA sections and the bundled airfoils only.
#[derive(Debug, Clone, Copy, Default)]
pub struct NoFiles;

impl FileSource for NoFiles {
    fn read(&self, _name: &str) -> Option<io::Result<Vec<u8>>> {
        None
    }
}

/// The files of a folder on disk, by their path relative to it (the scene file's folder).
#[derive(Debug, Clone)]
pub struct Folder(PathBuf);

impl Folder {
    /// Reads relative to `folder`.
    pub fn new(folder: impl Into<PathBuf>) -> Self {
        Self(folder.into())
    }

    /// The folder.
    pub fn path(&self) -> &Path {
        &self.0
    }
}

impl FileSource for Folder {
    fn read(&self, name: &str) -> Option<io::Result<Vec<u8>>> {
        let path = self.path_of(name)?;
        Some(std::fs::read(path))
    }

    fn path_of(&self, name: &str) -> Option<PathBuf> {
        let path = self.0.join(name);
        path.is_file().then_some(path)
    }
}

/// Files held in memory, by name.
#[derive(Debug, Clone, Default)]
pub struct MemoryFiles(BTreeMap<String, Vec<u8>>);

impl MemoryFiles {
    /// No files yet.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds (or replaces) the file `name`.
    pub fn with(mut self, name: impl Into<String>, bytes: impl Into<Vec<u8>>) -> Self {
        self.0.insert(name.into(), bytes.into());
        self
    }
}

impl FileSource for MemoryFiles {
    fn read(&self, name: &str) -> Option<io::Result<Vec<u8>>> {
        self.0.get(name).cloned().map(Ok)
    }
}
