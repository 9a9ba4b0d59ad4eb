//! The commands that help write a scene: `init` (a template that designs as written),
//! `kinds` (the mechanism kinds and their keys) and `schema` (the scene's JSON Schema).

use std::path::Path;

use anyhow::Context;
use flapwright::kinds::{KindSummary, MechanismScene};
use flapwright::scene::{scene_schema, template, template_kinds, SCHEMA_FILE_NAME, SCHEMA_ID};
use flapwright_cli::output;

use crate::{bad_input, Cli, Failure};

/// `flapwright init [--kind K] [FILE]`: writes the template with every station of `kind`,
/// and the schema its first line names beside it (unless a schema Flapwright did not write
/// is there).
pub fn init(cli: &Cli, kind: &str, file: &Path) -> Result<(), Failure> {
    let text = template(kind).ok_or_else(|| {
        bad_input(anyhow::anyhow!(
            "--kind {kind}: the template is written with a kind synthesised from the flap settings: {}; {}",
            template_kinds().join(", "),
            match MechanismScene::KINDS.contains(&kind) {
                true => "this one is given by its dimensions (`flapwright kinds` lists its keys; data/scenes/ has a scene with it)",
                false => "`flapwright kinds` lists every kind",
            }
        ))
    })?;
    if file.is_dir() {
        return Err(bad_input(anyhow::anyhow!(
            "{} is a folder: name the scene file to write",
            file.display()
        )));
    }
    let replaced = file.exists();
    if replaced && !cli.force {
        return Err(bad_input(anyhow::anyhow!(
            "{} exists: init never replaces a scene (it may hold your edits); name another file, or pass --force to replace it",
            file.display()
        )));
    }
    output::write_file_atomically(file, text.as_bytes()).with_context(|| format!("writing {}", file.display()))?;
    let schema_path = file.parent().unwrap_or(Path::new("")).join(SCHEMA_FILE_NAME);
    let schema = write_schema_beside(&schema_path)?;
    if cli.json {
        println!(
            "{}",
            serde_json::json!({
                "scene": file.display().to_string(),
                "kind": kind,
                "schema": schema.written.then(|| schema_path.display().to_string()),
            })
        );
    } else if !cli.quiet {
        if replaced {
            eprintln!("--force: replaced {}", file.display());
        }
        if let Some(notice) = &schema.notice {
            eprintln!("warning: {notice}");
        }
        println!(
            "wrote {} (a small swept wing, one flap on two {kind} stations){}; next: flapwright design {}",
            file.display(),
            match schema.written {
                true => format!(" and {}", schema_path.display()),
                false => String::new(),
            },
            file.display()
        );
    }
    Ok(())
}

/// What became of the schema file beside a new scene.
struct SchemaBeside {
    /// Written (absent before, or a schema Flapwright wrote).
    written: bool,
    /// Why it was left alone.
    notice: Option<String>,
}

/// Writes the scene schema to `path` unless a file Flapwright did not write is there.
fn write_schema_beside(path: &Path) -> Result<SchemaBeside, Failure> {
    let schema = scene_schema();
    if let Ok(existing) = std::fs::read_to_string(path) {
        if existing == schema {
            return Ok(SchemaBeside {
                written: false,
                notice: None,
            });
        }
        if !existing.contains(SCHEMA_ID) {
            return Ok(SchemaBeside {
                written: false,
                notice: Some(format!(
                    "{} exists and Flapwright did not write it: left alone, so the scene's `#:schema` line names that file (`flapwright schema > FILE` writes the scene schema elsewhere)",
                    path.display()
                )),
            });
        }
    } else if path.exists() {
        return Ok(SchemaBeside {
            written: false,
            notice: Some(format!("{} exists and cannot be read: left alone", path.display())),
        });
    }
    output::write_file_atomically(path, schema.as_bytes()).with_context(|| format!("writing {}", path.display()))?;
    Ok(SchemaBeside {
        written: true,
        notice: None,
    })
}

/// `flapwright kinds`: one line a kind, then the keys it needs and may take.
pub fn kinds(cli: &Cli) -> Result<(), Failure> {
    let summaries = MechanismScene::summaries();
    if cli.json {
        println!("{}", serde_json::to_string(&summaries)?);
    } else if !cli.quiet {
        print!("{}", kinds_text(&summaries));
    }
    Ok(())
}

/// The `kinds` listing: the name and its line, then `needs:` and `may take:`.
fn kinds_text(summaries: &[KindSummary]) -> String {
    let width = summaries.iter().map(|k| k.name.len()).max().unwrap_or(0);
    let mut text = String::new();
    for kind in summaries {
        text += &format!("{:width$}  {}\n", kind.name, kind.summary);
        let needs = match kind.required_keys.as_slice() {
            [] => "nothing".to_string(),
            keys => keys.join(", "),
        };
        text += &wrapped(&format!("needs: kind, {needs}"), width + 2);
        if !kind.optional_keys.is_empty() {
            text += &wrapped(&format!("may take: {}", kind.optional_keys.join(", ")), width + 2);
        }
    }
    text += &format!(
        "\n`flapwright init --kind KIND` writes a scene with one of {}; the keys are under [station.mechanism] (docs/scene.md).\n",
        template_kinds().join(", ")
    );
    text
}

/// Lines of at most [`LINE_WIDTH`] characters (a word longer than that stands alone), each
/// indented by `indent` spaces.
fn wrapped(text: &str, indent: usize) -> String {
    let mut lines = vec![String::new()];
    for word in text.split(' ') {
        let line = lines.last_mut().expect("one line at least");
        if !line.is_empty() && indent + line.len() + 1 + word.len() > LINE_WIDTH {
            lines.push(word.to_string());
        } else {
            if !line.is_empty() {
                line.push(' ');
            }
            line.push_str(word);
        }
    }
    lines.iter().map(|line| format!("{:indent$}{line}\n", "")).collect()
}

/// The width `kinds` wraps its key lists at.
const LINE_WIDTH: usize = 100;

/// `flapwright schema`: the scene's JSON Schema on stdout.
pub fn schema() -> Result<(), Failure> {
    print!("{}", scene_schema());
    Ok(())
}
