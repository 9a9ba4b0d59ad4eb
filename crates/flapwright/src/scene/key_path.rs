//! Key paths in the scene file (`station[1].mechanism.flap_mass_kg`) and where they are
//! written (line and column), so every problem points into the file.

use std::fmt;

use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// One step of a key path: a table key or an array index.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Step {
    /// `key` in a table.
    Key(String),
    /// `[index]` in an array.
    Index(usize),
}

/// A key path as written in problems: keys joined by `.`, indices in brackets.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct KeyPathBuf {
    steps: Vec<Step>,
}

impl KeyPathBuf {
    /// From its steps.
    pub fn from_steps(steps: Vec<Step>) -> Self {
        Self { steps }
    }

    /// Reads `a.b[2].c`; text that is no path (`wing (section 2)`) keeps its leading keys.
    pub fn parse(text: &str) -> Self {
        let mut steps = Vec::new();
        for part in text.split('.') {
            let (key, indices) = match part.find('[') {
                Some(open) => (&part[..open], &part[open..]),
                None => (part, ""),
            };
            if !key.is_empty() {
                if !key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') {
                    break;
                }
                steps.push(Step::Key(key.to_string()));
            }
            for index in indices.split(']').filter(|s| !s.is_empty()) {
                match index.trim_start_matches('[').parse() {
                    Ok(i) => steps.push(Step::Index(i)),
                    Err(_) => return Self { steps },
                }
            }
        }
        Self { steps }
    }

    /// The steps, outermost first.
    pub fn steps(&self) -> &[Step] {
        &self.steps
    }

    /// This path with `key` appended.
    pub fn child(&self, key: &str) -> Self {
        let mut steps = self.steps.clone();
        steps.push(Step::Key(key.to_string()));
        Self { steps }
    }

    /// This path without its last step.
    pub fn parent(&self) -> Self {
        let mut steps = self.steps.clone();
        steps.pop();
        Self { steps }
    }

    /// True when `prefix`'s steps begin this path.
    pub fn starts_with(&self, prefix: &Self) -> bool {
        self.steps.starts_with(&prefix.steps)
    }

    /// Appends another path.
    pub fn extend(&mut self, other: &Self) {
        self.steps.extend(other.steps.iter().cloned());
    }

    /// The last step when it is a key.
    pub fn last_key(&self) -> Option<&str> {
        match self.steps.last() {
            Some(Step::Key(key)) => Some(key),
            _ => None,
        }
    }
}

impl fmt::Display for KeyPathBuf {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, step) in self.steps.iter().enumerate() {
            match step {
                Step::Key(key) if i == 0 => write!(f, "{key}")?,
                Step::Key(key) => write!(f, ".{key}")?,
                Step::Index(index) => write!(f, "[{index}]")?,
            }
        }
        Ok(())
    }
}

/// A place in the scene file, 1-based as editors count.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Location {
    /// Line, from 1.
    pub line: usize,
    /// Column in characters, from 1.
    pub column: usize,
}

impl Location {
    /// The line and column of byte `offset` in `text`.
    pub fn of_offset(text: &str, offset: usize) -> Self {
        let offset = offset.min(text.len());
        let before = text.get(..offset).unwrap_or(text);
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        Self {
            line: before.matches('\n').count() + 1,
            column: before[line_start..].chars().count() + 1,
        }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}

/// The scene text with the spans of its keys, for locating problems.
pub struct SpannedScene<'t> {
    text: &'t str,
    root: Option<Spanned<DeTable<'t>>>,
}

impl<'t> SpannedScene<'t> {
    /// Parses `text` (a text that does not parse locates everything at 1:1).
    pub fn new(text: &'t str) -> Self {
        Self {
            text,
            root: DeTable::parse(text).ok(),
        }
    }

    /// Where `path` is written: the key itself when present, else the deepest table or
    /// array on the path that is (where a missing key belongs).
    pub fn locate(&self, path: &KeyPathBuf) -> Location {
        let offset = self.root.as_ref().map_or(0, |root| deepest_span(root, path.steps()));
        Location::of_offset(self.text, offset)
    }
}

impl SpannedScene<'_> {
    /// The deepest key path whose key or value holds byte `offset` (empty when none does):
    /// for an error the parser reports by position only (an integer too large).
    pub fn path_at(&self, offset: usize) -> KeyPathBuf {
        let mut steps = Vec::new();
        if let Some(root) = &self.root {
            path_in_table(root.get_ref(), offset, &mut steps);
        }
        KeyPathBuf { steps }
    }
}

// A table opened by a header (`[station.mechanism]`) or an array of tables may span its
// header only: where no entry holds the offset, the one opened last before it does.
fn path_in_table(table: &DeTable<'_>, offset: usize, steps: &mut Vec<Step>) {
    let holding = table
        .iter()
        .find(|(key, value)| key.span().contains(&offset) || value.span().contains(&offset))
        .or_else(|| {
            table
                .iter()
                .filter(|(_, value)| {
                    matches!(value.get_ref(), DeValue::Table(_) | DeValue::Array(_)) && value.span().start <= offset
                })
                .max_by_key(|(_, value)| value.span().start)
        });
    if let Some((key, value)) = holding {
        steps.push(Step::Key(key.get_ref().to_string()));
        path_in_value(value, offset, steps);
    }
}

fn path_in_value(value: &Spanned<DeValue<'_>>, offset: usize, steps: &mut Vec<Step>) {
    match value.get_ref() {
        DeValue::Table(table) => path_in_table(table, offset, steps),
        DeValue::Array(array) => {
            let element = array
                .iter()
                .enumerate()
                .find(|(_, e)| e.span().contains(&offset))
                .or_else(|| array.iter().enumerate().rev().find(|(_, e)| e.span().start <= offset));
            if let Some((i, element)) = element {
                steps.push(Step::Index(i));
                path_in_value(element, offset, steps);
            }
        }
        _ => {}
    }
}

/// Start of the deepest span along `steps` under `table`.
fn deepest_span(table: &Spanned<DeTable<'_>>, steps: &[Step]) -> usize {
    let mut best = table.span().start;
    let mut value: Option<&Spanned<DeValue<'_>>> = None;
    let mut current_table: Option<&DeTable<'_>> = Some(table.get_ref());
    for step in steps {
        match step {
            Step::Key(key) => {
                let Some(t) = current_table else { break };
                let Some((k, v)) = t.get_key_value(key.as_str()) else {
                    break;
                };
                best = k.span().start;
                value = Some(v);
            }
            Step::Index(i) => {
                let Some(DeValue::Array(array)) = value.map(Spanned::get_ref) else {
                    break;
                };
                let Some(element) = array.get(*i) else { break };
                best = element.span().start;
                value = Some(element);
            }
        }
        current_table = match value.map(Spanned::get_ref) {
            Some(DeValue::Table(t)) => Some(t),
            _ => None,
        };
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_round_trip_through_text() {
        for text in [
            "name",
            "wing.sections[2].chord_m",
            "station[0].mechanism.kind",
            "a[1][2].b",
        ] {
            assert_eq!(KeyPathBuf::parse(text).to_string(), text);
        }
        assert_eq!(KeyPathBuf::parse("flap[0] (inner)").to_string(), "flap[0]");
    }

    #[test]
    fn keys_are_located_in_the_text() {
        let text = "name = \"x\"\n\n[wing]\nsections = [\n  { y_m = 0.0, chord_m = 1.0 },\n  { y_m = 2.0, chord_m = -1 },\n]\n\n[[station]]\nname = \"s\"\n[station.mechanism]\nkind = \"k\"\n";
        let scene = SpannedScene::new(text);
        let at = |p: &str| scene.locate(&KeyPathBuf::parse(p)).to_string();
        assert_eq!(at("name"), "1:1");
        assert_eq!(at("wing.sections[1].chord_m"), "6:16");
        assert_eq!(at("station[0].mechanism.kind"), "12:1");
        // A missing key points at the table it belongs in.
        assert_eq!(at("station[0].mechanism.flap_mass_kg"), "11:10");
        assert_eq!(at("wing.sections[5].y_m"), "4:1");
    }

    #[test]
    fn a_position_is_named_by_the_key_that_holds_it() {
        let text = "name = \"x\"\n[[station]]\nname = \"s\"\n[station.mechanism]\nkind = \"k\"\nturns = 123\n";
        let scene = SpannedScene::new(text);
        let offset = text.find("123").unwrap() + 1;
        assert_eq!(scene.path_at(offset).to_string(), "station[0].mechanism.turns");
        assert_eq!(scene.path_at(0).to_string(), "name");
    }

    #[test]
    fn columns_count_characters() {
        assert_eq!(Location::of_offset("é = 1\nab", 7), Location { line: 2, column: 1 });
        assert_eq!(Location::of_offset("é = 1", 3), Location { line: 1, column: 3 });
    }
}
