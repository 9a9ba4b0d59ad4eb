//! A problem in a scene file, by key path and, once located, by file, line and column: the
//! leaf the parser, the validation and the kinds' tables all report with (so that none of
//! them imports another for it).

use std::fmt;

use super::key_path::Location;

/// One problem in a scene file: where (`wing.sections[2].chord_m`) and what.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// Path of the offending key in the file.
    pub path: String,
    /// What is wrong and what is allowed.
    pub message: String,
}

impl Problem {
    /// A problem at `path`.
    pub fn new(path: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            path: path.into(),
            message: message.into(),
        }
    }
}

/// A problem with the file and the line and column of its key (or of the table where a
/// missing key belongs).
#[derive(Debug, Clone, PartialEq)]
pub struct LocatedProblem {
    /// The scene file as the user named it.
    pub file: String,
    /// Where in that file.
    pub location: Location,
    /// The problem.
    pub problem: Problem,
}

impl fmt::Display for LocatedProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.file, self.location, self.problem)
    }
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // `path = value: rule` reads like the file; other messages follow a colon.
        if self.path.is_empty() {
            write!(f, "{}", self.message)
        } else if self.message.starts_with('=') {
            write!(f, "{} {}", self.path, self.message)
        } else {
            write!(f, "{}: {}", self.path, self.message)
        }
    }
}
