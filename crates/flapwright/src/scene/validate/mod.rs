//! Scene validation: every bad value reported with its path in the file, all at once.

use super::files::FileSource;
use std::fmt;

mod budget;
mod geometry;

pub(crate) use geometry::default_tube_end;
pub mod limits;
mod mechanism;
mod settings;

use super::key_path::{KeyPathBuf, Location, SpannedScene};
pub use super::problem::{LocatedProblem, Problem};
use super::Scene;

/// Why a scene could not be read.
#[derive(Debug)]
pub enum SceneError {
    /// The scene has problems, known by key path only (e.g. found by a stage after
    /// validation); [`SceneError::locate`] adds file, line and column.
    Invalid(Vec<Problem>),
    /// The scene has problems, each with file, line and column.
    Located(Vec<LocatedProblem>),
}

impl SceneError {
    /// Adds file, line and column to problems known by path only.
    pub fn locate(self, text: &str, file: &str) -> Self {
        match self {
            Self::Invalid(problems) => Self::Located(locate_all(text, file, problems)),
            other => other,
        }
    }

    /// Every problem as a line of text (`file:line:col: path = value: rule`).
    pub fn lines(&self) -> Vec<String> {
        match self {
            Self::Invalid(problems) => problems.iter().map(ToString::to_string).collect(),
            Self::Located(problems) => problems.iter().map(ToString::to_string).collect(),
        }
    }
}

/// Locates each problem's key path in `text`.
fn locate_all(text: &str, file: &str, problems: Vec<Problem>) -> Vec<LocatedProblem> {
    let spans = SpannedScene::new(text);
    let mut located: Vec<LocatedProblem> = problems
        .into_iter()
        .map(|problem| LocatedProblem {
            file: file.to_string(),
            location: spans.locate(&KeyPathBuf::parse(&problem.path)),
            problem,
        })
        .collect();
    // In the order of the file, as an editor lists them.
    located.sort_by_key(|p| (p.location.line, p.location.column));
    located
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Invalid(_) | Self::Located(_) => {
                let lines = self.lines();
                write!(f, "{} problem(s) in the scene:", lines.len())?;
                for line in lines {
                    write!(f, "\n  - {line}")?;
                }
                Ok(())
            }
        }
    }
}

impl std::error::Error for SceneError {}

impl Scene {
    /// Parses and validates a scene. `files` gives the airfoil files the scene names, which are
    /// looked up (bundled airfoils are found by name otherwise).
    pub fn from_toml(text: &str, files: &dyn FileSource) -> Result<Self, SceneError> {
        Self::from_file_text(text, "scene.toml", files)
    }

    /// Reads a scene file's bytes from `reader`, no further than [`MAX_SCENE_BYTES`] and one
    /// byte more: an endless file (`/dev/zero`) costs a megabyte, and [`Scene::decode`] tells
    /// a file over the limit.
    pub fn read_bytes(reader: impl std::io::Read) -> std::io::Result<Vec<u8>> {
        use std::io::Read as _;
        let mut bytes = Vec::new();
        reader.take(MAX_SCENE_BYTES as u64 + 1).read_to_end(&mut bytes)?;
        Ok(bytes)
    }

    /// The scene file's bytes as text; a file over [`MAX_SCENE_BYTES`] is refused, and
    /// invalid UTF-8 is located like any other problem.
    pub fn decode(bytes: Vec<u8>, file: &str) -> Result<String, SceneError> {
        if bytes.len() > MAX_SCENE_BYTES {
            return Err(SceneError::Located(vec![LocatedProblem {
                file: file.to_string(),
                location: Location::of_offset("", 0),
                problem: Problem::new(
                    "",
                    format!("more than {MAX_SCENE_BYTES} bytes: a scene file may hold at most {MAX_SCENE_BYTES} bytes"),
                ),
            }]));
        }
        String::from_utf8(bytes).map_err(|error| {
            let valid = error.utf8_error().valid_up_to();
            let bytes = error.as_bytes();
            let text = String::from_utf8_lossy(&bytes[..valid]);
            SceneError::Located(vec![LocatedProblem {
                file: file.to_string(),
                location: Location::of_offset(&text, valid),
                problem: Problem::new(
                    "",
                    format!("byte {valid} is not UTF-8 text (a scene file is UTF-8 TOML)"),
                ),
            }])
        })
    }

    /// As [`Scene::from_toml`], naming the file `file` in the problems
    /// (`file:line:col: path = value: rule`).
    pub fn from_file_text(text: &str, file: &str, files: &dyn FileSource) -> Result<Self, SceneError> {
        let located = |problems| SceneError::Invalid(problems).locate(text, file);
        let at = |offset: usize, path: String, message: String| {
            SceneError::Located(vec![LocatedProblem {
                file: file.to_string(),
                location: Location::of_offset(text, offset),
                problem: Problem::new(path, message),
            }])
        };
        if text.len() > MAX_SCENE_BYTES {
            return Err(at(
                0,
                String::new(),
                format!(
                    "{} bytes: a scene file may hold at most {MAX_SCENE_BYTES} bytes",
                    text.len()
                ),
            ));
        }
        let (_, syntax) = toml::de::DeTable::parse_recoverable(text);
        if !syntax.is_empty() {
            // The first only: after a syntax error the parser's later complaints are
            // mostly echoes of it (an unclosed `[wing` header makes its keys duplicates).
            return Err(SceneError::Located(
                syntax
                    .iter()
                    .take(1)
                    .map(|e| LocatedProblem {
                        file: file.to_string(),
                        location: Location::of_offset(text, e.span().map_or(0, |s| s.start)),
                        problem: Problem::new("", format!("TOML syntax: {}", e.message().trim_end())),
                    })
                    .collect(),
            ));
        }
        // What the syntax pass lets through but values cannot hold (an integer beyond i64):
        // named by the key whose value holds the error's position.
        let table: toml::Table = toml::from_str(text).map_err(|e| {
            let offset = e.span().map_or(0, |s| s.start);
            let path = SpannedScene::new(text).path_at(offset);
            let literal = e.span().and_then(|s| text.get(s)).unwrap_or_default().trim();
            let message = if e.message().contains("integer") && !literal.is_empty() {
                format!(
                    "= {}: a whole number beyond the 64-bit range (at most {}); write a float (1e20) if so large a value is meant",
                    literal.chars().take(40).collect::<String>(),
                    i64::MAX
                )
            } else {
                format!("TOML: {}", e.message().trim_end())
            };
            at(offset, path.to_string(), message)
        })?;
        let mut scene = Self::from_table(&table, files).map_err(located)?;
        scene.warnings = locate_all(text, file, scene.value_warnings())
            .iter()
            .map(ToString::to_string)
            .collect();
        Ok(scene)
    }

    /// A scene from its TOML table, parsed and validated; problems by key path only. The
    /// scene's `warnings` are left empty.
    pub fn from_table(table: &toml::Table, files: &dyn FileSource) -> Result<Self, Vec<Problem>> {
        let scene: Scene = super::parse::typed(table)?;
        let problems = scene.validate(files);
        if problems.is_empty() {
            Ok(scene)
        } else {
            Err(problems)
        }
    }

    /// Values that are valid but probably not what was meant, as problems by key path: a
    /// gap or overlap target (`*_percent`, % of the local chord) of magnitude below
    /// [`FRACTION_LIKE_PERCENT`], which reads as a fraction written for a percentage
    /// (`landing_gap_percent = 0.02` for 2 %).
    pub fn value_warnings(&self) -> Vec<Problem> {
        let mut warnings = Vec::new();
        for (i, flap) in self.flap.iter().enumerate() {
            let settings = &flap.settings;
            for (key, value) in [
                ("takeoff_gap_percent", settings.takeoff_gap_percent),
                ("takeoff_overlap_percent", settings.takeoff_overlap_percent),
                ("landing_gap_percent", settings.landing_gap_percent),
                ("landing_overlap_percent", settings.landing_overlap_percent),
            ] {
                let Some(value) = value else { continue };
                if value != 0.0 && value.abs() < FRACTION_LIKE_PERCENT {
                    // Rounded so that 0.07 reads 7, not 7.000000000000001.
                    let as_percent = (value * 100.0 * 1e9).round() / 1e9;
                    warnings.push(Problem::new(
                        format!("flap[{i}].settings.{key}"),
                        format!(
                            "= {}: taken as {} % of the local chord; a fraction written for a percentage? ({} % is written {})",
                            number(value),
                            number(value),
                            number(as_percent),
                            number(as_percent)
                        ),
                    ));
                }
            }
        }
        warnings
    }

    /// All problems of the scene (empty when valid).
    pub fn validate(&self, files: &dyn FileSource) -> Vec<Problem> {
        let (fewest, most) = limits::AIRFOIL_POINTS_PER_SIDE;
        let mut check = Checker {
            problems: Vec::new(),
            files,
            airfoil_points_per_side: self.resolution.airfoil_points_per_side.clamp(fewest, most),
        };
        if self.name.trim().is_empty() {
            check.fail("name", "\"\": must not be empty");
        }
        check.file_safe_name("name", &self.name);
        if self.wing.is_none() && self.station.is_empty() {
            check.fail(
                "station",
                "none: the scene has neither a [wing] nor a [[station]], so there is nothing to design; add a \
                 [[station]] with its [station.mechanism] (a 2D scene), or a [wing] with [[flap]] and stations on them",
            );
        }
        for (i, flap) in self.flap.iter().enumerate() {
            check.file_safe_name(&format!("flap[{i}].name"), &flap.name);
        }
        for (i, spar) in self.structure.spars.iter().enumerate() {
            check.file_safe_name(&format!("structure.spars[{i}].name"), &spar.name);
        }
        for (i, station) in self.station.iter().enumerate() {
            check.file_safe_name(&format!("station[{i}].name"), &station.name);
        }
        check.distinct_part_names(self);
        if let Some(wing) = &self.wing {
            check.wing(wing);
            for (i, flap) in self.flap.iter().enumerate() {
                check.flap(&format!("flap[{i}]"), flap, wing);
                // Only a kind synthesised from the settings drives the flap to them; a kind
                // given by its dimensions reports how far it misses them.
                let synthesised = self
                    .station
                    .iter()
                    .any(|s| s.flap.as_deref() == Some(flap.name.as_str()) && s.mechanism.is_synthesised());
                if synthesised {
                    check.overlap_needs_a_shroud(&format!("flap[{i}]"), flap);
                }
            }
            check.unique_names("flap", self.flap.iter().map(|f| f.name.as_str()));
            check.structure(self, wing);
        } else if !self.flap.is_empty() {
            check.fail("flap", "a flap needs a [wing]");
        }
        check.stations(self);
        check.loads(self);
        check.sizing(self);
        check.interference(self);
        if let Some(dynamics) = &self.dynamics {
            dynamics.check(&mut check);
            if self.wing.is_none() {
                // Without a wing there is no flap section to take a moment of inertia from.
                for (i, station) in self.station.iter().enumerate() {
                    if !station.mechanism.kind().models_own_dynamics() {
                        check.fail(
                            "dynamics",
                            format!(
                                "station[{i}] (\"{}\") has no flap section in a 2D scene (no [wing]) to take the flap's moment of inertia from: [dynamics] runs a 2D scene's stations only if their kind models its own masses (five-bar); give the scene a [wing] or remove [dynamics]",
                                station.name
                            ),
                        );
                    }
                }
            }
        }
        check.resolution(self);
        if check.problems.is_empty() {
            // The work estimate trusts the values: only for an otherwise valid scene.
            check.budget(self);
        }
        check.problems
    }
}

/// A value as a person reads it: `1e308`, not 309 digits.
pub fn number(value: f64) -> String {
    let magnitude = value.abs();
    if magnitude != 0.0 && magnitude.is_finite() && !(1e-4..1e6).contains(&magnitude) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

/// A non-zero gap or overlap target (% of the local chord) smaller than this is warned
/// about as a fraction written for a percentage. Targets of slotted flaps are 0-3 % of the
/// chord (`003_...` Fig. 3), so their fractions (0-0.03) all fall below it, while a real
/// target of 0.1 % is a millimetre on a 1 m chord, below the default 3 mm clearance and
/// manufacturing tolerance: whoever means so little writes 0 (which is not warned about).
pub const FRACTION_LIKE_PERCENT: f64 = 0.1;

/// Largest scene file read, bytes: a hand-written whole-wing scene is a few tens of
/// kilobytes; anything near this is generated by mistake, and parsing it would cost
/// seconds and memory before any check.
pub const MAX_SCENE_BYTES: usize = 1 << 20;

/// Longest name of a scene, flap, spar or station (they become file names).
pub const MAX_NAME_CHARS: usize = 64;

/// What a kind's table may ask of validation: the same checks, messages and locations as
/// every other key (`crate::kinds::KindScene::check`).
pub trait KeyChecker {
    /// A problem at `path`.
    fn fail(&mut self, path: &str, message: String);
    /// Finite and inside `[min, max]` (or open bounds where `open`); true when fine.
    fn in_range(&mut self, path: &str, value: f64, min: f64, max: f64, open: bool) -> bool;
    /// Finite and within the scene's coordinate limits in every coordinate.
    fn point_within(&mut self, path: &str, point: &[f64]) -> bool;
}

impl KeyChecker for Checker<'_> {
    fn fail(&mut self, path: &str, message: String) {
        Checker::fail(self, path, message);
    }

    fn in_range(&mut self, path: &str, value: f64, min: f64, max: f64, open: bool) -> bool {
        Checker::in_range(self, path, value, min, max, open)
    }

    fn point_within(&mut self, path: &str, point: &[f64]) -> bool {
        Checker::point_within(self, path, point)
    }
}

struct Checker<'a> {
    problems: Vec<Problem>,
    files: &'a dyn FileSource,
    /// Airfoils are read and resampled at the scene's resolution during validation, so a
    /// file that is not an airfoil is an input problem, not a failure of the geometry stage.
    airfoil_points_per_side: usize,
}

impl Checker<'_> {
    fn fail(&mut self, path: impl Into<String>, message: impl Into<String>) {
        self.problems.push(Problem {
            path: path.into(),
            message: message.into(),
        });
    }

    /// Finite and inside `[min, max]` (or open bounds where `open`); true when fine.
    fn in_range(&mut self, path: &str, value: f64, min: f64, max: f64, open: bool) -> bool {
        let ok = value.is_finite()
            && if open {
                value > min && value < max
            } else {
                value >= min && value <= max
            };
        if !ok {
            let (lo, hi) = if open { ("(", ")") } else { ("[", "]") };
            let bound = |b: f64| {
                if b.is_infinite() {
                    "inf".to_string()
                } else {
                    format!("{b}")
                }
            };
            self.fail(
                path,
                format!("= {}: must be in {lo}{}, {}{hi}", number(value), bound(min), bound(max)),
            );
        }
        ok
    }

    fn finite_point(&mut self, path: &str, point: &[f64]) -> bool {
        let ok = point.iter().all(|v| v.is_finite());
        if !ok {
            self.fail(path, format!("= {point:?}: every coordinate must be finite"));
        }
        ok
    }

    /// Finite and within [`limits::MAX_ABS_COORDINATE_M`] of the origin in every coordinate.
    fn point_within(&mut self, path: &str, point: &[f64]) -> bool {
        if !self.finite_point(path, point) {
            return false;
        }
        let limit = limits::MAX_ABS_COORDINATE_M;
        let ok = point.iter().all(|v| v.abs() <= limit);
        if !ok {
            self.fail(
                path,
                format!("= {point:?}: every coordinate must be in [-{limit}, {limit}] m"),
            );
        }
        ok
    }

    fn count_in(&mut self, path: &str, value: usize, min: usize, max: usize) {
        if value < min || value > max {
            self.fail(path, format!("= {value}: must be in [{min}, {max}]"));
        }
    }

    /// A name that becomes part of file names and URDF link names (scene, flaps, spars,
    /// stations): ASCII letters, digits, `_` and `-`, at most [`MAX_NAME_CHARS`], no `--`
    /// (XML comments forbid it), so that no name can reach outside the output folder.
    fn file_safe_name(&mut self, path: &str, name: &str) {
        let allowed = name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
        let safe = allowed && !name.contains("--") && name.len() <= MAX_NAME_CHARS;
        // An empty name is reported by the uniqueness rule.
        if !name.is_empty() && !safe {
            self.fail(
                path,
                format!(
                    "= \"{}\": names become file and URDF names: use ASCII letters, digits, '_' and '-' (no \"--\"), at most {MAX_NAME_CHARS} characters",
                    name.escape_default()
                ),
            );
        }
    }

    /// Flaps and spars are parts beside "wing" and "torque-tube": each part's STL file is
    /// named after it, so no two may share a name.
    fn distinct_part_names(&mut self, scene: &Scene) {
        let reserved = ["wing", "torque-tube", "wing_structure"];
        // A flap's URDF link sits beside the stations' links `<station>_...`.
        for (i, flap) in scene.flap.iter().enumerate() {
            if let Some(station) = scene
                .station
                .iter()
                .find(|s| flap.name == s.name || flap.name.starts_with(&format!("{}_", s.name)))
            {
                self.fail(
                    format!("flap[{i}].name"),
                    format!(
                        "= \"{}\": clashes with station \"{}\" (its URDF links are named \"{}\" and \"{}_...\")",
                        flap.name, station.name, station.name, station.name
                    ),
                );
            }
        }
        for (i, spar) in scene.structure.spars.iter().enumerate() {
            if reserved.contains(&spar.name.as_str()) || scene.flap.iter().any(|f| f.owns_part(&spar.name)) {
                self.fail(
                    format!("structure.spars[{i}].name"),
                    format!(
                        "= \"{}\": already the name of another part (the wing, the torque tube, a flap or a flap's aft element \"<flap>-aft\")",
                        spar.name
                    ),
                );
            }
        }
        for (i, flap) in scene.flap.iter().enumerate() {
            if reserved.contains(&flap.name.as_str()) {
                self.fail(
                    format!("flap[{i}].name"),
                    format!("= \"{}\": reserved for another part", flap.name),
                );
            }
            // Another flap's aft element takes "<flap>-aft".
            if let Some(other) = scene
                .flap
                .iter()
                .find(|other| other.name != flap.name && other.owns_part(&flap.name))
            {
                self.fail(
                    format!("flap[{i}].name"),
                    format!(
                        "= \"{}\": the name of flap \"{}\"'s aft element (its part is \"<flap>-aft\")",
                        flap.name, other.name
                    ),
                );
            }
        }
    }

    fn unique_names<'n>(&mut self, table: &str, names: impl Iterator<Item = &'n str>) {
        let mut seen = std::collections::BTreeSet::new();
        for (i, name) in names.enumerate() {
            if name.trim().is_empty() {
                self.fail(format!("{table}[{i}].name"), "must not be empty");
            } else if !seen.insert(name) {
                self.fail(
                    format!("{table}[{i}].name"),
                    format!("= \"{name}\": used twice; names must be unique"),
                );
            }
        }
    }
}
