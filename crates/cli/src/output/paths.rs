//! Where an output goes: `--out` resolved once (absolute, no `.` or `..`, links followed)
//! and the folders it may never be (the folder the run is in or above it, the scene's
//! folder or above it, an earlier output with a read-only folder in it).

use std::fs;
use std::io;
use std::path::{Component, Path, PathBuf};

use super::{exists, list_entries, OutputError};

/// `--out` resolved once: absolute, `.` and `..` taken out, symbolic links followed (as far
/// as the path exists; below that, `..` drops the name before it).
pub fn resolve_out(path: &Path) -> Result<PathBuf, OutputError> {
    resolve(path).map_err(|e| OutputError::Unwritable {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })
}

pub(super) fn resolve(path: &Path) -> io::Result<PathBuf> {
    let absolute = std::env::current_dir()?.join(path);
    let mut resolved = PathBuf::new();
    // `resolved` exists and is canonical (no links, no `..`).
    let mut on_disk = true;
    for component in absolute.components() {
        match component {
            Component::Prefix(_) | Component::RootDir => resolved.push(component.as_os_str()),
            Component::CurDir => {}
            Component::ParentDir => {
                resolved.pop();
                on_disk = exists(&resolved);
            }
            Component::Normal(name) => {
                resolved.push(name);
                if !on_disk {
                    continue;
                }
                match fs::symlink_metadata(&resolved) {
                    Ok(meta) => {
                        resolved = fs::canonicalize(&resolved).map_err(|e| {
                            if meta.file_type().is_symlink() {
                                io::Error::new(e.kind(), format!("a link that leads nowhere ({e})"))
                            } else {
                                e
                            }
                        })?;
                    }
                    Err(e) if e.kind() == io::ErrorKind::NotFound => on_disk = false,
                    Err(e) => return Err(e),
                }
            }
        }
    }
    Ok(resolved)
}

/// Refuses an output folder that is the folder the run is in or above it.
pub(super) fn refuse_working_folder(target: &Path) -> Result<(), OutputError> {
    let Ok(here) = std::env::current_dir().and_then(fs::canonicalize) else {
        return Ok(());
    };
    if here.starts_with(target) {
        return Err(OutputError::ContainsWorkingFolder {
            folder: target.to_path_buf(),
        });
    }
    Ok(())
}

/// Refuses an earlier output with a read-only folder in it.
pub(super) fn refuse_read_only(target: &Path) -> Result<(), OutputError> {
    match read_only_folder(target)? {
        Some(read_only) => Err(OutputError::ReadOnly {
            folder: target.to_path_buf(),
            read_only,
        }),
        None => Ok(()),
    }
}

/// The first folder in `folder` (itself included) that no one may write to.
pub(super) fn read_only_folder(folder: &Path) -> io::Result<Option<PathBuf>> {
    if fs::metadata(folder)?.permissions().readonly() {
        return Ok(Some(folder.to_path_buf()));
    }
    let mut entries = Vec::new();
    list_entries(folder, Path::new(""), &mut entries)?;
    Ok(entries
        .into_iter()
        .find(|(_, meta)| meta.is_dir() && meta.permissions().readonly())
        .map(|(relative, _)| folder.join(relative)))
}

/// Refuses an output folder that is the scene's folder or above it.
pub(super) fn refuse_scene_folder(target: &Path, scene: &Path) -> Result<(), OutputError> {
    let Ok(scene_abs) = fs::canonicalize(scene) else {
        return Ok(());
    };
    let target_abs = absolute(target);
    if scene_abs.starts_with(&target_abs) {
        return Err(OutputError::ContainsScene {
            folder: target.to_path_buf(),
            scene: scene.to_path_buf(),
        });
    }
    Ok(())
}

/// `path` made absolute with symbolic links resolved as far as it exists.
pub(super) fn absolute(path: &Path) -> PathBuf {
    resolve(path).unwrap_or_else(|_| path.to_path_buf())
}

pub(super) fn parent_of(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

pub(super) fn folder_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "flapwright-out".into())
}
