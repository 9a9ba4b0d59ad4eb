//! `flapwright sweep`: many variants of one scene, designed in parallel, one table out
//! (issue 39).
//!
//! A variant is the user's scene with some keys set to other values: [`KeyPath`]s as the
//! scene's own problems name them (`flap[0].settings.landing_gap_percent`), with `[*]` for
//! every element of an array and `[name]` for the element of that `name`. The variants
//! are the product of ranges and lists ([`Vary`], the first varied slowest) or the rows of
//! a table ([`Variants::from_csv`]). Each variant is designed in memory as the study designs
//! its kinds (no STL, URDF, glTF or drawings), the variants sharing one [`WingCache`]: a
//! variant that changes only settings or a mechanism meshes no wing of its own. Its row
//! ([`SweepRow`]) holds its values, the SHA-256 of its scene text, the verdict and the
//! whole wing's figures (the study's per-station figures, [`crate::study::StationFigures`],
//! gathered over the stations), or the error that stopped it.
//!
//! Rows are CSV ([`csv_header`], [`SweepRow::csv_record`]): numbers as Rust writes them
//! (the shortest text that reads back to the same `f64`), so the same scene and variants
//! give the same bytes on any run. The `csv` crate quotes; no scheduler is built in:
//! [`Shard`] picks every N-th variant so that a job array or a cluster splits the work.

use std::fmt;

use rayon::prelude::*;
use sha2::{Digest, Sha256};

use crate::error::Error;
use crate::pipeline::{self, Inputs, Mode, WingCache};
use crate::report::Report;
use crate::scene::{FileSource, Scene, SceneError};
use crate::sink::MemorySink;

/// Why a sweep's input cannot be used. Every message names the key, the value or the row.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SweepError {
    /// A key path that does not parse.
    #[error("key `{key}`: {why}")]
    BadKey {
        /// The key as given.
        key: String,
        /// What is wrong with it.
        why: String,
    },
    /// A key path the scene has no place for.
    #[error("key `{key}`: {why}")]
    NoSuchKey {
        /// The key as given.
        key: String,
        /// Where it leaves the scene.
        why: String,
    },
    /// A `--vary` value that does not parse.
    #[error("--vary {given}: {why}")]
    BadRange {
        /// The argument as given.
        given: String,
        /// What is wrong with it.
        why: String,
    },
    /// A variants table that cannot be read.
    #[error("variants table, {place}: {why}")]
    BadTable {
        /// Row (1 is the header) or column.
        place: String,
        /// What is wrong.
        why: String,
    },
    /// A shard that does not name one of N parts.
    #[error("--shard {given}: {why}")]
    BadShard {
        /// The argument as given.
        given: String,
        /// What is wrong with it.
        why: String,
    },
    /// Neither ranges nor a table of variants, or both.
    #[error("{0}")]
    Variants(&'static str),
    /// The user's scene text is not TOML (its own problems are located by `Scene`).
    #[error("the scene is not a TOML table: {0}")]
    NotToml(String),
}

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

/// One `--vary KEY=START:STOP:STEP` or `--vary KEY=A,B,C`.
#[derive(Debug, Clone, PartialEq)]
pub struct Vary {
    /// The key.
    pub key: KeyPath,
    /// Its values in order, as text (the table's cells) and as TOML.
    pub values: Vec<(String, toml::Value)>,
}

/// The most values one range may give.
pub const MAX_RANGE_VALUES: usize = 1_000_000;

impl std::str::FromStr for Vary {
    type Err = SweepError;

    fn from_str(given: &str) -> Result<Self, SweepError> {
        let bad = |why: String| SweepError::BadRange {
            given: given.to_string(),
            why,
        };
        let Some((key, spec)) = given.split_once('=') else {
            return Err(bad("give KEY=START:STOP:STEP or KEY=A,B,C".into()));
        };
        let key: KeyPath = key.trim().parse()?;
        let spec = spec.trim();
        let parts: Vec<&str> = spec.split(':').collect();
        let values = if parts.len() == 3 {
            let number = |what: &str, s: &str| -> Result<f64, SweepError> {
                s.trim()
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| bad(format!("{what} `{s}` is not a finite number")))
            };
            let (start, stop, step) = (
                number("START", parts[0])?,
                number("STOP", parts[1])?,
                number("STEP", parts[2])?,
            );
            if step <= 0.0 {
                return Err(bad(format!("STEP {step} must be > 0")));
            }
            if stop < start {
                return Err(bad(format!("STOP {stop} is below START {start}")));
            }
            let intervals = (stop - start) / step;
            let count = intervals.round();
            if (intervals - count).abs() > 1e-6 * count.max(1.0) {
                return Err(bad(format!(
                    "STOP - START = {} is not a whole number of steps of {step}",
                    stop - start
                )));
            }
            if count + 1.0 > MAX_RANGE_VALUES as f64 {
                return Err(bad(format!("{} values: at most {MAX_RANGE_VALUES}", count + 1.0)));
            }
            // Each value from the start, not by adding steps, so that errors do not pile up;
            // rounded to 12 significant digits, so that 1.5 + 3 x 0.1 reads 1.8.
            (0..=count as usize)
                .map(|k| {
                    let v = round_significant(start + step * k as f64, 12);
                    (format_number(v), toml::Value::Float(v))
                })
                .collect()
        } else if parts.len() == 1 && !spec.is_empty() {
            spec.split(',')
                .map(|s| (s.trim().to_string(), parse_value(s)))
                .collect()
        } else {
            return Err(bad("give START:STOP:STEP or a comma-separated list".into()));
        };
        Ok(Self { key, values })
    }
}

fn round_significant(v: f64, digits: i32) -> f64 {
    if v == 0.0 {
        return 0.0;
    }
    let scale = 10f64.powi(digits - 1 - v.abs().log10().floor() as i32);
    (v * scale).round() / scale
}

/// A number as the table writes it: Rust's shortest text that reads back to the same value.
pub fn format_number(v: f64) -> String {
    format!("{v}")
}

/// The variants of a sweep: the keys and each variant's values (text and TOML).
#[derive(Debug, Clone, PartialEq)]
pub struct Variants {
    /// The keys, in the table's column order.
    pub keys: Vec<KeyPath>,
    /// Per variant, one value per key.
    pub rows: Vec<Vec<(String, toml::Value)>>,
}

impl Variants {
    /// The variants of `vary` (each `KEY=START:STOP:STEP` or `KEY=A,B,C`: their product)
    /// or of `table` (CSV text), one of the two.
    pub fn from_arguments(vary: &[String], table: Option<&str>) -> Result<Self, SweepError> {
        match (vary.is_empty(), table) {
            (false, None) => {
                let varies = vary.iter().map(|v| v.parse::<Vary>()).collect::<Result<Vec<_>, _>>()?;
                Self::product(&varies)
            }
            (true, Some(table)) => Self::from_csv(table),
            (false, Some(_)) => Err(SweepError::Variants(
                "give ranges (--vary) or a table of variants, not both",
            )),
            (true, None) => Err(SweepError::Variants(
                "nothing to sweep: give --vary KEY=START:STOP:STEP (or KEY=A,B,C), or a table of variants (--variants FILE.csv)",
            )),
        }
    }

    /// The product of the ranges, the first varied slowest.
    pub fn product(varies: &[Vary]) -> Result<Self, SweepError> {
        let mut rows: Vec<Vec<(String, toml::Value)>> = vec![Vec::new()];
        for vary in varies {
            if rows.len().saturating_mul(vary.values.len()) > MAX_RANGE_VALUES {
                return Err(SweepError::BadRange {
                    given: vary.key.to_string(),
                    why: format!("the product of the ranges passes {MAX_RANGE_VALUES} variants"),
                });
            }
            rows = rows
                .into_iter()
                .flat_map(|row| {
                    vary.values.iter().map(move |value| {
                        let mut row = row.clone();
                        row.push(value.clone());
                        row
                    })
                })
                .collect();
        }
        Ok(Self {
            keys: varies.iter().map(|v| v.key.clone()).collect(),
            rows,
        })
    }

    /// The rows of a CSV table whose header names the keys; each cell a value as
    /// [`parse_value`] reads it.
    pub fn from_csv(text: &str) -> Result<Self, SweepError> {
        let mut reader = csv::ReaderBuilder::new().has_headers(true).from_reader(text.as_bytes());
        let bad = |place: String, why: String| SweepError::BadTable { place, why };
        let header = reader
            .headers()
            .map_err(|e| bad("row 1".into(), e.to_string()))?
            .clone();
        let keys = header
            .iter()
            .map(|k| k.trim().parse::<KeyPath>())
            .collect::<Result<Vec<_>, _>>()?;
        if keys.is_empty() {
            return Err(bad("row 1".into(), "no keys in the header".into()));
        }
        let mut rows = Vec::new();
        for (i, record) in reader.records().enumerate() {
            let record = record.map_err(|e| bad(format!("row {}", i + 2), e.to_string()))?;
            if record.len() != keys.len() {
                return Err(bad(
                    format!("row {}", i + 2),
                    format!("{} cells where the header names {} keys", record.len(), keys.len()),
                ));
            }
            rows.push(record.iter().map(|s| (s.trim().to_string(), parse_value(s))).collect());
        }
        Ok(Self { keys, rows })
    }

    /// The scene text of variant `index`: the user's scene with its keys set, as TOML.
    pub fn scene_text(&self, base: &toml::Table, index: usize) -> Result<String, SweepError> {
        let mut table = base.clone();
        for (key, (_, value)) in self.keys.iter().zip(&self.rows[index]) {
            key.set(&mut table, value)?;
        }
        toml::to_string(&table).map_err(|e| SweepError::NotToml(e.to_string()))
    }
}

/// Every N-th variant: `I/N` takes the variants whose index (from 0) is I - 1 modulo N.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// I, from 1.
    pub part: usize,
    /// N.
    pub parts: usize,
}

impl std::str::FromStr for Shard {
    type Err = SweepError;

    fn from_str(given: &str) -> Result<Self, SweepError> {
        let bad = |why: &str| SweepError::BadShard {
            given: given.to_string(),
            why: why.to_string(),
        };
        let (i, n) = given.split_once('/').ok_or_else(|| bad("give I/N, as 2/8"))?;
        let (part, parts) = (
            i.trim().parse::<usize>().map_err(|_| bad("I is not a whole number"))?,
            n.trim().parse::<usize>().map_err(|_| bad("N is not a whole number"))?,
        );
        if parts == 0 || part == 0 || part > parts {
            return Err(bad("I must lie in 1..=N and N be at least 1"));
        }
        Ok(Self { part, parts })
    }
}

impl Shard {
    /// The whole sweep.
    pub const ALL: Self = Self { part: 1, parts: 1 };

    /// True when variant `index` is this shard's.
    pub fn takes(&self, index: usize) -> bool {
        index % self.parts == self.part - 1
    }
}

/// A variant's outcome.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// Designed, and every clearance met.
    Pass,
    /// Designed, and a clearance not met.
    Fail,
    /// Designed without an interference check (a scene without a wing).
    Unchecked,
    /// Not designed: the `error` column says why.
    Error,
}

impl Verdict {
    /// As the table writes it.
    pub fn as_str(self) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::Fail => "fail",
            Verdict::Unchecked => "unchecked",
            Verdict::Error => "error",
        }
    }
}

/// The whole wing's figures of a designed variant (the study's per-station figures
/// gathered; every station the scene designs).
#[derive(Debug, Clone, PartialEq)]
pub struct WingFigures {
    /// Deepest fairing, % of its flap chord.
    pub fairing_depth_percent_flap_chord: f64,
    /// Longest fairing, % of its flap chord.
    pub fairing_length_percent_flap_chord: f64,
    /// Largest actuator load of any station (N for screw jacks, N m for rotary actuators:
    /// a wing of one actuator type compares like with like).
    pub max_actuator_load: f64,
    /// Largest peak power of any station (W).
    pub peak_power_w: f64,
    /// The stations' work per deployment, summed (J).
    pub work_per_deployment_j: f64,
    /// The stations' sized mechanism masses, summed (kg).
    pub mechanism_mass_kg: f64,
    /// The largest gap or overlap miss of any station at any setting (% of the local
    /// chord, magnitude).
    pub max_setting_miss_percent_chord: f64,
    /// The smallest clearance of any checked pair (m); none without a pair.
    pub min_clearance_m: Option<f64>,
}

/// One variant's row.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRow {
    /// Its index among the sweep's variants (from 0).
    pub variant: usize,
    /// Its values as given, one per key.
    pub values: Vec<String>,
    /// SHA-256 of its scene text, hex (empty where no text could be made).
    pub scene_sha256: String,
    /// Its outcome.
    pub verdict: Verdict,
    /// Its figures where designed.
    pub figures: Option<WingFigures>,
    /// Warnings the design raised.
    pub warnings: usize,
    /// Why it was not designed.
    pub error: Option<String>,
}

/// The table's columns after the keys.
pub const FIGURE_COLUMNS: [&str; 12] = [
    "scene_sha256",
    "verdict",
    "fairing_depth_percent_flap_chord",
    "fairing_length_percent_flap_chord",
    "max_actuator_load",
    "peak_power_w",
    "work_per_deployment_j",
    "mechanism_mass_kg",
    "max_setting_miss_percent_chord",
    "min_clearance_m",
    "warnings",
    "error",
];

/// The table's header: `variant`, the keys, then the figures.
pub fn csv_header(keys: &[KeyPath]) -> Vec<String> {
    std::iter::once("variant".to_string())
        .chain(keys.iter().map(|k| k.to_string()))
        .chain(FIGURE_COLUMNS.iter().map(|c| c.to_string()))
        .collect()
}

impl SweepRow {
    /// The row's cells, in [`csv_header`]'s order.
    pub fn csv_record(&self) -> Vec<String> {
        let number = |v: Option<f64>| v.map_or(String::new(), format_number);
        let f = self.figures.as_ref();
        std::iter::once(self.variant.to_string())
            .chain(self.values.iter().cloned())
            .chain([
                self.scene_sha256.clone(),
                self.verdict.as_str().to_string(),
                number(f.map(|f| f.fairing_depth_percent_flap_chord)),
                number(f.map(|f| f.fairing_length_percent_flap_chord)),
                number(f.map(|f| f.max_actuator_load)),
                number(f.map(|f| f.peak_power_w)),
                number(f.map(|f| f.work_per_deployment_j)),
                number(f.map(|f| f.mechanism_mass_kg)),
                number(f.map(|f| f.max_setting_miss_percent_chord)),
                number(f.and_then(|f| f.min_clearance_m)),
                self.warnings.to_string(),
                self.error.clone().unwrap_or_default(),
            ])
            .collect()
    }
}

/// See [`Sweep::batch_size`].
const BATCH_PER_THREAD: usize = 4;

/// What every variant of a sweep shares: the user's scene as a TOML table, its files and
/// the wing cache.
pub struct Sweep<'a> {
    text: String,
    base: toml::Table,
    variants: Variants,
    files: &'a dyn FileSource,
    file: String,
    cache: WingCache,
}

impl<'a> Sweep<'a> {
    /// A sweep of `variants` of the scene `text` (from `file`, whose folder `files` reads).
    pub fn new(text: &str, file: &str, files: &'a dyn FileSource, variants: Variants) -> Result<Self, SweepError> {
        let base: toml::Table = text
            .parse()
            .map_err(|e: toml::de::Error| SweepError::NotToml(e.to_string()))?;
        // Every key must have its place in the scene: a typo fails the sweep before any
        // design, not each variant after it.
        if !variants.rows.is_empty() {
            variants.scene_text(&base, 0)?;
        }
        Ok(Self {
            text: text.to_string(),
            base,
            variants,
            files,
            file: file.to_string(),
            cache: WingCache::default(),
        })
    }

    /// The variants.
    pub fn variants(&self) -> &Variants {
        &self.variants
    }

    /// Variants to design between two appends to a table: a few per thread, so that an
    /// interrupted sweep loses little and every core stays busy.
    pub fn batch_size() -> usize {
        BATCH_PER_THREAD * rayon::current_num_threads().max(1)
    }

    /// Designs the variants at `indices` in parallel (rayon), rows in their order.
    pub fn design(&self, indices: &[usize]) -> Vec<SweepRow> {
        indices.par_iter().map(|&i| self.design_one(i)).collect()
    }

    /// Designs variant `index` (every error is the row's, never the sweep's).
    pub fn design_one(&self, index: usize) -> SweepRow {
        let values: Vec<String> = self.variants.rows[index].iter().map(|(text, _)| text.clone()).collect();
        let failed = |sha: String, error: String| SweepRow {
            variant: index,
            values: values.clone(),
            scene_sha256: sha,
            verdict: Verdict::Error,
            figures: None,
            warnings: 0,
            error: Some(error),
        };
        let text = match self.variants.scene_text(&self.base, index) {
            Ok(text) => text,
            Err(error) => return failed(String::new(), error.to_string()),
        };
        let sha = hex_sha256(&text);
        let mut scene = match Scene::from_file_text(&text, &self.file, self.files) {
            Ok(scene) => scene,
            // The variant's text is the user's with values changed: each problem is located
            // at its key in the user's file, and the row names the variant's values.
            Err(SceneError::Located(problems)) => {
                let located = SceneError::Invalid(problems.into_iter().map(|p| p.problem).collect())
                    .locate(&self.text, &self.file);
                return failed(sha, one_line(&located.to_string()));
            }
            Err(error) => return failed(sha, one_line(&error.to_string())),
        };
        for_a_table(&mut scene);
        let inputs = Inputs {
            scene: &scene,
            scene_text: &text,
            files: self.files,
            wing_cache: Some(&self.cache),
        };
        let sink = MemorySink::new();
        match pipeline::design(&inputs, Mode::Design, &sink) {
            Ok(outcome) => match wing_figures(&outcome.report) {
                Ok(figures) => SweepRow {
                    variant: index,
                    values,
                    scene_sha256: sha,
                    verdict: match outcome.summary.interference_passes {
                        Some(true) => Verdict::Pass,
                        Some(false) => Verdict::Fail,
                        None => Verdict::Unchecked,
                    },
                    figures: Some(figures),
                    warnings: outcome.report.warnings.len(),
                    error: None,
                },
                Err(error) => failed(sha, one_line(&error.chain_message())),
            },
            Err(error) => failed(sha, one_line(&error.chain_message())),
        }
    }
}

/// The outputs a table needs: the figures, no files for people or viewers.
fn for_a_table(scene: &mut Scene) {
    let outputs = &mut scene.outputs;
    outputs.stl = false;
    outputs.urdf = false;
    outputs.svg = false;
    outputs.gltf = false;
    outputs.kinematics = true;
    outputs.sizing = true;
    outputs.interference = scene.wing.is_some();
}

fn hex_sha256(text: &str) -> String {
    Sha256::digest(text.as_bytes())
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// A message on one line (a table cell).
fn one_line(message: &str) -> String {
    message.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The whole wing's figures from a design's report.
pub fn wing_figures(report: &Report) -> Result<WingFigures, Error> {
    let stations = report
        .stations
        .iter()
        .map(|station| crate::study::station_figures(report, station))
        .collect::<Result<Vec<_>, _>>()?;
    let max = |f: &dyn Fn(&crate::study::StationFigures) -> f64| stations.iter().map(f).fold(0.0, f64::max);
    let sum = |f: &dyn Fn(&crate::study::StationFigures) -> f64| stations.iter().map(f).sum::<f64>();
    let min_clearance_m = report.interference.as_ref().and_then(|i| {
        i.pairs
            .iter()
            .map(|p| p.clearance.min_clearance_m)
            .filter(|c| c.is_finite())
            .reduce(f64::min)
    });
    Ok(WingFigures {
        fairing_depth_percent_flap_chord: max(&|s| s.fairing_depth_percent_flap_chord),
        fairing_length_percent_flap_chord: max(&|s| s.fairing_length_percent_flap_chord),
        max_actuator_load: max(&|s| s.max_actuator_load),
        peak_power_w: max(&|s| s.peak_power_w),
        work_per_deployment_j: sum(&|s| s.work_per_deployment_j),
        mechanism_mass_kg: sum(&|s| s.mechanism_mass_kg),
        max_setting_miss_percent_chord: max(&|s| {
            s.setting_misses
                .iter()
                .map(|m| m.gap_miss_percent_chord.abs().max(m.overlap_miss_percent_chord.abs()))
                .fold(0.0, f64::max)
        }),
        min_clearance_m,
    })
}

/// The rows of an earlier table at `text` whose header is `header`: the variant indices it
/// holds and its rows as read. `None` when the header differs (a table of another sweep,
/// or not Flapwright's).
pub fn rows_done(text: &str, header: &[String]) -> Option<Vec<(usize, Vec<String>)>> {
    // Every row the table writes ends in a newline: text after the last one is a row an
    // interrupted run cut short (the CSV reader would take an unclosed quote for a whole
    // cell), designed again.
    let text = &text[..text.rfind('\n').map_or(0, |p| p + 1)];
    let mut reader = csv::ReaderBuilder::new().has_headers(true).from_reader(text.as_bytes());
    let found: Vec<String> = reader.headers().ok()?.iter().map(|s| s.to_string()).collect();
    if found != header {
        return None;
    }
    let mut rows = Vec::new();
    for record in reader.records() {
        let Ok(record) = record else { continue };
        if record.len() != header.len() {
            continue;
        }
        let Ok(index) = record[0].parse::<usize>() else {
            continue;
        };
        rows.push((index, record.iter().map(|s| s.to_string()).collect()));
    }
    Some(rows)
}

/// The table's bytes: the header and `rows` (cells), sorted by variant.
pub fn csv_bytes(header: &[String], rows: &[Vec<String>]) -> Vec<u8> {
    let mut writer = csv::WriterBuilder::new()
        .terminator(csv::Terminator::Any(b'\n'))
        .from_writer(Vec::new());
    // Writing to memory cannot fail.
    let _ = writer.write_record(header);
    for row in rows {
        let _ = writer.write_record(row);
    }
    writer.into_inner().unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(text: &str) -> toml::Table {
        text.parse().unwrap()
    }

    #[test]
    fn a_key_path_sets_a_key_by_index_by_name_and_in_every_element() {
        let mut scene = table("[design]\n[[flap]]\nname = \"a\"\nx = 1.0\n[[flap]]\nname = \"b\"\nx = 1.0\n");
        let two = toml::Value::Float(2.0);
        "flap[1].x".parse::<KeyPath>().unwrap().set(&mut scene, &two).unwrap();
        assert_eq!(scene["flap"][1]["x"].as_float(), Some(2.0));
        assert_eq!(scene["flap"][0]["x"].as_float(), Some(1.0));
        "flap[a].x"
            .parse::<KeyPath>()
            .unwrap()
            .set(&mut scene, &toml::Value::Float(3.0))
            .unwrap();
        assert_eq!(scene["flap"][0]["x"].as_float(), Some(3.0));
        "flap[*].y".parse::<KeyPath>().unwrap().set(&mut scene, &two).unwrap();
        assert!(scene["flap"]
            .as_array()
            .unwrap()
            .iter()
            .all(|f| f["y"].as_float() == Some(2.0)));
        // A key the scene leaves at its default may be set, in a table it leaves out too;
        // an array of tables it lacks may not be made.
        let key = |text: &str| text.parse::<KeyPath>().unwrap();
        key("design.actuator_load_weight").set(&mut scene, &two).unwrap();
        key("outputs.svg")
            .set(&mut scene, &toml::Value::Boolean(false))
            .unwrap();
        assert_eq!(scene["outputs"]["svg"].as_bool(), Some(false));
        let missing = key("station[0].name").set(&mut scene, &two).unwrap_err();
        assert_eq!(missing.to_string(), "key `station[0].name`: the scene has no `station`");
        let beyond = "flap[2].x"
            .parse::<KeyPath>()
            .unwrap()
            .set(&mut scene, &two)
            .unwrap_err();
        assert_eq!(beyond.to_string(), "key `flap[2].x`: `flap` has 2 elements, no [2]");
        let unnamed = "flap[c].x"
            .parse::<KeyPath>()
            .unwrap()
            .set(&mut scene, &two)
            .unwrap_err();
        assert!(
            unnamed.to_string().contains("no element named c (its names: a, b)"),
            "{unnamed}"
        );
    }

    #[test]
    fn a_whole_number_stays_an_integer_where_the_scene_has_one() {
        let mut scene = table("[interference]\nmax_evaluations = 1200\n");
        let key: KeyPath = "interference.max_evaluations".parse().unwrap();
        key.set(&mut scene, &toml::Value::Float(2400.0)).unwrap();
        assert_eq!(scene["interference"]["max_evaluations"].as_integer(), Some(2400));
    }

    #[test]
    fn bad_keys_ranges_and_shards_are_refused_with_what_to_give() {
        for bad in ["", "a..b", "a[", "a[]", "a]b", "a b"] {
            assert!(bad.parse::<KeyPath>().is_err(), "{bad:?} parsed");
        }
        for bad in ["x", "x=1:2", "x=2:1:0.5", "x=1:2:0", "x=1:2:0.3", "x=a:2:1"] {
            assert!(bad.parse::<Vary>().is_err(), "{bad:?} parsed");
        }
        for bad in ["1", "0/2", "3/2", "1/0", "a/b"] {
            assert!(bad.parse::<Shard>().is_err(), "{bad:?} parsed");
        }
    }

    #[test]
    fn a_range_gives_each_value_from_its_start_rounded_to_twelve_digits() {
        let vary: Vary = "flap[*].settings.landing_gap_percent=1.5:2.5:0.005".parse().unwrap();
        assert_eq!(vary.values.len(), 201);
        assert_eq!(vary.values[60].0, "1.8");
        assert_eq!(vary.values[200].0, "2.5");
        let list: Vary = "station[*].mechanism.kind=four-bar, \"dropped-hinge\"".parse().unwrap();
        assert_eq!(list.values[0].1, toml::Value::String("four-bar".into()));
        assert_eq!(list.values[1].1, toml::Value::String("dropped-hinge".into()));
    }

    #[test]
    fn the_product_varies_the_first_key_slowest_and_shards_split_it_whole() {
        let a: Vary = "a=1:2:1".parse().unwrap();
        let b: Vary = "b=x,y,z".parse().unwrap();
        let variants = Variants::product(&[a, b]).unwrap();
        let cells: Vec<String> = variants.rows.iter().map(|r| format!("{}{}", r[0].0, r[1].0)).collect();
        assert_eq!(cells, ["1x", "1y", "1z", "2x", "2y", "2z"]);
        let shards: Vec<Shard> = (1..=4).map(|i| format!("{i}/4").parse().unwrap()).collect();
        for index in 0..variants.rows.len() {
            assert_eq!(shards.iter().filter(|s| s.takes(index)).count(), 1);
        }
    }

    #[test]
    fn a_variants_table_reads_its_keys_and_cells_and_names_a_short_row() {
        let variants = Variants::from_csv(
            "design.actuator_load_weight,station[0].mechanism.kind\n0.1,four-bar\n0.3,\"link-track\"\n",
        )
        .unwrap();
        assert_eq!(variants.rows.len(), 2);
        assert_eq!(variants.rows[1][0].1, toml::Value::Float(0.3));
        let short = Variants::from_csv("a,b\n1\n").unwrap_err();
        assert!(short.to_string().contains("row 2"), "{short}");
    }

    #[test]
    fn an_earlier_table_is_read_back_only_with_the_same_header() {
        let header = csv_header(&["a".parse().unwrap()]);
        let row = SweepRow {
            variant: 3,
            values: vec!["1.5".into()],
            scene_sha256: "ab".into(),
            verdict: Verdict::Error,
            figures: None,
            warnings: 0,
            error: Some("no, \"really\"".into()),
        };
        let bytes = csv_bytes(&header, &[row.csv_record()]);
        let text = String::from_utf8(bytes).unwrap();
        let done = rows_done(&text, &header).unwrap();
        assert_eq!(done, vec![(3, row.csv_record())]);
        let other = csv_header(&["b".parse().unwrap()]);
        assert!(rows_done(&text, &other).is_none());
        // Cut short mid-row: that row is left to design again.
        assert_eq!(rows_done(&text[..text.len() - 5], &header).unwrap(), vec![]);
    }
}
