//! Reader for the CSV files in `data/validation/` (comment lines start with `#`).

use std::path::PathBuf;

/// Rows of a validation CSV as strings, header removed.
pub fn rows(file: &str) -> Vec<Vec<String>> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../data/validation")
        .join(file);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text
        .lines()
        .filter(|l| !l.trim_start().starts_with('#') && !l.trim().is_empty());
    lines.next().expect("header row");
    lines
        .map(|l| l.split(',').map(|c| c.trim().to_owned()).collect())
        .collect()
}

/// A cell parsed as f64.
pub fn number(cell: &str) -> f64 {
    cell.parse().unwrap_or_else(|e| panic!("{cell}: {e}"))
}
