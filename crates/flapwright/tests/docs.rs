//! The README and `docs/` read on a screen (issue 40): the first screen holds the quick
//! start, the install and a first scene; no table cell runs past a few lines; every link
//! resolves; the README's scene is the shipped `minimal.toml`; its test command is CI's.

use std::path::{Path, PathBuf};

/// The workspace root (this crate sits at `crates/flapwright`).
fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The README and every Markdown file in `docs/`, with their paths.
fn documents() -> Vec<(PathBuf, String)> {
    let mut paths = vec![workspace().join("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(workspace().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    paths.extend(docs);
    paths
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap();
            (p, text)
        })
        .collect()
}

/// The longest table cell a reader takes in at a glance: about three lines of a table on a
/// laptop screen. Longer text belongs in a paragraph under the table.
const LONGEST_CELL: usize = 250;

/// A table row's cells (split at `|` outside backticks; `\|` is part of a cell).
fn cells(row: &str) -> Vec<String> {
    let body = row.trim().trim_start_matches('|').trim_end_matches('|');
    let (mut cells, mut cell, mut code) = (Vec::new(), String::new(), false);
    let mut chars = body.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                cell.push('|');
                chars.next();
            }
            '`' => {
                code = !code;
                cell.push(c);
            }
            '|' if !code => cells.push(std::mem::take(&mut cell).trim().to_string()),
            _ => cell.push(c),
        }
    }
    cells.push(cell.trim().to_string());
    cells
}

#[test]
fn no_table_cell_is_longer_than_a_glance() {
    let mut long = Vec::new();
    for (path, text) in documents() {
        for (number, line) in text.lines().enumerate() {
            if !line.starts_with('|') {
                continue;
            }
            for cell in cells(line) {
                if cell.chars().count() > LONGEST_CELL {
                    long.push(format!(
                        "{}:{}: {} characters",
                        path.display(),
                        number + 1,
                        cell.chars().count()
                    ));
                }
            }
        }
    }
    assert!(
        long.is_empty(),
        "cells longer than {LONGEST_CELL} characters:\n{}",
        long.join("\n")
    );
}

#[test]
fn the_readmes_first_screen_holds_the_quick_start_the_install_and_a_first_scene() {
    let readme = std::fs::read_to_string(workspace().join("README.md")).unwrap();
    let first_screen: String = readme.lines().take(60).collect::<Vec<_>>().join("\n");
    for needed in [
        "## Quick start",
        "cargo run --release",
        "cargo test --workspace --release",
        "## Install",
        "cargo install --path crates/cli",
        "## A first scene",
        "flapwright init",
        "flapwright design",
        "flapwright check",
    ] {
        assert!(
            first_screen.contains(needed),
            "the README's first 60 lines lack `{needed}`"
        );
    }
}

#[test]
fn the_readmes_test_command_is_the_one_ci_runs() {
    let readme = std::fs::read_to_string(workspace().join("README.md")).unwrap();
    let ci = std::fs::read_to_string(workspace().join(".ci/run")).unwrap();
    let command = "cargo test --workspace --release";
    assert!(readme.contains(&format!("{command}   # runs every test")));
    assert!(
        ci.lines().any(|line| line.trim() == command),
        ".ci/run does not run `{command}`"
    );
}

#[test]
fn the_readmes_scene_is_the_shipped_minimal_scene() {
    let readme = std::fs::read_to_string(workspace().join("README.md")).unwrap();
    let start = readme.find("```toml\n").expect("a TOML block") + "```toml\n".len();
    let block = &readme[start..start + readme[start..].find("```").unwrap()];
    let shipped = std::fs::read_to_string(workspace().join("data/scenes/minimal.toml")).unwrap();
    let without_header: String = shipped
        .lines()
        .skip_while(|line| line.starts_with('#'))
        .map(|line| format!("{line}\n"))
        .collect();
    assert_eq!(block, without_header);
}

#[test]
fn every_relative_link_resolves() {
    let mut broken = Vec::new();
    for (path, text) in documents() {
        let folder = path.parent().unwrap();
        let mut search = text.as_str();
        while let Some(at) = search.find("](") {
            let after = &search[at + 2..];
            let Some(end) = after.find(')') else { break };
            let target = &after[..end];
            search = &after[end..];
            if target.starts_with("http") || target.starts_with('#') || target.contains(' ') {
                continue;
            }
            let file = target.split('#').next().unwrap();
            if !folder.join(file).exists() {
                broken.push(format!("{}: {target}", path.display()));
            }
        }
    }
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}
