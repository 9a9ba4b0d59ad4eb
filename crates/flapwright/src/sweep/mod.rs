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
//!
//! - `keys`: [`KeyPath`] and [`parse_value`], a key of the scene and a value as typed;
//! - `variants`: [`Vary`], [`Variants`] and [`Shard`], what to design;
//! - `table`: [`SweepRow`], [`WingFigures`] and the CSV table, what comes out;
//! - here: [`Sweep`], which designs them, and [`SweepError`].

mod keys;
mod table;
mod variants;

pub use keys::{parse_value, KeyPath};
pub use table::{csv_bytes, csv_header, rows_done, wing_figures, SweepRow, Verdict, WingFigures, FIGURE_COLUMNS};
pub use variants::{format_number, Shard, Variants, Vary, MAX_RANGE_VALUES};

use rayon::prelude::*;
use sha2::{Digest, Sha256};

use crate::pipeline::{self, Inputs, Mode, WingCache};
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
