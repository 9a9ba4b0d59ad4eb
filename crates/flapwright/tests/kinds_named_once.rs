//! The recipe for adding a kind (`docs/architecture.md`) holds: outside a kind's own modules
//! (`crates/kinds/src/<kind>/`, `crates/flapwright/src/kinds/<kind>.rs`), only the kind
//! registry and the scene enum (`crates/flapwright/src/kinds/mod.rs`) and the kinds crate's
//! table of contents (`crates/kinds/src/lib.rs`) name a kind in code; no kind names
//! another. Comments and `#[cfg(test)]` items are not code here: tests may pick kinds.
//!
//! A kind is named by its type prefix (`FourBar`, matching `FourBarSpec`,
//! `FourBarScene`, ...) or by its scene name as a string literal (`"four-bar"`).

use std::path::{Path, PathBuf};

use flapwright::kinds::MechanismScene;

/// The workspace root (this crate sits at `crates/flapwright`).
fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Every `.rs` file below `dir`, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut pending = vec![dir.to_path_buf()];
    while let Some(dir) = pending.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                pending.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

/// The code of a source file: comment lines, trailing `//` comments and the items marked
/// `#[cfg(test)]` (brace-matched) removed; line numbers kept.
fn code_lines(text: &str) -> Vec<(usize, String)> {
    let mut lines = Vec::new();
    let mut skipping_test_item = false;
    let mut depth = 0i64;
    let mut opened = false;
    for (index, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("#[cfg(test)]") {
            skipping_test_item = true;
            depth = 0;
            opened = false;
            continue;
        }
        if skipping_test_item {
            depth += line.matches('{').count() as i64 - line.matches('}').count() as i64;
            opened |= line.contains('{');
            if (opened && depth <= 0) || (!opened && trimmed.ends_with(';')) {
                skipping_test_item = false;
            }
            continue;
        }
        if trimmed.starts_with("//") {
            continue;
        }
        let code = match line.find(" // ") {
            Some(at) => &line[..at],
            None => line,
        };
        lines.push((index + 1, code.to_owned()));
    }
    lines
}

/// `five-bar` -> (`five_bar`, `FiveBar`).
fn module_and_type(scene_name: &str) -> (String, String) {
    let module = scene_name.replace('-', "_");
    let type_prefix = scene_name
        .split('-')
        .map(|word| {
            let mut chars = word.chars();
            chars
                .next()
                .map(|c| c.to_ascii_uppercase().to_string() + chars.as_str())
                .unwrap_or_default()
        })
        .collect();
    (module, type_prefix)
}

#[test]
fn only_a_kinds_own_modules_its_registry_row_and_the_scene_enum_name_it() {
    let root = workspace();
    let crates = root.join("crates");
    let kinds: Vec<(&str, String, String)> = MechanismScene::KINDS
        .iter()
        .map(|name| {
            let (module, type_prefix) = module_and_type(name);
            (*name, module, type_prefix)
        })
        .collect();
    // The kinds crate has one module per kind, named as the scene names it.
    for (name, module, _) in &kinds {
        assert!(
            crates.join("kinds/src").join(module).is_dir(),
            "kind `{name}`: no folder crates/kinds/src/{module}/"
        );
        assert!(
            crates
                .join("flapwright/src/kinds")
                .join(format!("{module}.rs"))
                .is_file(),
            "kind `{name}`: no registry module crates/flapwright/src/kinds/{module}.rs"
        );
    }
    let registry = [
        crates.join("flapwright/src/kinds/mod.rs"),
        crates.join("kinds/src/lib.rs"),
    ];
    let mut files_read = 0;
    let mut offences = Vec::new();
    let mut crate_dirs: Vec<PathBuf> = std::fs::read_dir(&crates).unwrap().map(|e| e.unwrap().path()).collect();
    crate_dirs.sort();
    for crate_dir in crate_dirs {
        for file in rust_files(&crate_dir.join("src")) {
            if registry
                .iter()
                .any(|r| r.canonicalize().unwrap() == file.canonicalize().unwrap())
            {
                continue;
            }
            files_read += 1;
            let text = std::fs::read_to_string(&file).unwrap();
            let relative = file.strip_prefix(&root).unwrap_or(&file).display().to_string();
            let code = code_lines(&text);
            for (name, module, type_prefix) in &kinds {
                let own = relative.starts_with(&format!("crates/kinds/src/{module}/"))
                    || relative == format!("crates/flapwright/src/kinds/{module}.rs");
                if own {
                    continue;
                }
                let literal = format!("\"{name}\"");
                for (line, text) in &code {
                    if text.contains(type_prefix.as_str()) || text.contains(&literal) {
                        offences.push(format!("{relative}:{line}: names `{name}`: {}", text.trim()));
                    }
                }
            }
        }
    }
    assert!(
        files_read > 100,
        "read only {files_read} source files: is the workspace where this test thinks?"
    );
    assert!(
        offences.is_empty(),
        "kinds named outside their modules:\n{}",
        offences.join("\n")
    );
}

#[test]
fn the_scan_sees_a_kind_named_in_code_and_ignores_comments_and_tests() {
    let text = "// FourBar in a comment\nlet x = FourBarSpec::default(); // FourBar\n#[cfg(test)]\nmod tests {\n    fn f() { let k = \"four-bar\"; }\n}\nlet y = 1;\n";
    let code = code_lines(text);
    assert_eq!(code.len(), 2, "{code:?}");
    assert_eq!(code[0], (2, "let x = FourBarSpec::default();".to_owned()));
    assert_eq!(code[1], (7, "let y = 1;".to_owned()));
    assert_eq!(
        module_and_type("circular-arc-track"),
        ("circular_arc_track".to_owned(), "CircularArcTrack".to_owned())
    );
}
