//! Scene validation: every bad value reported with its path in the file, all at once.

use std::fmt;
use std::path::Path;

mod geometry;
mod mechanism;
mod settings;

use super::Scene;

/// One problem in a scene file: where (`wing.sections[2].chord_m`) and what.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// Path of the offending key in the file.
    pub path: String,
    /// What is wrong and what is allowed.
    pub message: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // `path = value: rule` reads like the file; other messages follow a colon.
        if self.message.starts_with('=') {
            write!(f, "{} {}", self.path, self.message)
        } else {
            write!(f, "{}: {}", self.path, self.message)
        }
    }
}

/// Why a scene could not be read.
#[derive(Debug)]
pub enum SceneError {
    /// The TOML does not parse into the scene structure (syntax, wrong type, unknown key).
    Parse(String),
    /// The scene parsed but has invalid values.
    Invalid(Vec<Problem>),
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Parse(message) => write!(f, "{}", message.trim_end()),
            Self::Invalid(problems) => {
                write!(f, "{} problem(s) in the scene:", problems.len())?;
                for problem in problems {
                    write!(f, "\n  - {problem}")?;
                }
                Ok(())
            }
        }
    }
}

impl std::error::Error for SceneError {}

impl Scene {
    /// Parses and validates a scene. `scene_dir` is where relative airfoil files are
    /// looked up (bundled airfoils are found by name otherwise).
    pub fn from_toml(text: &str, scene_dir: Option<&Path>) -> Result<Self, SceneError> {
        let scene: Scene = toml::from_str(text).map_err(|e| SceneError::Parse(e.to_string()))?;
        let problems = scene.validate(scene_dir);
        if problems.is_empty() {
            Ok(scene)
        } else {
            Err(SceneError::Invalid(problems))
        }
    }

    /// All problems of the scene (empty when valid).
    pub fn validate(&self, scene_dir: Option<&Path>) -> Vec<Problem> {
        let mut check = Checker {
            problems: Vec::new(),
            scene_dir,
        };
        if self.name.trim().is_empty() {
            check.fail("name", "\"\": must not be empty");
        }
        if let Some(wing) = &self.wing {
            check.wing(wing);
            for (i, flap) in self.flap.iter().enumerate() {
                check.flap(&format!("flap[{i}]"), flap, wing);
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
        check.resolution(self);
        check.problems
    }
}

struct Checker<'a> {
    problems: Vec<Problem>,
    scene_dir: Option<&'a Path>,
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
                format!("= {value}: must be in {lo}{}, {}{hi}", bound(min), bound(max)),
            );
        }
        ok
    }

    fn positive(&mut self, path: &str, value: f64) -> bool {
        let ok = value.is_finite() && value > 0.0;
        if !ok {
            self.fail(path, format!("= {value}: must be > 0 and finite"));
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

    fn count_in(&mut self, path: &str, value: usize, min: usize, max: usize) {
        if value < min || value > max {
            self.fail(path, format!("= {value}: must be in [{min}, {max}]"));
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
