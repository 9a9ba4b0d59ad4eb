//! Atomic output folders: a failed run never leaves a half-written result.

use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// A folder being written beside its final place; [`StagedDir::commit`] moves it there.
#[derive(Debug)]
pub struct StagedDir {
    staging: PathBuf,
    target: PathBuf,
}

impl StagedDir {
    /// Creates an empty staging folder beside `target` (same parent, so the final move is a
    /// rename on one file system).
    pub fn create(target: &Path) -> io::Result<Self> {
        let parent = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        fs::create_dir_all(&parent)?;
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|| "flapwright-out".into());
        let staging = parent.join(format!(".{name}.partial-{}", std::process::id()));
        if staging.exists() {
            fs::remove_dir_all(&staging)?;
        }
        fs::create_dir(&staging)?;
        Ok(Self {
            staging,
            target: target.to_path_buf(),
        })
    }

    /// Path of a file inside the staging folder.
    pub fn file(&self, name: &str) -> PathBuf {
        self.staging.join(name)
    }

    /// Replaces `target` with the staged folder. An existing `target` must be a folder that
    /// a previous run wrote (it holds `report.json`) or empty, so a typo in `--out` cannot
    /// delete unrelated files.
    pub fn commit(self) -> io::Result<PathBuf> {
        if self.target.exists() {
            let is_previous_run =
                self.target.join("report.json").is_file() || fs::read_dir(&self.target)?.next().is_none();
            if !self.target.is_dir() || !is_previous_run {
                return Err(io::Error::new(
                    io::ErrorKind::AlreadyExists,
                    format!(
                        "{} exists and is not an earlier Flapwright output (no report.json); choose another --out",
                        self.target.display()
                    ),
                ));
            }
            let old = self.staging.with_extension("old");
            fs::rename(&self.target, &old)?;
            fs::rename(&self.staging, &self.target)?;
            fs::remove_dir_all(&old)?;
        } else {
            fs::rename(&self.staging, &self.target)?;
        }
        Ok(self.target.clone())
    }
}

impl Drop for StagedDir {
    fn drop(&mut self) {
        // Reached with the staging folder still present only when the run failed.
        let _ = fs::remove_dir_all(&self.staging);
    }
}
