//! Shared helpers: the thesis track and the validation tables in `data/validation/`.

use std::collections::HashMap;
use std::path::PathBuf;

use flapwright_kinds::{CircularArcTrack, CircularArcTrackSpec};

/// mm per m.
pub const MM: f64 = 1000.0;

/// The synthesised thesis case study.
pub fn thesis_track() -> CircularArcTrack {
    CircularArcTrack::synthesise(CircularArcTrackSpec::thesis_case_study()).expect("thesis case synthesises")
}

/// A validation CSV (comment lines start with '#'): header and rows of raw cell strings.
/// A parsed validation table.
pub struct Table {
    /// Column names.
    pub header: Vec<String>,
    /// Raw cells.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// Index of a column.
    pub fn column(&self, name: &str) -> usize {
        self.header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("column {name} missing"))
    }

    /// A cell as a number.
    pub fn number(&self, row: usize, name: &str) -> f64 {
        self.rows[row][self.column(name)]
            .parse()
            .unwrap_or_else(|_| panic!("row {row} column {name} is not a number"))
    }

    /// Half a unit in the last printed digit of a cell: its printing resolution.
    pub fn resolution(&self, row: usize, name: &str) -> f64 {
        let cell = &self.rows[row][self.column(name)];
        let decimals = cell.split('.').nth(1).map_or(0, str::len);
        0.5 * 10f64.powi(-(decimals as i32))
    }

    /// Rows keyed by the first column.
    pub fn by_key(&self) -> HashMap<String, Vec<String>> {
        self.rows.iter().map(|row| (row[0].clone(), row.clone())).collect()
    }
}

/// Loads `data/validation/<name>` of the workspace.
pub fn load_table(name: &str) -> Table {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/validation")
        .join(name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text
        .lines()
        .map(str::trim)
        .filter(|line| !line.is_empty() && !line.starts_with('#'));
    let split = |line: &str| line.split(',').map(|c| c.trim().to_owned()).collect::<Vec<_>>();
    let header = split(lines.next().expect("header"));
    let rows = lines.map(split).collect();
    Table { header, rows }
}

/// Nut position of spreadsheet row `row` (m): s34,i + 10 mm * row, clamped at s34,f.
pub fn spreadsheet_input_m(track: &CircularArcTrack, row: usize) -> f64 {
    let synthesis = track.synthesis();
    (synthesis.stroke_start_m + 0.010 * row as f64).min(synthesis.stroke_end_m)
}

/// `computed` agrees with a printed value to 1e-4 relative, or to the printing resolution
/// when the print has fewer digits than that.
pub fn assert_matches_print(computed: f64, printed: f64, resolution: f64, what: &str) {
    let tolerance = (1e-4 * printed.abs()).max(resolution);
    assert!(
        (computed - printed).abs() <= tolerance,
        "{what}: computed {computed}, printed {printed}, tolerance {tolerance}"
    );
}
