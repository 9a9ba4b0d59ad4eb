//! Output folders a user can trust: a failed run never leaves a half-written result, and
//! no run deletes or overwrites a file Flapwright did not write.
//!
//! The guarantees (the README's "Output folders" repeats them):
//! - `--out` is resolved once, before anything is read or moved ([`resolve_out`]): made
//!   absolute, `.` and `..` taken out, symbolic links followed. Every later step uses that
//!   one path, so `--out ./out/../out` and `--out out/.` are `--out out`. A symbolic link as
//!   `--out` is followed: the folder it points to is the output, and the link stays a link.
//! - The scene's own folder and every folder above it are never an output; nor are the
//!   folder the run is in and the folders above it (`--out .`, `--out ..`): a run replaces
//!   `--out` as a whole, so it cannot be the folder the user's shell stands in, and writing
//!   into it file by file would give up both the all-or-nothing replacement and the
//!   guarantee that no file of the user's is touched. Both are refused before any work, with
//!   the reason (exit 2).
//! - A run writes into a staging folder beside `--out` (`.<out>.partial-<pid>-<nanos>`)
//!   and moves it into place only when it succeeds (two renames on one file system).
//! - Every output folder holds a manifest ([`MANIFEST`]): each file written, with its size
//!   and SHA-256. An existing `--out` is replaced only when it is empty or when every file
//!   in it is in its manifest, unchanged; otherwise the run refuses with the foreign
//!   files named ([`OutputError::Foreign`]), unless `--force` is given, which removes them
//!   and says so.
//! - An earlier output with a read-only folder in it (the user protected it) is never
//!   replaced, not even with `--force` ([`OutputError::ReadOnly`], before any work): removing
//!   it would stop half-way on a read-only folder and leave a hidden backup behind.
//! - Staging and backup names are unique per run; leftovers of a killed run (its process
//!   is gone) are removed by the next run to the same `--out` and never block it.
//! - A single file (`--junit`) is written to a temporary file beside it and renamed into
//!   place; the temporary file is removed when any step fails (a full disk).

use std::fs;
use std::io::{self, Write};
use std::path::{Component, Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

/// Name of the manifest inside every output folder.
pub const MANIFEST: &str = ".flapwright-manifest.json";

/// Why an output folder cannot be used. Every variant is a problem with the user's
/// choice of `--out` (exit 2), except [`OutputError::Io`].
#[derive(Debug)]
pub enum OutputError {
    /// The folder holds files Flapwright did not write (or changed since).
    Foreign {
        /// The output folder.
        folder: PathBuf,
        /// Files not in its manifest or changed since, relative to the folder.
        files: Vec<PathBuf>,
    },
    /// `--out` is the scene's folder or a folder above it.
    ContainsScene {
        /// The output folder.
        folder: PathBuf,
        /// The scene file.
        scene: PathBuf,
    },
    /// `--out` is the folder the run is in or a folder above it (`--out .`).
    ContainsWorkingFolder {
        /// The output folder.
        folder: PathBuf,
    },
    /// `--out` exists and is not a folder.
    NotAFolder(PathBuf),
    /// The earlier output has a read-only folder in it: the user protected it.
    ReadOnly {
        /// The output folder.
        folder: PathBuf,
        /// The read-only folder in it (or the output folder itself).
        read_only: PathBuf,
    },
    /// An output file (`--junit`) exists and Flapwright did not write it.
    ForeignFile {
        /// The option that names it.
        option: &'static str,
        /// The file.
        path: PathBuf,
    },
    /// An output file would replace one of the run's inputs (the scene, an airfoil file)
    /// or land inside `--out`, which is replaced as a whole: never, even with `--force`.
    ReservedFile {
        /// The option that names it.
        option: &'static str,
        /// The file.
        path: PathBuf,
        /// What it is.
        what: String,
    },
    /// The folder cannot be created or written.
    Unwritable {
        /// The path tried.
        path: PathBuf,
        /// What the system said.
        reason: String,
    },
    /// Reading or moving files failed during the run.
    Io(io::Error),
}

impl std::fmt::Display for OutputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Foreign { folder, files } => {
                write!(
                    f,
                    "--out {} holds {} file(s) Flapwright did not write (or that changed since): ",
                    folder.display(),
                    files.len()
                )?;
                let shown: Vec<String> = files.iter().take(10).map(|p| p.display().to_string()).collect();
                write!(f, "{}", shown.join(", "))?;
                if files.len() > 10 {
                    write!(f, " and {} more", files.len() - 10)?;
                }
                write!(f, "; choose another --out, or pass --force to replace the folder with them")
            }
            Self::ContainsScene { folder, scene } => write!(
                f,
                "--out {} holds the scene file {}: the scene's folder and the folders above it are never an output; choose another --out",
                folder.display(),
                scene.display()
            ),
            Self::ContainsWorkingFolder { folder } => write!(
                f,
                "--out {} is the folder this run is in, or a folder above it: a run replaces --out as a whole, so it must be a folder of its own; name one inside it (for example --out flapwright-out)",
                folder.display()
            ),
            Self::NotAFolder(path) => write!(f, "--out {} exists and is not a folder", path.display()),
            Self::ReadOnly { folder, read_only } => write!(
                f,
                "--out {}: {} is read-only, and Flapwright does not replace an output made read-only (removing it would stop half-way); make it writable (chmod -R u+w {}) or choose another --out",
                folder.display(),
                read_only.display(),
                folder.display()
            ),
            Self::ForeignFile { option, .. } => write!(
                f,
                "exists and Flapwright did not write it; choose another {option} path, or pass --force to replace it"
            ),
            Self::ReservedFile { option, what, .. } => write!(
                f,
                "is {what}: never replaced, even with --force; choose another {option} path"
            ),
            Self::Unwritable { path, reason } => write!(f, "cannot write {}: {reason}", path.display()),
            Self::Io(error) => write!(f, "{error}"),
        }
    }
}

impl std::error::Error for OutputError {}

impl OutputError {
    /// True when the user's choice of paths is at fault (exit 2), false for a failure
    /// during the run.
    pub fn is_input_problem(&self) -> bool {
        !matches!(self, Self::Io(_))
    }
}

impl From<io::Error> for OutputError {
    fn from(error: io::Error) -> Self {
        Self::Io(error)
    }
}

/// What the manifest records of one file.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq, Eq)]
struct ManifestEntry {
    path: String,
    bytes: u64,
    sha256: String,
}

/// The manifest of an output folder.
#[derive(Debug, Clone, Serialize, Deserialize)]
struct Manifest {
    written_by: String,
    files: Vec<ManifestEntry>,
}

/// A folder being written beside its final place; [`StagedDir::commit`] moves it there.
#[derive(Debug)]
pub struct StagedDir {
    staging: PathBuf,
    target: PathBuf,
    force: bool,
    /// Files a forced commit removed (relative to the target), for the user to read.
    removed: Vec<PathBuf>,
}

/// A name unique to this run: process id and the clock's nanoseconds.
fn run_tag() -> String {
    let nanos = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_nanos());
    format!("{}-{nanos}", std::process::id())
}

fn exists(path: &Path) -> bool {
    fs::symlink_metadata(path).is_ok()
}

impl StagedDir {
    /// Checks that `target` may become an output (see the module docs) and creates an empty
    /// staging folder beside it. `scene` is the scene file, if any. With `force`, foreign
    /// files in `target` are replaced at commit.
    pub fn create(target: &Path, scene: Option<&Path>, force: bool) -> Result<Self, OutputError> {
        let target = resolve_out(target)?;
        if let Some(scene) = scene {
            refuse_scene_folder(&target, scene)?;
        }
        refuse_working_folder(&target)?;
        if target.file_name().is_none() {
            return Err(OutputError::ContainsWorkingFolder { folder: target });
        }
        check_replaceable(&target, force)?;
        let parent = parent_of(&target);
        fs::create_dir_all(&parent).map_err(|e| OutputError::Unwritable {
            path: parent.clone(),
            reason: e.to_string(),
        })?;
        let name = folder_name(&target);
        clean_leftovers(&parent, &name);
        let staging = parent.join(format!(".{name}.partial-{}", run_tag()));
        fs::create_dir(&staging).map_err(|e| OutputError::Unwritable {
            path: staging.clone(),
            reason: e.to_string(),
        })?;
        Ok(Self {
            staging,
            target,
            force,
            removed: Vec::new(),
        })
    }

    /// The output folder, resolved.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Path of a file inside the staging folder.
    pub fn file(&self, name: &str) -> PathBuf {
        self.staging.join(name)
    }

    /// Files a forced commit removed, relative to the output folder.
    pub fn removed(&self) -> &[PathBuf] {
        &self.removed
    }

    /// Writes the manifest and replaces `target` with the staged folder. Returns the
    /// output folder and the foreign files that `--force` removed.
    pub fn commit(mut self) -> Result<(PathBuf, Vec<PathBuf>), OutputError> {
        write_manifest(&self.staging)?;
        // Checked again: another process may have written into the folder meanwhile.
        self.removed = check_replaceable(&self.target, self.force)?;
        let parent = parent_of(&self.target);
        if self.target.exists() {
            let old = parent.join(format!(".{}.old-{}", folder_name(&self.target), run_tag()));
            fs::rename(&self.target, &old)?;
            if let Err(error) = fs::rename(&self.staging, &self.target) {
                // Put the earlier output back rather than leave nothing.
                let _ = fs::rename(&old, &self.target);
                return Err(error.into());
            }
            fs::remove_dir_all(&old)?;
        } else {
            fs::rename(&self.staging, &self.target)?;
        }
        Ok((self.target.clone(), std::mem::take(&mut self.removed)))
    }
}

impl Drop for StagedDir {
    fn drop(&mut self) {
        // Reached with the staging folder still present only when the run failed.
        let _ = fs::remove_dir_all(&self.staging);
    }
}

/// Checks that a file may be written at `path` outside any output folder (a JUnit file
/// named by `option`): it is none of the `reserved` paths (the run's input files, and
/// folders whose contents it must not land in, flagged `true`), its folder exists and
/// takes files, and an existing file is one Flapwright wrote (`is_ours` on its text)
/// unless `force`. Returns true when `force` lets it replace a file Flapwright did not
/// write (the caller says so).
pub fn check_writable_file(
    option: &'static str,
    path: &Path,
    reserved: &[(PathBuf, String, bool)],
    force: bool,
    is_ours: impl Fn(&str) -> bool,
) -> Result<bool, OutputError> {
    if path.is_dir() {
        return Err(OutputError::Unwritable {
            path: path.to_path_buf(),
            reason: "it is a folder".into(),
        });
    }
    let target = absolute(path);
    for (reserved_path, what, is_folder) in reserved {
        let reserved_abs = absolute(reserved_path);
        if target == reserved_abs || (*is_folder && target.starts_with(&reserved_abs)) {
            return Err(OutputError::ReservedFile {
                option,
                path: path.to_path_buf(),
                what: what.clone(),
            });
        }
    }
    let mut replaces_foreign = false;
    if path.exists() {
        let ours = fs::read_to_string(path).map(|text| is_ours(&text)).unwrap_or(false);
        if !ours && !force {
            return Err(OutputError::ForeignFile {
                option,
                path: path.to_path_buf(),
            });
        }
        replaces_foreign = !ours;
    }
    let probe = parent_of(path).join(format!(".{}.probe-{}", folder_name(path), run_tag()));
    match fs::write(&probe, b"") {
        Ok(()) => {
            let _ = fs::remove_file(&probe);
            Ok(replaces_foreign)
        }
        Err(e) => Err(OutputError::Unwritable {
            path: path.to_path_buf(),
            reason: e.to_string(),
        }),
    }
}

/// Writes `contents` to `path` through a temporary file and a rename, so a reader never
/// sees half a file; the temporary file is removed when any step fails (a full disk).
pub fn write_file_atomically(path: &Path, contents: &[u8]) -> io::Result<()> {
    write_atomically_with(path, |file| file.write_all(contents))
}

/// As [`write_file_atomically`], the contents written by `write`.
fn write_atomically_with(path: &Path, write: impl FnOnce(&mut fs::File) -> io::Result<()>) -> io::Result<()> {
    let temporary = parent_of(path).join(format!(".{}.partial-{}", folder_name(path), run_tag()));
    let mut file = fs::File::create_new(&temporary)?;
    let written = write(&mut file).and_then(|()| file.sync_all());
    drop(file);
    let result = written.and_then(|()| fs::rename(&temporary, path));
    if result.is_err() {
        let _ = fs::remove_file(&temporary);
    }
    result
}

/// `--out` resolved once: absolute, `.` and `..` taken out, symbolic links followed (as far
/// as the path exists; below that, `..` drops the name before it).
pub fn resolve_out(path: &Path) -> Result<PathBuf, OutputError> {
    resolve(path).map_err(|e| OutputError::Unwritable {
        path: path.to_path_buf(),
        reason: e.to_string(),
    })
}

fn resolve(path: &Path) -> io::Result<PathBuf> {
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
fn refuse_working_folder(target: &Path) -> Result<(), OutputError> {
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
fn refuse_read_only(target: &Path) -> Result<(), OutputError> {
    match read_only_folder(target)? {
        Some(read_only) => Err(OutputError::ReadOnly {
            folder: target.to_path_buf(),
            read_only,
        }),
        None => Ok(()),
    }
}

/// The first folder in `folder` (itself included) that no one may write to.
fn read_only_folder(folder: &Path) -> io::Result<Option<PathBuf>> {
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
fn refuse_scene_folder(target: &Path, scene: &Path) -> Result<(), OutputError> {
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
fn absolute(path: &Path) -> PathBuf {
    resolve(path).unwrap_or_else(|_| path.to_path_buf())
}

fn parent_of(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

fn folder_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "flapwright-out".into())
}

/// Checks that `target` may be replaced: absent, empty, or every file in it recorded in
/// its manifest and unchanged, and no folder in it read-only. Returns the foreign files
/// (only with `force`, which allows them).
fn check_replaceable(target: &Path, force: bool) -> Result<Vec<PathBuf>, OutputError> {
    let meta = match fs::symlink_metadata(target) {
        Ok(meta) => meta,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(e.into()),
    };
    if !meta.is_dir() {
        return Err(OutputError::NotAFolder(target.to_path_buf()));
    }
    refuse_read_only(target)?;
    let foreign = foreign_files(target)?;
    if foreign.is_empty() || force {
        Ok(foreign)
    } else {
        Err(OutputError::Foreign {
            folder: target.to_path_buf(),
            files: foreign,
        })
    }
}

/// Files (and links, and other entries) in `folder` that its manifest does not vouch for.
fn foreign_files(folder: &Path) -> io::Result<Vec<PathBuf>> {
    let manifest: Option<Manifest> = fs::read_to_string(folder.join(MANIFEST))
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok());
    let mut entries = Vec::new();
    list_entries(folder, Path::new(""), &mut entries)?;
    let mut foreign = Vec::new();
    for (relative, meta) in entries {
        if relative == Path::new(MANIFEST) && manifest.is_some() {
            continue;
        }
        if meta.is_dir() {
            // A folder is vouched for by the files in it; an empty one is harmless.
            continue;
        }
        let vouched = meta.is_file()
            && manifest.as_ref().is_some_and(|m| {
                m.files.iter().any(|entry| {
                    Path::new(&entry.path) == relative
                        && entry.bytes == meta.len()
                        && hash_file(&folder.join(&relative)).is_ok_and(|h| h == entry.sha256)
                })
            });
        if !vouched {
            foreign.push(relative);
        }
    }
    foreign.sort();
    Ok(foreign)
}

/// Every entry below `folder` (not following links), with paths relative to it.
fn list_entries(folder: &Path, relative: &Path, out: &mut Vec<(PathBuf, fs::Metadata)>) -> io::Result<()> {
    for entry in fs::read_dir(folder.join(relative))? {
        let entry = entry?;
        let path = relative.join(entry.file_name());
        let meta = fs::symlink_metadata(entry.path())?;
        if meta.is_dir() {
            list_entries(folder, &path, out)?;
        }
        out.push((path, meta));
    }
    Ok(())
}

fn hash_file(path: &Path) -> io::Result<String> {
    let bytes = fs::read(path)?;
    Ok(hex(&Sha256::digest(bytes)))
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// Records every file in `folder` (sorted, so the manifest is the same for the same
/// outputs).
fn write_manifest(folder: &Path) -> io::Result<()> {
    let mut entries = Vec::new();
    list_entries(folder, Path::new(""), &mut entries)?;
    let mut files = Vec::new();
    for (relative, meta) in entries {
        if meta.is_file() {
            files.push(ManifestEntry {
                path: relative.to_string_lossy().replace('\\', "/"),
                bytes: meta.len(),
                sha256: hash_file(&folder.join(&relative))?,
            });
        }
    }
    files.sort_by(|a, b| a.path.cmp(&b.path));
    let manifest = Manifest {
        written_by: "flapwright".into(),
        files,
    };
    let json = serde_json::to_string_pretty(&manifest).map_err(io::Error::other)?;
    fs::write(folder.join(MANIFEST), json + "\n")
}

/// Removes staging and backup folders of earlier runs to `name` whose process is gone.
/// Only names Flapwright makes (`.<name>.partial-<pid>-...`, `.<name>.old-<pid>-...`, and the
/// `.<name>.partial-<pid>` / `.<name>.old` of earlier versions) are considered.
fn clean_leftovers(parent: &Path, name: &str) {
    let Ok(entries) = fs::read_dir(parent) else { return };
    for entry in entries.flatten() {
        let file_name = entry.file_name().to_string_lossy().into_owned();
        let Some(rest) = file_name.strip_prefix(&format!(".{name}.")) else {
            continue;
        };
        let pid = if rest == "old" {
            None
        } else if let Some(tag) = rest.strip_prefix("partial-").or_else(|| rest.strip_prefix("old-")) {
            match tag.split('-').next().and_then(|p| p.parse::<u32>().ok()) {
                Some(pid) => Some(pid),
                None => continue,
            }
        } else {
            continue;
        };
        if pid.is_some_and(process_is_running) {
            continue;
        }
        let _ = fs::remove_dir_all(entry.path());
    }
}

/// Whether process `pid` still runs (Linux: `/proc/<pid>`; elsewhere assumed running, so
/// nothing of a live run is ever removed).
fn process_is_running(pid: u32) -> bool {
    if pid == std::process::id() {
        return true;
    }
    if Path::new("/proc/self").exists() {
        Path::new(&format!("/proc/{pid}")).exists()
    } else {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn staged_run(target: &Path, force: bool, files: &[(&str, &str)]) -> Result<(PathBuf, Vec<PathBuf>), OutputError> {
        let staged = StagedDir::create(target, None, force)?;
        for (name, text) in files {
            fs::write(staged.file(name), text).unwrap();
        }
        staged.commit()
    }

    fn names_in(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn an_output_is_replaced_only_while_its_manifest_vouches_for_every_file() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        staged_run(&out, false, &[("report.json", "{}")]).unwrap();
        staged_run(&out, false, &[("report.json", "{\"a\": 1}")]).unwrap();
        // A file the user added.
        fs::write(out.join("notes.txt"), "mine").unwrap();
        let Err(OutputError::Foreign { files, .. }) = staged_run(&out, false, &[("report.json", "{}")]) else {
            panic!("a foreign file must stop the run");
        };
        assert_eq!(files, [PathBuf::from("notes.txt")]);
        assert_eq!(fs::read_to_string(out.join("notes.txt")).unwrap(), "mine");
        // A file of ours the user edited.
        fs::remove_file(out.join("notes.txt")).unwrap();
        fs::write(out.join("report.json"), "edited").unwrap();
        assert!(matches!(
            staged_run(&out, false, &[("report.json", "{}")]),
            Err(OutputError::Foreign { .. })
        ));
        let (_, removed) = staged_run(&out, true, &[("report.json", "{}")]).unwrap();
        assert_eq!(removed, [PathBuf::from("report.json")]);
    }

    #[test]
    fn leftovers_of_dead_runs_are_cleaned_and_live_ones_kept() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        // pid 0 is never a user process: a dead run.
        for name in [".out.old", ".out.partial-0", ".out.old-0-5", ".out.partial-0-7"] {
            fs::create_dir(dir.path().join(name)).unwrap();
        }
        let live = format!(".out.partial-{}-1", std::process::id());
        fs::create_dir(dir.path().join(&live)).unwrap();
        fs::create_dir(dir.path().join(".out.unrelated")).unwrap();
        staged_run(&out, false, &[("report.json", "{}")]).unwrap();
        let mut left: Vec<String> = fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        left.sort();
        assert_eq!(left, [live.as_str(), ".out.unrelated", "out"]);
    }

    /// Issue 35 item 12: a write that fails half-way (a full disk) leaves no temporary file,
    /// and the file it was to replace as it was.
    #[test]
    fn a_failed_write_leaves_no_partial_file() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("j.xml");
        fs::write(&path, "earlier").unwrap();
        let failed = write_atomically_with(&path, |file| {
            file.write_all(b"<testsuites")?;
            Err(io::Error::new(io::ErrorKind::StorageFull, "no space left on device"))
        });
        assert!(failed.is_err());
        assert_eq!(names_in(dir.path()), ["j.xml"]);
        assert_eq!(fs::read_to_string(&path).unwrap(), "earlier");
        write_file_atomically(&path, b"later").unwrap();
        assert_eq!(names_in(dir.path()), ["j.xml"]);
        assert_eq!(fs::read_to_string(&path).unwrap(), "later");
    }

    /// Issue 35 item 10: `.` and `..` are taken out once, links followed.
    #[test]
    fn out_is_resolved_without_dots() {
        let dir = tempfile::tempdir().unwrap();
        let root = fs::canonicalize(dir.path()).unwrap();
        fs::create_dir(root.join("out")).unwrap();
        for spelled in ["out/../out", "out/.", "./out", "missing/../out", "out/missing/.."] {
            assert_eq!(resolve(&root.join(spelled)).unwrap(), root.join("out"), "{spelled}");
        }
        assert_eq!(resolve(&root.join("a/b/../c/.")).unwrap(), root.join("a/c"));
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(root.join("out"), root.join("link")).unwrap();
            assert_eq!(resolve(&root.join("link/.")).unwrap(), root.join("out"));
            std::os::unix::fs::symlink(root.join("nowhere"), root.join("dangling")).unwrap();
            assert!(resolve(&root.join("dangling")).is_err());
        }
    }

    /// Issue 35 item 12: an earlier output with a read-only folder is refused, left as it was.
    #[cfg(unix)]
    #[test]
    fn a_read_only_output_is_refused() {
        use std::os::unix::fs::PermissionsExt;
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        staged_run(&out, false, &[("report.json", "{}")]).unwrap();
        fs::set_permissions(&out, fs::Permissions::from_mode(0o555)).unwrap();
        let refused = staged_run(&out, false, &[("report.json", "{}")]);
        fs::set_permissions(&out, fs::Permissions::from_mode(0o755)).unwrap();
        assert!(matches!(refused, Err(OutputError::ReadOnly { .. })), "{refused:?}");
        assert_eq!(names_in(dir.path()), ["out"]);
    }
}
