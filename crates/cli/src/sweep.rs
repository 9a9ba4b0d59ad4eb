//! `flapwright sweep`: the variants of a scene designed in parallel into one table,
//! resumable and split into shards (`flapwright::sweep`).

use std::io::Write;
use std::path::Path;
use std::time::Instant;

use flapwright::scene::Scene;
use flapwright::sweep::{csv_bytes, csv_header, rows_done, Shard, Sweep, Variants, Verdict};

use crate::{bad_input, read_scene_text, Cli, Failure, EXIT_FAILED};

/// The table's file in the output folder.
pub(crate) const TABLE: &str = "sweep.csv";

/// What `flapwright sweep` was asked.
pub(crate) struct SweepArgs<'a> {
    pub scene: Option<&'a Path>,
    pub out: &'a Path,
    pub vary: &'a [String],
    pub variants: Option<&'a Path>,
    pub shard: Option<&'a str>,
}

pub(crate) fn sweep(cli: &Cli, args: &SweepArgs<'_>) -> Result<(), Failure> {
    let bad = |e: flapwright::sweep::SweepError| bad_input(anyhow::Error::new(e));
    let (text, files) = read_scene_text(args.scene)?;
    let label = args
        .scene
        .map_or("(embedded default)".into(), |p| p.display().to_string());
    // The user's own scene first: its problems located in its own file.
    Scene::from_file_text(&text, &label, files.as_ref())
        .map_err(|e| bad_input(anyhow::Error::new(e).context(format!("invalid scene {label}"))))?;
    let table = match args.variants {
        Some(path) => Some(std::fs::read_to_string(path).map_err(|e| {
            bad_input(anyhow::Error::new(e).context(format!("reading variants table {}", path.display())))
        })?),
        None => None,
    };
    let variants = Variants::from_arguments(args.vary, table.as_deref()).map_err(|e| match args.variants {
        Some(path) => bad_input(anyhow::Error::new(e).context(format!("variants table {}", path.display()))),
        None => bad(e),
    })?;
    let shard = match args.shard {
        Some(given) => given.parse::<Shard>().map_err(bad)?,
        None => Shard::ALL,
    };
    let sweep = Sweep::new(&text, &label, files.as_ref(), variants).map_err(bad)?;
    let header = csv_header(&sweep.variants().keys);
    let table_path = args.out.join(TABLE);
    std::fs::create_dir_all(args.out)
        .map_err(|e| failed(anyhow::Error::new(e).context(format!("creating {}", args.out.display()))))?;
    // An earlier table of the same sweep: its rows are kept and not designed again. A
    // file of that name with another header is not ours to replace.
    let mut done: Vec<(usize, Vec<String>)> = match std::fs::read_to_string(&table_path) {
        Ok(earlier) => match rows_done(&earlier, &header) {
            Some(rows) => rows,
            None if cli.force => Vec::new(),
            None => {
                return Err(bad_input(anyhow::anyhow!(
                "{} is not a table of this sweep (its header differs): give another --out, or --force to replace it",
                table_path.display()
            )))
            }
        },
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Vec::new(),
        Err(e) => {
            return Err(failed(
                anyhow::Error::new(e).context(format!("reading {}", table_path.display())),
            ))
        }
    };
    let count = sweep.variants().rows.len();
    done.retain(|(index, _)| *index < count && shard.takes(*index));
    done.sort_by_key(|(index, _)| *index);
    done.dedup_by_key(|(index, _)| *index);
    let to_design: Vec<usize> = (0..count)
        .filter(|&i| shard.takes(i) && done.binary_search_by_key(&i, |(index, _)| *index).is_err())
        .collect();
    // The table as it stands, rows appended as they are designed.
    write_table(
        &table_path,
        &csv_bytes(&header, &done.iter().map(|(_, r)| r.clone()).collect::<Vec<_>>()),
    )?;
    let mut table = std::fs::OpenOptions::new()
        .append(true)
        .open(&table_path)
        .map_err(|e| failed(anyhow::Error::new(e).context(format!("opening {}", table_path.display()))))?;
    if !cli.quiet && !done.is_empty() {
        eprintln!(
            "{}: {} variants already in the table, kept",
            table_path.display(),
            done.len()
        );
    }
    let started = Instant::now();
    let batch = Sweep::batch_size();
    let mut designed = 0;
    for chunk in to_design.chunks(batch) {
        let rows = sweep.design(chunk);
        let cells: Vec<Vec<String>> = rows.iter().map(|r| r.csv_record()).collect();
        let bytes = csv_bytes(&header, &cells);
        // The header is already in the file: the rows alone.
        let body = &bytes[bytes.iter().position(|&b| b == b'\n').map_or(0, |p| p + 1)..];
        table
            .write_all(body)
            .and_then(|()| table.flush())
            .map_err(|e| failed(anyhow::Error::new(e).context(format!("writing {}", table_path.display()))))?;
        done.extend(rows.iter().map(|r| (r.variant, r.csv_record())));
        designed += chunk.len();
        if !cli.quiet {
            let minutes = started.elapsed().as_secs_f64() / 60.0;
            eprintln!(
                "designed {designed}/{} variants ({:.1} a minute)",
                to_design.len(),
                designed as f64 / minutes.max(1e-9)
            );
        }
    }
    // The whole table in variant order: the same bytes however the run was split or resumed.
    done.sort_by_key(|(index, _)| *index);
    let rows: Vec<Vec<String>> = done.iter().map(|(_, r)| r.clone()).collect();
    write_table(&table_path, &csv_bytes(&header, &rows))?;
    let verdict_column = header.iter().position(|c| c == "verdict").unwrap_or(0);
    let tally = |verdict: Verdict| rows.iter().filter(|r| r[verdict_column] == verdict.as_str()).count();
    let (pass, fail, unchecked, errors) = (
        tally(Verdict::Pass),
        tally(Verdict::Fail),
        tally(Verdict::Unchecked),
        tally(Verdict::Error),
    );
    let summary = serde_json::json!({
        "table": table_path.display().to_string(),
        "variants": rows.len(),
        "pass": pass,
        "fail": fail,
        "unchecked": unchecked,
        "error": errors,
    });
    if cli.json {
        println!("{summary}");
    } else if !cli.quiet {
        eprintln!(
            "{}: {} variants: {pass} pass, {fail} fail, {unchecked} unchecked, {errors} not designed (see its error column)",
            table_path.display(),
            rows.len()
        );
    }
    // A sweep that designed nothing did not succeed.
    if !rows.is_empty() && errors == rows.len() {
        return Err(Failure {
            code: EXIT_FAILED,
            error: anyhow::anyhow!(
                "no variant could be designed (see the error column of {})",
                table_path.display()
            ),
            summary: Some(summary),
        });
    }
    Ok(())
}

fn failed(error: anyhow::Error) -> Failure {
    Failure {
        code: EXIT_FAILED,
        error,
        summary: None,
    }
}

/// Writes the table through a file beside it, renamed over it: a reader never sees half.
fn write_table(path: &Path, bytes: &[u8]) -> Result<(), Failure> {
    let partial = path.with_extension("csv.partial");
    std::fs::write(&partial, bytes)
        .and_then(|()| std::fs::rename(&partial, path))
        .map_err(|e| failed(anyhow::Error::new(e).context(format!("writing {}", path.display()))))
}
