//! Reading the TOML text into the typed scene, reporting *every* structural problem at once
//! (wrong type, missing key, unknown key, wrong array length), each with its key path.
//!
//! serde stops at the first error. To report all of them, the text is parsed once into a
//! plain `toml::Table`, then deserialised with [`serde_path_to_error`] (which names the
//! failing key); after each error the offending value is patched in the table (an unknown
//! key removed, a missing or mistyped value replaced by a stand-in of another type) and the
//! deserialisation is repeated, at most [`MAX_ROUNDS`] times. The stand-ins only let the
//! search go on: a scene with any structural problem is rejected and never reaches a stage.
//! No crate does this for TOML: `eserde` (the one made for collecting serde errors) was
//! tried and loses paths after the first failing table and inside tagged enums.

use serde::de::DeserializeOwned;
use serde_path_to_error::{Path as KeyPath, Segment};
use toml::{Table, Value};

use super::key_path::{KeyPathBuf, Step};
use super::nested_error::{split_nested, DECIDES_MARK};
use super::problem::Problem;

/// Deserialisation rounds before the search gives up (each round finds one problem).
pub const MAX_ROUNDS: usize = 200;

/// Deserialises `T` from `table`, returning every structural problem (paths only; the
/// caller adds line and column).
pub fn typed<T: DeserializeOwned>(table: &Table) -> Result<T, Vec<Problem>> {
    let mut work = Value::Table(table.clone());
    let mut problems: Vec<Problem> = Vec::new();
    // Stand-ins tried so far at each patched path.
    let mut tried: Vec<(KeyPathBuf, usize)> = Vec::new();
    // Tables whose deciding key is wrong: nothing more is reported under them.
    let mut moot: Vec<KeyPathBuf> = Vec::new();
    for _ in 0..MAX_ROUNDS {
        let error = match serde_path_to_error::deserialize::<_, T>(work.clone()) {
            Ok(value) if problems.is_empty() => return Ok(value),
            Ok(_) => return Err(problems),
            Err(error) => error,
        };
        let raw = error.inner().message().to_string();
        let mut path = KeyPathBuf::from_serde(error.path());
        let (inner, text) = split_nested(&raw);
        if let Some(inner) = inner {
            path.extend(&KeyPathBuf::parse(&inner));
        }
        let (text, decides) = match text.strip_prefix(DECIDES_MARK) {
            Some(text) => (text, true),
            None => (text, false),
        };
        let fault = Fault::classify(text);
        let (problem_path, patch) = match &fault {
            Fault::Missing(key) => (path.child(key), Patch::StandIn),
            Fault::Unknown(key) => {
                // serde_path_to_error names the unknown key itself on some paths and its
                // table on others.
                let at = if path.last_key() == Some(key.as_str()) {
                    path.clone()
                } else {
                    path.child(key)
                };
                (at, Patch::Remove)
            }
            Fault::Other(_) => (path.clone(), Patch::StandIn),
        };
        let attempt = match tried.iter_mut().find(|(p, _)| *p == problem_path) {
            Some((_, n)) => {
                *n += 1;
                *n
            }
            None => {
                tried.push((problem_path.clone(), 0));
                if !moot.iter().any(|table| problem_path.starts_with(table)) {
                    problems.push(Problem::new(problem_path.to_string(), fault.message()));
                }
                0
            }
        };
        if decides {
            moot.push(problem_path.parent());
        }
        let patched = match patch {
            Patch::Remove => problem_path.remove_from(&mut work),
            Patch::StandIn => match STAND_INS.get(attempt) {
                Some(make) => problem_path.set_in(&mut work, make()),
                None => false,
            },
        };
        if !patched {
            // Nothing left to try at this path: report what was found.
            return Err(problems);
        }
    }
    Err(problems)
}

enum Patch {
    Remove,
    StandIn,
}

/// Values tried, in order, in place of a missing or mistyped one.
const STAND_INS: &[fn() -> Value] = &[
    || Value::Float(1.0),
    || Value::String(crate::kinds::MechanismScene::KINDS[0].into()),
    || Value::Boolean(true),
    || Value::Integer(1),
    || Value::Table(Table::new()),
    || Value::Array(vec![Value::Float(1.0); 3]),
    || Value::Array(vec![Value::Float(1.0); 2]),
    || Value::Array(Vec::new()),
];

/// What serde reported, reworded for people.
enum Fault {
    Missing(String),
    Unknown(String),
    Other(String),
}

impl Fault {
    fn classify(text: &str) -> Self {
        if let Some(key) = backticked_after(text, "missing field ") {
            return Self::Missing(key);
        }
        if let Some(key) = backticked_after(text, "unknown field ") {
            return Self::Unknown(key);
        }
        Self::Other(text.to_string())
    }

    fn message(&self) -> String {
        match self {
            Self::Missing(_) => "missing: this key is required".into(),
            Self::Unknown(_) => {
                "unknown key (check the spelling; docs/scene.md and `flapwright kinds` list the keys of each table)"
                    .into()
            }
            Self::Other(text) => reword(text),
        }
    }
}

/// The key in `` prefix`key` `` at the start of `text`.
fn backticked_after(text: &str, prefix: &str) -> Option<String> {
    let rest = text.strip_prefix(prefix)?.strip_prefix('`')?;
    rest.split_once('`').map(|(key, _)| key.to_string())
}

/// serde's "invalid type: floating point `1e300...0.0`, expected usize" with literals cut
/// short and the expected type in words.
fn reword(text: &str) -> String {
    let mut out = String::with_capacity(text.len().min(200));
    let mut rest = text;
    while let Some(start) = rest.find('`') {
        out.push_str(&rest[..start]);
        let after = &rest[start + 1..];
        match after.find('`') {
            Some(end) => {
                let literal = &after[..end];
                out.push('`');
                if literal.chars().count() > 24 {
                    match literal.parse::<f64>() {
                        Ok(v) => out.push_str(&format!("{v:e}")),
                        Err(_) => {
                            out.extend(literal.chars().take(20));
                            out.push_str("...");
                        }
                    }
                } else {
                    out.push_str(literal);
                }
                out.push('`');
                rest = &after[end + 1..];
            }
            None => {
                rest = &rest[start..];
                break;
            }
        }
    }
    out.push_str(rest);
    let out = out
        .replace("expected f64", "expected a number")
        .replace("expected usize", "expected a whole number >= 0")
        .replace("expected u64", "expected a whole number >= 0")
        .replace("expected u32", "expected a whole number >= 0")
        .replace(
            "expected fewer elements in array",
            "more elements than this fixed-length array holds (points are [x, y, z]; flap_centre_of_mass_m is [x, y])",
        );
    out.trim_end().to_string()
}

impl KeyPathBuf {
    /// The path serde_path_to_error reports.
    fn from_serde(path: &KeyPath) -> Self {
        let mut steps = Vec::new();
        for segment in path.iter() {
            match segment {
                Segment::Map { key } => steps.push(Step::Key(key.clone())),
                Segment::Seq { index } => steps.push(Step::Index(*index)),
                Segment::Enum { .. } | Segment::Unknown => {}
            }
        }
        Self::from_steps(steps)
    }

    /// Sets the value at this path (creating the last key), true when done.
    fn set_in(&self, root: &mut Value, value: Value) -> bool {
        let Some((last, parents)) = self.steps().split_last() else {
            return false;
        };
        let Some(parent) = walk_mut(root, parents) else {
            return false;
        };
        match (parent, last) {
            (Value::Table(table), Step::Key(key)) => {
                table.insert(key.clone(), value);
                true
            }
            (Value::Array(array), Step::Index(i)) if *i < array.len() => {
                array[*i] = value;
                true
            }
            _ => false,
        }
    }

    /// Removes the key or element at this path, true when done.
    fn remove_from(&self, root: &mut Value) -> bool {
        let Some((last, parents)) = self.steps().split_last() else {
            return false;
        };
        let Some(parent) = walk_mut(root, parents) else {
            return false;
        };
        match (parent, last) {
            (Value::Table(table), Step::Key(key)) => table.remove(key).is_some(),
            _ => false,
        }
    }
}

fn walk_mut<'v>(mut value: &'v mut Value, steps: &[Step]) -> Option<&'v mut Value> {
    for step in steps {
        value = match (value, step) {
            (Value::Table(table), Step::Key(key)) => table.get_mut(key)?,
            (Value::Array(array), Step::Index(i)) => array.get_mut(*i)?,
            _ => return None,
        };
    }
    Some(value)
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Outer {
        name: String,
        point_m: [f64; 3],
        #[serde(default)]
        inner: Vec<Inner>,
        count: usize,
    }

    #[derive(Debug, Deserialize)]
    #[serde(deny_unknown_fields)]
    #[allow(dead_code)]
    struct Inner {
        length_m: f64,
        width_m: f64,
    }

    fn problems(text: &str) -> Vec<String> {
        let table: Table = toml::from_str(text).expect("valid TOML");
        typed::<Outer>(&table)
            .expect_err("has problems")
            .into_iter()
            .map(|p| format!("{} | {}", p.path, p.message))
            .collect::<std::collections::BTreeSet<_>>()
            .into_iter()
            .collect()
    }

    #[test]
    fn every_structural_problem_is_reported_with_its_key() {
        let found = problems(
            "name = 3\npoint_m = [0, 1, 2, 3, \"x\"]\ncount = 1e300\n[[inner]]\nlength_m = \"a\"\nbogus = 1\n[[inner]]\nwidth_m = 2\n",
        );
        assert_eq!(
            found,
            [
                "count | invalid type: floating point `1e300`, expected a whole number >= 0",
                "inner[0].bogus | unknown key (check the spelling; docs/scene.md and `flapwright kinds` list the keys of each table)",
                "inner[0].length_m | invalid type: string \"a\", expected a number",
                "inner[0].width_m | missing: this key is required",
                "inner[1].length_m | missing: this key is required",
                "name | invalid type: integer `3`, expected a string",
                "point_m | invalid length 5, more elements than this fixed-length array holds (points are [x, y, z]; flap_centre_of_mass_m is [x, y])",
            ],
            "{found:#?}"
        );
    }

    #[test]
    fn a_valid_table_deserialises() {
        let table: Table = toml::from_str("name = \"a\"\npoint_m = [0, 1, 2]\ncount = 2\n").unwrap();
        let outer: Outer = typed(&table).unwrap();
        assert_eq!(outer.count, 2);
    }

    #[test]
    fn short_arrays_and_missing_top_level_keys_are_named() {
        let found = problems("point_m = [0, 1]\n");
        assert_eq!(
            found,
            [
                "count | missing: this key is required",
                "name | missing: this key is required",
                "point_m | invalid length 2, expected an array of length 3",
            ],
            "{found:#?}"
        );
    }
}
