//! Output folders a user can trust: a failed run never leaves a half-written result, and
//! no run deletes or overwrites a file Flapwright did not write.
//!
//! The guarantees (`docs/commands.md`, "Output folders", repeats them):
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
//! - A run writes into a staging folder beside `--out` (`.<out>.partial-<tag>`) and moves it
//!   into place only when it succeeds: the earlier output is renamed to `.<out>.old-<tag>`,
//!   the staging folder to `--out`, and the earlier output is then removed, its manifest
//!   last: a removal that stops half-way (an immutable file) leaves a folder its manifest
//!   still vouches for, which a later run removes once it can.
//! - Every output folder holds a manifest ([`MANIFEST`]): each file written, with its size
//!   and SHA-256. An existing `--out` is replaced only when it is empty or when every file
//!   in it is in its manifest, unchanged (checked before any work, and again on the earlier
//!   output once it is renamed aside, where nothing can write into it by its name);
//!   otherwise the run refuses with the foreign files named ([`OutputError::Foreign`]) and
//!   puts it back, unless `--force` is given, which removes them and says so.
//! - An earlier output with a read-only folder in it (the user protected it) is never
//!   replaced, not even with `--force` ([`OutputError::ReadOnly`], before any work): removing
//!   it would stop half-way on a read-only folder and leave a hidden backup behind.
//! - Each run records itself beside `--out` in a marker file, `.<out>.run-<tag>.json`: the
//!   resolved `--out`, its process id and that process's start time, and whether it was
//!   forced; `<tag>` (process id, clock and a count) names its staging and backup folders.
//!   The marker is written before either folder exists and removed once both are gone (a
//!   backup that could not be removed keeps its marker). A later run acts only on folders a
//!   marker for the same `--out` vouches for, and only once the marker's process is gone (no
//!   process with that id and start time): names alone prove nothing, so a user's
//!   `.out.old` or `.out.old-2024-01-05` is never touched.
//! - The next run to the same `--out` finishes what a killed run left: its staging folder
//!   is removed; its backup (the earlier output) is put back at `--out` when `--out` is
//!   missing (a kill between the two renames), and otherwise kept until the new output is
//!   in place, then removed only when its manifest vouches for every file in it (or the
//!   killed run had `--force`). A backup that is kept, or cannot be removed, keeps its
//!   marker and is named in a warning ([`Committed::notices`]) by every later run that
//!   completes, until the user deals with it; an earlier output put back is named too.
//! - Without `/proc` (not Linux), every marked run counts as running: its leftovers are
//!   kept, never removed (nor put back).
//! - A temporary file that a killed run leaves beside a `--junit` file is not removed.
//! - A single file (`--junit`) is written to a temporary file beside it and renamed into
//!   place; the temporary file is removed when any step fails (a full disk).
//!
//! Test hook: with the environment variable [`TEST_EXIT_AT`] set to `staged` (the staging
//! folder made), `between-renames` or `after-renames`, a run ends at that point at once,
//! with no clean-up, as `kill -9` would end it; the end-to-end tests use it.

use std::fs;
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{SystemTime, UNIX_EPOCH};

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};

/// Name of the manifest inside every output folder.
pub const MANIFEST: &str = ".flapwright-manifest.json";

/// The test hook's environment variable (see the module docs).
pub const TEST_EXIT_AT: &str = "FLAPWRIGHT_TEST_EXIT_AT";

/// What a run's marker and a manifest say wrote them.
const WRITTEN_BY: &str = "flapwright";

mod paths;
#[cfg(test)]
use paths::resolve;
pub use paths::resolve_out;
use paths::{absolute, folder_name, parent_of, refuse_read_only, refuse_scene_folder, refuse_working_folder};

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

/// Ends the process at once when the test hook names `point` (see the module docs).
fn test_exit_point(point: &str) {
    if std::env::var_os(TEST_EXIT_AT).is_some_and(|value| value == point) {
        std::process::exit(137);
    }
}

/// What a run records of itself beside `--out` (`.<out>.run-<tag>.json`).
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq, Eq)]
struct RunMarker {
    written_by: String,
    /// The resolved `--out` (as text: a name that is not UTF-8 is written lossily, and
    /// compared the same way).
    out: String,
    /// Names the run's staging and backup folders.
    tag: String,
    pid: u32,
    /// The process's start time (clock ticks after boot, `/proc/<pid>/stat`), so that a
    /// later process with the same id is not taken for this one.
    process_start: Option<u64>,
    /// When the run started, nanoseconds after the Unix epoch.
    started_unix_nanos: u64,
    /// The run had `--force`: its backup may hold files the user let it remove.
    force: bool,
}

/// The paths one run uses beside `--out`.
#[derive(Debug, Clone)]
struct RunPaths {
    marker: PathBuf,
    staging: PathBuf,
    backup: PathBuf,
}

impl RunPaths {
    fn new(parent: &Path, name: &str, tag: &str) -> Self {
        Self {
            marker: parent.join(format!(".{name}.run-{tag}.json")),
            staging: parent.join(format!(".{name}.partial-{tag}")),
            backup: parent.join(format!(".{name}.old-{tag}")),
        }
    }
}

/// What a commit did: the output folder, the foreign files `--force` removed, and what the
/// user should hear about leftovers of earlier runs.
#[derive(Debug)]
pub struct Committed {
    /// The output folder (resolved).
    pub folder: PathBuf,
    /// Files a forced commit removed, relative to the folder.
    pub removed: Vec<PathBuf>,
    /// Warnings: an earlier output put back, a backup kept or not removable.
    pub notices: Vec<String>,
}

/// A folder being written beside its final place; [`StagedDir::commit`] moves it there.
#[derive(Debug)]
pub struct StagedDir {
    target: PathBuf,
    paths: RunPaths,
    force: bool,
    /// Backups left by killed runs, to remove once this run's output is in place.
    superseded: Vec<(RunMarker, RunPaths)>,
    notices: Vec<String>,
}

fn nanos_now() -> u64 {
    SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| u64::try_from(d.as_nanos()).unwrap_or(u64::MAX))
}

/// A name unique to this run: process id, the clock's nanoseconds and a count (a study
/// makes several outputs at once in one process).
fn run_tag() -> String {
    static COUNT: AtomicU64 = AtomicU64::new(0);
    let count = COUNT.fetch_add(1, Ordering::Relaxed);
    format!("{}-{}-{count}", std::process::id(), nanos_now())
}

fn exists(path: &Path) -> bool {
    fs::symlink_metadata(path).is_ok()
}

impl StagedDir {
    /// Resolves `target` (see [`resolve_out`]), checks that it may become an output (see the
    /// module docs), finishes what killed runs to it left, and creates an empty staging
    /// folder beside it. `scene` is the scene file, if any. With `force`, foreign files in
    /// `target` are replaced at commit.
    pub fn create(target: &Path, scene: Option<&Path>, force: bool) -> Result<Self, OutputError> {
        let target = resolve_out(target)?;
        if let Some(scene) = scene {
            refuse_scene_folder(&target, scene)?;
        }
        refuse_working_folder(&target)?;
        let (parent, name) = match (target.parent(), target.file_name()) {
            (Some(parent), Some(name)) => (parent.to_path_buf(), name.to_string_lossy().into_owned()),
            _ => return Err(OutputError::ContainsWorkingFolder { folder: target }),
        };
        fs::create_dir_all(&parent).map_err(|e| OutputError::Unwritable {
            path: parent.clone(),
            reason: e.to_string(),
        })?;
        let tag = run_tag();
        let paths = RunPaths::new(&parent, &name, &tag);
        let pid = std::process::id();
        let marker = RunMarker {
            written_by: WRITTEN_BY.into(),
            out: target.to_string_lossy().into_owned(),
            tag,
            pid,
            process_start: process_state(pid).map(|(_, start)| start),
            started_unix_nanos: nanos_now(),
            force,
        };
        let json = serde_json::to_string_pretty(&marker).map_err(io::Error::other)?;
        fs::File::create_new(&paths.marker)
            .and_then(|mut file| file.write_all(json.as_bytes()))
            .map_err(|e| OutputError::Unwritable {
                path: paths.marker.clone(),
                reason: e.to_string(),
            })?;
        // From here on, dropping `staged` removes what this run made.
        let mut staged = Self {
            target,
            paths,
            force,
            superseded: Vec::new(),
            notices: Vec::new(),
        };
        staged.recover(&parent, &name)?;
        check_replaceable(&staged.target, force)?;
        fs::create_dir(&staged.paths.staging).map_err(|e| OutputError::Unwritable {
            path: staged.paths.staging.clone(),
            reason: e.to_string(),
        })?;
        test_exit_point("staged");
        Ok(staged)
    }

    /// The output folder, resolved.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// Path of a file inside the staging folder.
    pub fn file(&self, name: &str) -> PathBuf {
        self.paths.staging.join(name)
    }

    /// Warnings so far (an earlier output put back); [`StagedDir::commit`] returns the rest.
    pub fn take_notices(&mut self) -> Vec<String> {
        std::mem::take(&mut self.notices)
    }

    /// Finishes what killed runs to this `--out` left (see the module docs): their staging
    /// folders are removed, the newest backup is put back when `--out` is missing, and the
    /// other backups are kept for [`StagedDir::commit`].
    fn recover(&mut self, parent: &Path, name: &str) -> Result<(), OutputError> {
        let mut dead = dead_runs(parent, name, &self.target);
        // Newest first: the backup put back is the latest earlier output.
        dead.sort_by_key(|run| std::cmp::Reverse(run.0.started_unix_nanos));
        for (marker, paths) in dead {
            if exists(&paths.staging) {
                if let Err(error) = fs::remove_dir_all(&paths.staging) {
                    self.notices.push(format!(
                        "could not remove {}, the staging folder of an interrupted run ({error}); later runs try again",
                        paths.staging.display()
                    ));
                    continue;
                }
            }
            if !exists(&paths.backup) {
                let _ = fs::remove_file(&paths.marker);
            } else if !exists(&self.target) {
                fs::rename(&paths.backup, &self.target).map_err(|e| {
                    io::Error::new(
                        e.kind(),
                        format!(
                            "putting back the earlier output, which an interrupted run moved aside to {}: {e}",
                            paths.backup.display()
                        ),
                    )
                })?;
                let _ = fs::remove_file(&paths.marker);
                self.notices.push(format!(
                    "put back the earlier output at {}: an interrupted run (process {}) had moved it aside",
                    self.target.display(),
                    marker.pid
                ));
            } else {
                self.superseded.push((marker, paths));
            }
        }
        Ok(())
    }

    /// Writes the manifest and replaces `target` with the staged folder.
    pub fn commit(mut self) -> Result<Committed, OutputError> {
        write_manifest(&self.paths.staging)?;
        let removed = match fs::symlink_metadata(&self.target) {
            Err(e) if e.kind() == io::ErrorKind::NotFound => {
                fs::rename(&self.paths.staging, &self.target)?;
                Vec::new()
            }
            Err(e) => return Err(e.into()),
            Ok(meta) if !meta.is_dir() => return Err(OutputError::NotAFolder(self.target.clone())),
            Ok(_) => self.replace()?,
        };
        self.remove_superseded();
        if !exists(&self.paths.backup) {
            let _ = fs::remove_file(&self.paths.marker);
        }
        Ok(Committed {
            folder: self.target.clone(),
            removed,
            notices: std::mem::take(&mut self.notices),
        })
    }

    /// The two renames over an existing output, and the earlier output's removal. Returns
    /// the foreign files `--force` removed.
    fn replace(&mut self) -> Result<Vec<PathBuf>, OutputError> {
        refuse_read_only(&self.target)?;
        let backup = self.paths.backup.clone();
        fs::rename(&self.target, &backup)?;
        test_exit_point("between-renames");
        // Checked again on the moved folder, where nothing writes by its name any more.
        let foreign = match foreign_files(&backup) {
            Ok(foreign) => foreign,
            Err(error) => {
                self.put_back()?;
                return Err(error.into());
            }
        };
        if !foreign.is_empty() && !self.force {
            self.put_back()?;
            return Err(OutputError::Foreign {
                folder: self.target.clone(),
                files: foreign,
            });
        }
        if let Err(error) = fs::rename(&self.paths.staging, &self.target) {
            self.put_back()?;
            return Err(error.into());
        }
        test_exit_point("after-renames");
        if let Err(error) = remove_output(&backup) {
            self.notices.push(format!(
                "the new output is in place, but the earlier one could not be removed ({error}): it is kept as {}; later runs to this --out try again",
                backup.display()
            ));
        }
        Ok(foreign)
    }

    /// Moves the earlier output back to `target` (a commit that cannot go on). When this
    /// fails, the marker stays, and the next run puts it back.
    fn put_back(&self) -> Result<(), OutputError> {
        fs::rename(&self.paths.backup, &self.target).map_err(|e| {
            OutputError::Io(io::Error::new(
                e.kind(),
                format!(
                    "putting the earlier output back from {}: {e}; the next run to this --out does",
                    self.paths.backup.display()
                ),
            ))
        })
    }

    /// Removes the backups of killed runs now that this run's output is in place, when
    /// their manifests vouch for every file in them (or the run was forced); keeps and names
    /// the others.
    fn remove_superseded(&mut self) {
        for (marker, paths) in std::mem::take(&mut self.superseded) {
            if !exists(&paths.backup) {
                let _ = fs::remove_file(&paths.marker);
                continue;
            }
            match foreign_files(&paths.backup) {
                Ok(foreign) if foreign.is_empty() || marker.force => match remove_output(&paths.backup) {
                    Ok(()) => {
                        let _ = fs::remove_file(&paths.marker);
                    }
                    Err(error) => self.notices.push(format!(
                        "could not remove {}, an earlier output a run moved aside ({error}); later runs try again",
                        paths.backup.display()
                    )),
                },
                Ok(foreign) => self.notices.push(format!(
                    "kept {}, an earlier output a run moved aside: it holds {} file(s) Flapwright did not write ({}); move what you need out of it, then delete it",
                    paths.backup.display(),
                    foreign.len(),
                    foreign
                        .iter()
                        .take(10)
                        .map(|p| p.display().to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                )),
                Err(error) => self.notices.push(format!(
                    "kept {}, an earlier output a run moved aside: it cannot be read ({error})",
                    paths.backup.display()
                )),
            }
        }
    }
}

/// A plain file name: no folders, not `.` or `..` (the library names every file it writes).
fn plain_name(name: &str) -> io::Result<&str> {
    if name.is_empty() || name == "." || name == ".." || name.contains(['/', '\\']) {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{name:?} is not a plain file name"),
        ));
    }
    Ok(name)
}

impl flapwright::Sink for StagedDir {
    fn write(&self, name: &str, bytes: &[u8]) -> io::Result<()> {
        fs::write(self.file(plain_name(name)?), bytes)
    }

    /// The folder and its manifest, or nothing when a write fails.
    fn write_folder(&self, name: &str, files: &flapwright::MemorySink) -> io::Result<()> {
        let folder = self.file(plain_name(name)?);
        fs::create_dir(&folder)?;
        let written = files
            .files()
            .iter()
            .try_for_each(|(file, bytes)| fs::write(folder.join(plain_name(file)?), bytes))
            .and_then(|()| write_manifest(&folder));
        if written.is_err() {
            let _ = fs::remove_dir_all(&folder);
        }
        written
    }
}

impl Drop for StagedDir {
    fn drop(&mut self) {
        // Reached with the staging folder still present only when the run failed.
        if exists(&self.paths.staging) {
            let _ = fs::remove_dir_all(&self.paths.staging);
        }
        // A backup still present is the earlier output: its marker lets the next run put it
        // back or remove it.
        if !exists(&self.paths.backup) {
            let _ = fs::remove_file(&self.paths.marker);
        }
    }
}

/// Removes an earlier output folder, its manifest last: when the removal stops half-way
/// (an immutable file), what is left is still vouched for, and a later run removes it.
fn remove_output(folder: &Path) -> io::Result<()> {
    for entry in fs::read_dir(folder)? {
        let entry = entry?;
        if entry.file_name() == MANIFEST {
            continue;
        }
        if entry.file_type()?.is_dir() {
            fs::remove_dir_all(entry.path())?;
        } else {
            fs::remove_file(entry.path())?;
        }
    }
    match fs::remove_file(folder.join(MANIFEST)) {
        Err(e) if e.kind() != io::ErrorKind::NotFound => return Err(e),
        _ => {}
    }
    fs::remove_dir(folder)
}

/// The runs to `target` (folder `name` in `parent`) whose markers verify and whose process
/// is gone.
fn dead_runs(parent: &Path, name: &str, target: &Path) -> Vec<(RunMarker, RunPaths)> {
    let Ok(entries) = fs::read_dir(parent) else {
        return Vec::new();
    };
    let prefix = format!(".{name}.run-");
    let mut dead = Vec::new();
    for entry in entries.flatten() {
        let file_name = entry.file_name().to_string_lossy().into_owned();
        let Some(tag) = file_name
            .strip_prefix(&prefix)
            .and_then(|rest| rest.strip_suffix(".json"))
        else {
            continue;
        };
        let Some(marker) = fs::read_to_string(entry.path())
            .ok()
            .and_then(|text| serde_json::from_str::<RunMarker>(&text).ok())
        else {
            continue;
        };
        if marker.written_by != WRITTEN_BY || marker.tag != tag || marker.out != target.to_string_lossy() {
            continue;
        }
        if owner_is_running(marker.pid, marker.process_start) {
            continue;
        }
        dead.push((marker, RunPaths::new(parent, name, tag)));
    }
    dead
}

/// Whether the process that wrote a marker still runs: a process `pid` that started at
/// `start` (Linux: `/proc/<pid>/stat`; elsewhere assumed running, so nothing of a live run
/// is ever removed).
fn owner_is_running(pid: u32, start: Option<u64>) -> bool {
    if !Path::new("/proc/self/stat").exists() {
        return true;
    }
    match process_state(pid) {
        // A process we cannot read (another user's, behind `hidepid`) may be the one.
        None => Path::new(&format!("/proc/{pid}")).exists(),
        Some((state, started)) => !matches!(state, 'Z' | 'X') && start.is_none_or(|s| s == started),
    }
}

/// A process's state letter and start time (clock ticks after boot), from
/// `/proc/<pid>/stat`: the fields after the command name's closing parenthesis, the state
/// the 3rd field of the line and the start time the 22nd.
fn process_state(pid: u32) -> Option<(char, u64)> {
    let stat = fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    let fields: Vec<&str> = stat.get(stat.rfind(')')? + 1..)?.split_whitespace().collect();
    let state = fields.first()?.chars().next()?;
    let start = fields.get(19)?.parse().ok()?;
    Some((state, start))
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
        written_by: WRITTEN_BY.into(),
        files,
    };
    let json = serde_json::to_string_pretty(&manifest).map_err(io::Error::other)?;
    fs::write(folder.join(MANIFEST), json + "\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn staged_run(target: &Path, force: bool, files: &[(&str, &str)]) -> Result<Committed, OutputError> {
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

    /// What a run to `target` killed at once leaves: its marker, naming a process that is
    /// gone (no process has the id `u32::MAX`).
    fn killed_run(target: &Path, tag: &str, force: bool) -> RunPaths {
        let target = resolve(target).unwrap();
        let name = target.file_name().unwrap().to_string_lossy().into_owned();
        let paths = RunPaths::new(target.parent().unwrap(), &name, tag);
        let marker = RunMarker {
            written_by: WRITTEN_BY.into(),
            out: target.to_string_lossy().into_owned(),
            tag: tag.into(),
            pid: u32::MAX,
            process_start: Some(1),
            started_unix_nanos: tag.len() as u64,
            force,
        };
        fs::write(&paths.marker, serde_json::to_string(&marker).unwrap()).unwrap();
        paths
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
        let committed = staged_run(&out, true, &[("report.json", "{}")]).unwrap();
        assert_eq!(committed.removed, [PathBuf::from("report.json")]);
        assert_eq!(names_in(dir.path()), ["out"]);
    }

    #[test]
    fn a_file_added_while_the_run_works_is_found_on_the_moved_folder_and_put_back() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        staged_run(&out, false, &[("report.json", "{}")]).unwrap();
        let staged = StagedDir::create(&out, None, false).unwrap();
        fs::write(staged.file("report.json"), "{}").unwrap();
        fs::write(out.join("notes.txt"), "mine").unwrap();
        assert!(matches!(staged.commit(), Err(OutputError::Foreign { .. })));
        assert_eq!(fs::read_to_string(out.join("notes.txt")).unwrap(), "mine");
        assert_eq!(names_in(dir.path()), ["out"]);
    }

    /// Issue 35 item 9: only folders a verified marker of a dead run vouches for are removed.
    #[test]
    fn leftovers_of_dead_runs_are_cleaned_and_everything_else_kept() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        staged_run(&out, false, &[("report.json", "{}")]).unwrap();
        // A killed run's staging folder, and one killed after its renames (the earlier
        // output, ours, still beside the new one).
        let staging = killed_run(&out, "0-1-0", false);
        fs::create_dir(&staging.staging).unwrap();
        fs::write(staging.staging.join("report.json"), "half").unwrap();
        let renamed = killed_run(&out, "0-2-0", false);
        staged_run(&dir.path().join("earlier"), false, &[("report.json", "{}")]).unwrap();
        fs::rename(dir.path().join("earlier"), &renamed.backup).unwrap();
        // A live run's (this process's) marker and staging folder.
        let live = StagedDir::create(&out, None, false).unwrap();
        // The user's folders with names like ours, and a marker for another --out.
        let mine = [
            ".out.old",
            ".out.old-2024-01-05",
            ".out.old-0-5",
            ".out.partial-0-7",
            ".out.old-0-3-0",
        ];
        for name in mine {
            fs::create_dir(dir.path().join(name)).unwrap();
        }
        fs::create_dir(dir.path().join("elsewhere")).unwrap();
        let other = killed_run(&dir.path().join("elsewhere/out"), "0-3-0", false);
        fs::rename(&other.marker, dir.path().join(".out.run-0-3-0.json")).unwrap();
        staged_run(&out, false, &[("report.json", "{\"b\": 1}")]).unwrap();
        let mut expected: Vec<String> = mine.iter().map(|n| n.to_string()).collect();
        expected.extend([".out.run-0-3-0.json".into(), "elsewhere".into(), "out".into()]);
        for path in [&live.paths.marker, &live.paths.staging] {
            expected.push(path.file_name().unwrap().to_string_lossy().into_owned());
        }
        expected.sort();
        assert_eq!(names_in(dir.path()), expected);
        drop(live);
    }

    /// Issue 35 item 11: the earlier output a run killed between its renames moved aside is
    /// put back by the next run, even when that one fails.
    #[test]
    fn an_earlier_output_moved_aside_by_a_killed_run_is_put_back() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        staged_run(&out, false, &[("report.json", "earlier")]).unwrap();
        let killed = killed_run(&out, "0-1-0", false);
        fs::create_dir(&killed.staging).unwrap();
        fs::rename(&out, &killed.backup).unwrap();
        let mut staged = StagedDir::create(&out, None, false).unwrap();
        assert_eq!(fs::read_to_string(out.join("report.json")).unwrap(), "earlier");
        assert_eq!(staged.take_notices().len(), 1);
        drop(staged);
        assert_eq!(names_in(dir.path()), ["out"]);
        assert_eq!(fs::read_to_string(out.join("report.json")).unwrap(), "earlier");
    }

    /// Issue 35 item 11: a killed run's backup beside an existing output is kept until a new
    /// output is in place, and then removed only when its manifest vouches for it.
    #[test]
    fn a_backup_holding_a_users_file_is_kept_and_named() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        staged_run(&out, false, &[("report.json", "{}")]).unwrap();
        let killed = killed_run(&out, "0-1-0", false);
        staged_run(&dir.path().join("earlier"), false, &[("report.json", "{}")]).unwrap();
        fs::write(dir.path().join("earlier/notes.txt"), "mine").unwrap();
        fs::rename(dir.path().join("earlier"), &killed.backup).unwrap();
        // A failed run keeps it.
        drop(StagedDir::create(&out, None, false).unwrap());
        assert!(killed.backup.join("notes.txt").exists());
        let committed = staged_run(&out, false, &[("report.json", "{}")]).unwrap();
        assert!(
            committed.notices.iter().any(|n| n.contains("notes.txt")),
            "{:?}",
            committed.notices
        );
        assert_eq!(fs::read_to_string(killed.backup.join("notes.txt")).unwrap(), "mine");
        // Still recognised: once the user has taken the file out, a run removes it.
        fs::remove_file(killed.backup.join("notes.txt")).unwrap();
        staged_run(&out, false, &[("report.json", "{}")]).unwrap();
        assert_eq!(names_in(dir.path()), ["out"]);
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

    /// An earlier output whose removal stopped half-way (an immutable file, `chattr +i`) is
    /// still vouched for by its manifest, which goes last, so a later run removes it once it
    /// can. Runs only where `chattr +i` works (root on ext4).
    #[cfg(unix)]
    #[test]
    fn a_backup_whose_removal_stopped_half_way_is_removed_later() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        staged_run(
            &out,
            false,
            &[("a.json", "{}"), ("report.json", "{}"), ("z.json", "{}")],
        )
        .unwrap();
        let chattr = |flag: &str, path: &Path| {
            std::process::Command::new("chattr")
                .arg(flag)
                .arg(path)
                .output()
                .is_ok_and(|o| o.status.success())
        };
        if !chattr("+i", &out.join("report.json")) {
            return;
        }
        let committed = staged_run(&out, false, &[("report.json", "{}")]);
        let backups: Vec<PathBuf> = fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.file_name().unwrap().to_string_lossy().starts_with(".out.old-"))
            .collect();
        for backup in &backups {
            chattr("-i", &backup.join("report.json"));
        }
        chattr("-i", &out.join("report.json"));
        let committed = committed.unwrap();
        assert_eq!(backups.len(), 1, "{:?}", names_in(dir.path()));
        assert!(
            committed.notices.iter().any(|n| n.contains("could not be removed")),
            "{:?}",
            committed.notices
        );
        // As if the run that left it had ended (this process still runs).
        for entry in fs::read_dir(dir.path()).unwrap() {
            let path = entry.unwrap().path();
            if path.to_string_lossy().ends_with(".json") {
                let mut marker: RunMarker = serde_json::from_str(&fs::read_to_string(&path).unwrap()).unwrap();
                marker.pid = u32::MAX;
                fs::write(&path, serde_json::to_string(&marker).unwrap()).unwrap();
            }
        }
        let committed = staged_run(&out, false, &[("report.json", "{}")]).unwrap();
        assert!(committed.notices.is_empty(), "{:?}", committed.notices);
        assert_eq!(names_in(dir.path()), ["out"]);
    }
}
