//! What a sweep designs: ranges and lists of values, a table of variants, a shard of them.

use super::keys::{parse_value, KeyPath};
use super::SweepError;

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
