//! A key of the scene as its problems name it, and a value as a user types it.

use std::fmt;

use super::SweepError;

/// One step of a key path.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Step {
    /// A table's key.
    Key(String),
    /// Elements of an array.
    Element(Selector),
}

/// Which elements of an array a step takes.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Selector {
    /// By index.
    Index(usize),
    /// The element whose `name` is this.
    Named(String),
    /// Every element.
    Every,
}

/// A scene key as the scene's problems name it: `design.actuator_load_weight`,
/// `flap[0].settings.landing_deg`, `station[ob-inner].mechanism.axis_offset_m`,
/// `flap[*].settings.landing_gap_percent`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KeyPath {
    text: String,
    steps: Vec<Step>,
}

impl fmt::Display for KeyPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

impl std::str::FromStr for KeyPath {
    type Err = SweepError;

    fn from_str(text: &str) -> Result<Self, SweepError> {
        let bad = |why: &str| SweepError::BadKey {
            key: text.to_string(),
            why: why.to_string(),
        };
        let mut steps = Vec::new();
        for part in text.split('.') {
            let (key, mut rest) = match part.find('[') {
                Some(at) => (&part[..at], &part[at..]),
                None => (part, ""),
            };
            if key.is_empty() || !key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') {
                return Err(bad(
                    "each part is a key of letters, digits, `_` or `-`, then `[index]`, `[name]` or `[*]`",
                ));
            }
            steps.push(Step::Key(key.to_string()));
            while !rest.is_empty() {
                let Some(end) = rest.find(']').filter(|_| rest.starts_with('[')) else {
                    return Err(bad("an unclosed or stray `[`"));
                };
                let inside = &rest[1..end];
                steps.push(Step::Element(match inside {
                    "" => return Err(bad("`[]` selects nothing: give an index, a name or `*`")),
                    "*" => Selector::Every,
                    _ => match inside.parse::<usize>() {
                        Ok(index) => Selector::Index(index),
                        Err(_) => Selector::Named(inside.to_string()),
                    },
                }));
                rest = &rest[end + 1..];
            }
        }
        Ok(Self {
            text: text.to_string(),
            steps,
        })
    }
}

impl KeyPath {
    /// Sets the key to `value` in `table` (every element where the path says `[*]`).
    /// Errors: [`SweepError::NoSuchKey`] naming where the path leaves the scene. The last
    /// key may be new (a key the scene leaves at its default), and so may the tables before
    /// it (a table the scene leaves out); every array of tables must be in the scene.
    pub fn set(&self, table: &mut toml::Table, value: &toml::Value) -> Result<(), SweepError> {
        let mut root = toml::Value::Table(std::mem::take(table));
        let result = self.set_in(&mut root, &self.steps, value, String::new());
        if let toml::Value::Table(t) = root {
            *table = t;
        }
        result
    }

    fn set_in(
        &self,
        at: &mut toml::Value,
        steps: &[Step],
        value: &toml::Value,
        place: String,
    ) -> Result<(), SweepError> {
        let missing = |why: String| SweepError::NoSuchKey {
            key: self.text.clone(),
            why,
        };
        let Some((step, rest)) = steps.split_first() else {
            *at = value.clone();
            return Ok(());
        };
        let here = if place.is_empty() {
            "the scene".to_string()
        } else {
            format!("`{place}`")
        };
        match step {
            Step::Key(key) => {
                let toml::Value::Table(table) = at else {
                    return Err(missing(format!("{here} is not a table")));
                };
                let path = if place.is_empty() {
                    key.clone()
                } else {
                    format!("{place}.{key}")
                };
                if rest.is_empty() {
                    // A number where the scene has an integer stays an integer when whole
                    // (`max_evaluations = 2400`).
                    let value = match (table.get(key), value) {
                        (Some(toml::Value::Integer(_)), toml::Value::Float(f))
                            if f.fract() == 0.0 && f.abs() < 9e15 =>
                        {
                            toml::Value::Integer(*f as i64)
                        }
                        _ => value.clone(),
                    };
                    table.insert(key.clone(), value);
                    return Ok(());
                }
                // A table the scene leaves out (`[design]`, all defaults) is made; an array
                // of tables is not (which element would it be?).
                if !table.contains_key(key) && matches!(rest.first(), Some(Step::Key(_))) {
                    table.insert(key.clone(), toml::Value::Table(toml::Table::new()));
                }
                let next = table
                    .get_mut(key)
                    .ok_or_else(|| missing(format!("{here} has no `{key}`")))?;
                self.set_in(next, rest, value, path)
            }
            Step::Element(selector) => {
                let toml::Value::Array(items) = at else {
                    return Err(missing(format!("{here} is not an array")));
                };
                let count = items.len();
                let chosen: Vec<usize> = match selector {
                    Selector::Index(i) if *i < count => vec![*i],
                    Selector::Index(i) => return Err(missing(format!("{here} has {count} elements, no [{i}]"))),
                    Selector::Every => (0..count).collect(),
                    Selector::Named(name) => {
                        let found: Vec<usize> = (0..count)
                            .filter(|&i| items[i].get("name").and_then(|n| n.as_str()) == Some(name.as_str()))
                            .collect();
                        if found.is_empty() {
                            let names: Vec<&str> = items.iter().filter_map(|v| v.get("name")?.as_str()).collect();
                            return Err(missing(format!(
                                "{here} has no element named {name} (its names: {})",
                                names.join(", ")
                            )));
                        }
                        found
                    }
                };
                for i in chosen {
                    self.set_in(&mut items[i], rest, value, format!("{place}[{i}]"))?;
                }
                Ok(())
            }
        }
    }
}

/// A value as a user types it: TOML (`2.5`, `true`, `"four-bar"`, `[1.0, 2.0]`), or
/// else a bare string (`four-bar`).
pub fn parse_value(text: &str) -> toml::Value {
    let text = text.trim();
    match format!("v = {text}").parse::<toml::Table>() {
        Ok(mut table) => table
            .remove("v")
            .unwrap_or_else(|| toml::Value::String(text.to_string())),
        Err(_) => toml::Value::String(text.to_string()),
    }
}
