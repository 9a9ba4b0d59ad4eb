//! What a sweep writes: a row per variant, the whole wing's figures, the CSV table.

use super::keys::KeyPath;
use super::variants::format_number;
use crate::error::Error;
use crate::report::Report;

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
