//! `flapwright`: designs the flap support and drive mechanisms of a wing from a scene file.

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Context;
mod authoring;
mod sweep;

use clap::{Parser, Subcommand};
use flapwright::pipeline::{self, Inputs, Mode};
use flapwright::scene::{FileSource, Folder, NoFiles, Scene, SceneError, StlSetting, DEFAULT_SCENE_TOML};
use flapwright_cli::output::{self, OutputError, StagedDir};

/// Exit code for bad input (scene file, flags).
const EXIT_BAD_INPUT: u8 = 2;
/// Exit code for a run that failed for another reason (I/O, a mechanism that cannot move).
const EXIT_FAILED: u8 = 1;

#[derive(Parser, Debug)]
#[command(
    name = "flapwright",
    version,
    about = "Designs trailing-edge flap support and drive mechanisms for a whole wing"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// Print nothing but errors.
    #[arg(long, global = true)]
    quiet: bool,
    /// Print a machine-readable summary (JSON) on stdout; on failure, a JSON error object.
    #[arg(long, global = true)]
    json: bool,
    /// Replace an output folder (or JUnit file) even when it holds files Flapwright did
    /// not write; the files removed are listed.
    #[arg(long, global = true)]
    force: bool,
}

/// `export --at`: the flap setting the STL files show.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum At {
    /// Flaps stowed (the URDF's and glTF's rest pose).
    Stowed,
    /// Each flap at its take-off deflection.
    Takeoff,
    /// Each flap at its landing deflection.
    Landing,
}

impl From<At> for StlSetting {
    fn from(at: At) -> Self {
        match at {
            At::Stowed => Self::Stowed,
            At::Takeoff => Self::Takeoff,
            At::Landing => Self::Landing,
        }
    }
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Write a commented scene to start from, which designs and passes `check` as written.
    ///
    /// A small swept wing, one flap on two stations, settings with gap and overlap targets,
    /// a flight load case. The scene schema is written beside it (`scene.schema.json`).
    Init {
        /// The scene file to write (never replaced without --force).
        #[arg(default_value = "scene.toml")]
        file: PathBuf,
        /// The stations' mechanism kind: one synthesised from the flap settings
        /// (`flapwright kinds`); default: the first of them.
        #[arg(long)]
        kind: Option<String>,
    },
    /// List the mechanism kinds: one line each, the keys each needs and may take.
    Kinds,
    /// Design a scene: geometry, planes, mechanisms, checks, sizing; writes report.json and the files.
    Design {
        /// Scene file (TOML). Without it, the embedded default scene (small aircraft of the thesis).
        scene: Option<PathBuf>,
        /// Output folder (replaced atomically on success).
        #[arg(long, default_value = "flapwright-out")]
        out: PathBuf,
    },
    /// Check clearances only: exit 0 when every clearance is met, 1 when not, 2 for bad input.
    ///
    /// Runs only the stages the interference check needs. A pair fails when it interferes
    /// or comes closer than `interference.required_clearance_m`, a joint when its parts
    /// come apart by more than `interference.joint_play_m`.
    Check {
        /// Scene file (TOML). Without it, the embedded default scene.
        scene: Option<PathBuf>,
        /// Output folder for report.json (replaced atomically on success).
        #[arg(long, default_value = "flapwright-check")]
        out: PathBuf,
        /// Also write a JUnit XML file (one test case per station and part pair; pairs the
        /// check leaves out are skipped cases with the reason).
        #[arg(long)]
        junit: Option<PathBuf>,
        /// Fail (exit 1) when any pair is left out of the check, whatever the reason.
        #[arg(long)]
        strict: bool,
    },
    /// Export files for viewers and people: URDF, STL, SVG, animated glTF.
    ///
    /// Without a flag, all of them. Runs only the stages those files need: STL, URDF and
    /// glTF need no interference check, kinematics or sizing; SVG needs the check (its
    /// failing pairs are marked) and the kinematics (its plots).
    Export {
        /// Scene file (TOML). Without it, the embedded default scene.
        scene: Option<PathBuf>,
        /// Output folder (replaced atomically on success).
        #[arg(long, default_value = "flapwright-export")]
        out: PathBuf,
        /// URDF of the wing and mechanisms, and a trajectory file.
        #[arg(long)]
        urdf: bool,
        /// One binary STL per part.
        #[arg(long)]
        stl: bool,
        /// SVG drawing and plots per station.
        #[arg(long)]
        svg: bool,
        /// Animated binary glTF (`<scene>.glb`) of the deployment.
        #[arg(long)]
        gltf: bool,
        /// Where the STL files show the flaps and mechanisms: stowed, or each flap at its
        /// take-off or landing deflection (with `--stl` alone: the URDF, glTF and drawings
        /// start from stowed).
        #[arg(long, value_enum, default_value = "stowed")]
        at: At,
    },
    /// Compare the synthesised mechanism kinds at the scene's stations (`003_...` Table 1).
    ///
    /// Each kind is designed in place of the stations' mechanisms (`003_...` Fig. 17): its
    /// figures in study.json, gap and overlap charts per station, and a ranking.
    Study {
        /// Scene file (TOML). Without it, the embedded default scene.
        scene: Option<PathBuf>,
        /// Output folder (replaced atomically on success).
        #[arg(long, default_value = "flapwright-study")]
        out: PathBuf,
        /// Kinds to compare, comma-separated (default: dropped-hinge, four-bar,
        /// link-track, hooked-track).
        #[arg(long, value_delimiter = ',')]
        kinds: Vec<String>,
        /// Study only these stations (and their flaps), comma-separated; default all.
        #[arg(long, value_delimiter = ',')]
        station: Vec<String>,
    },
    /// Design many variants of a scene in parallel into one table (`OUT/sweep.csv`).
    ///
    /// Each variant is the scene with keys set to other values, the keys named as the
    /// scene's problems name them (`flap[0].settings.landing_deg`, `[*]` for every element,
    /// `[name]` for the one of that name). A row per variant: its values, its scene's
    /// SHA-256, the verdict and the whole wing's figures, or the error that stopped it. Rows
    /// already in the table are kept (run again to resume).
    Sweep {
        /// Scene file (TOML). Without it, the embedded default scene.
        scene: Option<PathBuf>,
        /// Output folder; the table is `sweep.csv` in it.
        #[arg(long, default_value = "flapwright-sweep")]
        out: PathBuf,
        /// KEY=START:STOP:STEP or KEY=A,B,C; several give their product, the first varied
        /// slowest.
        #[arg(long)]
        vary: Vec<String>,
        /// A CSV table of variants: its header names the keys, each row a variant.
        #[arg(long)]
        variants: Option<PathBuf>,
        /// I/N: design only every N-th variant, from the I-th (a job array's part).
        #[arg(long)]
        shard: Option<String>,
    },
    /// Print the scene's JSON Schema, for editors with a TOML language server.
    ///
    /// Print the scene's JSON Schema (for editors: a TOML language server completes and
    /// checks keys from it).
    Schema,
}

/// A failure with the exit code it maps to.
struct Failure {
    code: u8,
    error: anyhow::Error,
    /// The run's summary, when it ran to the end but failed its verdict (`check`): with
    /// `--json` it goes into the error object, so that stdout holds one line.
    summary: Option<serde_json::Value>,
}

impl<E: Into<anyhow::Error>> From<E> for Failure {
    fn from(error: E) -> Self {
        let error = error.into();
        let input_problem = scene_error(&error).is_some()
            || error
                .downcast_ref::<OutputError>()
                .is_some_and(OutputError::is_input_problem);
        let code = if input_problem { EXIT_BAD_INPUT } else { EXIT_FAILED };
        Self {
            code,
            error,
            summary: None,
        }
    }
}

/// The scene's problems behind `error`: the error itself, or what a stage of the library met
/// (found through the stages that wrapped it).
fn scene_error(error: &anyhow::Error) -> Option<&SceneError> {
    error
        .downcast_ref::<SceneError>()
        .or_else(|| error.downcast_ref::<flapwright::Error>()?.scene_error())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            if cli.json {
                println!("{}", json_error(&failure));
            }
            eprintln!("error: {:#}", failure.error);
            ExitCode::from(failure.code)
        }
    }
}

/// The failure as one line of JSON: `error` (the whole message), `exit_code`, `problems`
/// (each scene problem as `{file, line, col, key, message}`, when the scene was at fault)
/// and, for a run that ended in a failed verdict, its `summary`.
fn json_error(failure: &Failure) -> String {
    let scene_error = scene_error(&failure.error).or_else(|| {
        failure
            .error
            .downcast_ref::<flapwright::study::Unstudiable>()
            .map(|u| &u.0)
    });
    let problems: Vec<serde_json::Value> = match scene_error {
        Some(SceneError::Located(problems)) => problems
            .iter()
            .map(|p| {
                serde_json::json!({
                    "file": p.file,
                    "line": p.location.line,
                    "col": p.location.column,
                    "key": p.problem.path,
                    "message": p.problem.message,
                })
            })
            .collect(),
        Some(SceneError::Invalid(problems)) => problems
            .iter()
            .map(|p| {
                serde_json::json!({
                    "file": null,
                    "line": null,
                    "col": null,
                    "key": p.path,
                    "message": p.message,
                })
            })
            .collect(),
        None => Vec::new(),
    };
    let mut error = serde_json::json!({
        "error": format!("{:#}", failure.error),
        "exit_code": failure.code,
        "problems": problems,
    });
    if let Some(summary) = &failure.summary {
        error["summary"] = summary.clone();
    }
    error.to_string()
}

/// Bad input (exit 2).
/// A command that needs a `[wing]` on a 2D scene: bad input, located at the scene's `wing`
/// key path (where it is missing: the file's start), as every other scene problem is.
fn no_wing(text: &str, file: &str, message: String) -> Failure {
    let located = SceneError::Invalid(vec![flapwright::scene::Problem::new("wing", message)]).locate(text, file);
    bad_input(anyhow::Error::new(located).context(format!("invalid scene {file}")))
}

fn bad_input(error: anyhow::Error) -> Failure {
    Failure {
        code: EXIT_BAD_INPUT,
        error,
        summary: None,
    }
}

fn run(cli: &Cli) -> Result<(), Failure> {
    match &cli.command {
        Some(Command::Init { file, kind }) => {
            let kind = kind.as_deref().unwrap_or(flapwright::scene::template_kinds()[0]);
            return authoring::init(cli, kind, file);
        }
        Some(Command::Kinds) => return authoring::kinds(cli),
        Some(Command::Schema) => return authoring::schema(),
        Some(Command::Sweep {
            scene,
            out,
            vary,
            variants,
            shard,
        }) => {
            return sweep::sweep(
                cli,
                &sweep::SweepArgs {
                    scene: scene.as_deref(),
                    out,
                    vary,
                    variants: variants.as_deref(),
                    shard: shard.as_deref(),
                },
            )
        }
        _ => {}
    }
    if let Some(Command::Study {
        scene,
        out,
        kinds,
        station,
    }) = &cli.command
    {
        return study(cli, scene.as_deref(), out, kinds, station);
    }
    let (scene_path, out, mode, junit) = match &cli.command {
        None => (None, PathBuf::from("flapwright-out"), Mode::Design, None),
        Some(Command::Design { scene, out }) => (scene.clone(), out.clone(), Mode::Design, None),
        Some(Command::Check { scene, out, junit, .. }) => (scene.clone(), out.clone(), Mode::Check, junit.clone()),
        Some(Command::Export { scene, out, .. }) => (scene.clone(), out.clone(), Mode::Export, None),
        Some(
            Command::Study { .. } | Command::Init { .. } | Command::Kinds | Command::Schema | Command::Sweep { .. },
        ) => {
            unreachable!("handled above")
        }
    };
    let (text, files) = read_scene_text(scene_path.as_deref())?;
    let file_label = scene_path
        .as_deref()
        .map_or("(embedded default)".into(), |p| p.display().to_string());
    let mut scene = Scene::from_file_text(&text, &file_label, files.as_ref())
        .map_err(|e| bad_input(anyhow::Error::new(e).context(format!("invalid scene {file_label}"))))?;
    if let Some(Command::Export {
        urdf,
        stl,
        svg,
        gltf,
        at,
        ..
    }) = &cli.command
    {
        let all = !(*urdf || *stl || *svg || *gltf);
        if scene.wing.is_none() {
            let asked: Vec<&str> = [(*urdf, "--urdf"), (*stl, "--stl"), (*gltf, "--gltf")]
                .iter()
                .filter_map(|(on, flag)| on.then_some(*flag))
                .collect();
            if !asked.is_empty() {
                return Err(no_wing(
                    &text,
                    &file_label,
                    format!(
                        "`export {}` needs a scene with a [wing]: a 2D station has no 3D geometry to export (`--svg` draws it)",
                        asked.join(" ")
                    ),
                ));
            }
        }
        if *at != At::Stowed && (all || !*stl || *urdf || *gltf || *svg) {
            return Err(Failure {
                summary: None,
                code: EXIT_BAD_INPUT,
                error: anyhow::anyhow!(
                    "--at {} moves the STL files only: use it with --stl alone (the URDF, the glTF and the drawings start from stowed)",
                    match at {
                        At::Takeoff => "takeoff",
                        _ => "landing",
                    }
                ),
            });
        }
        scene.outputs.stl_setting = StlSetting::from(*at);
        let outputs = &mut scene.outputs;
        // Without a flag: every file the scene has geometry for (a 2D station: drawings).
        let solid = all && scene.wing.is_some();
        (outputs.urdf, outputs.stl, outputs.svg, outputs.gltf) =
            (solid || *urdf, solid || *stl, all || *svg, solid || *gltf);
        // Only the drawings need the check (failing pairs marked) and the sweeps (plots).
        (outputs.interference, outputs.kinematics) = (outputs.svg, outputs.svg);
        outputs.sizing = false;
    }
    let mut staged = StagedDir::create(&out, scene_path.as_deref(), cli.force)?;
    print_notices(cli, &staged.take_notices());
    let mut junit_replaces_foreign = false;
    if let Some(path) = &junit {
        // Never one of the run's inputs, nor inside --out (replaced as a whole).
        let mut reserved: Vec<(PathBuf, String, bool)> = scene_path
            .iter()
            .map(|p| (p.clone(), "the scene file".to_string(), false))
            .collect();
        reserved.extend(
            scene_inputs(&scene, files.as_ref())
                .into_iter()
                .map(|p| (p, "an airfoil file the scene reads".to_string(), false)),
        );
        reserved.push((
            staged.target().to_path_buf(),
            "inside --out, which each run replaces as a whole".to_string(),
            true,
        ));
        junit_replaces_foreign = output::check_writable_file("--junit", path, &reserved, cli.force, |text| {
            text.contains("<testsuites name=\"flapwright check\"")
        })
        .with_context(|| format!("--junit {}", path.display()))?;
    }
    let inputs = Inputs {
        scene: &scene,
        scene_text: &text,
        files: files.as_ref(),
        wing_cache: None,
    };
    if mode == Mode::Check && scene.wing.is_none() {
        return Err(no_wing(
            &text,
            &file_label,
            "`check` needs a scene with a [wing]: there is no 3D geometry to check".into(),
        ));
    }
    // A spinner naming the running stage, only for a person watching a terminal.
    let spinner = (!cli.quiet && !cli.json && std::io::stdout().is_terminal()).then(|| {
        let bar = indicatif::ProgressBar::new_spinner();
        bar.enable_steady_tick(std::time::Duration::from_millis(100));
        bar
    });
    let on_stage = |stage: &str| {
        if let Some(bar) = &spinner {
            bar.set_message(format!("{stage}..."));
        }
    };
    let outcome = pipeline::design_with_progress(&inputs, mode, &staged, &on_stage);
    if let Some(bar) = &spinner {
        bar.finish_and_clear();
    }
    // Input problems found by a stage (after validation) are located in the file too.
    let outcome = outcome.map_err(|error| match error.into_scene_error() {
        Ok(scene_error) => bad_input(
            anyhow::Error::new(scene_error.locate(&text, &file_label)).context(format!("invalid scene {file_label}")),
        ),
        Err(error) => Failure::from(error),
    })?;
    let output::Committed {
        folder: written,
        removed,
        notices,
    } = staged
        .commit()
        .with_context(|| format!("moving results into {}", out.display()))?;
    print_notices(cli, &notices);
    if !removed.is_empty() && !cli.quiet {
        eprintln!(
            "--force: replaced {} file(s) Flapwright had not written: {}",
            removed.len(),
            removed
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    if let (Some(path), Some(report)) = (&junit, &outcome.report.interference) {
        let xml = flapwright::junit::interference_junit(&scene.name, report)?;
        output::write_file_atomically(path, xml.as_bytes()).with_context(|| format!("writing {}", path.display()))?;
        if junit_replaces_foreign && !cli.quiet {
            eprintln!("--force: replaced {}, which Flapwright had not written", path.display());
        }
    }
    let check_failed = mode == Mode::Check && outcome.summary.interference_passes == Some(false);
    if !cli.quiet && !cli.json {
        for warning in &outcome.report.warnings {
            eprintln!("warning: {warning}");
        }
    } else if !cli.quiet && check_failed {
        // With --json, stderr still says which pairs failed.
        for warning in outcome.report.warnings.iter().filter(|w| w.starts_with("interference")) {
            eprintln!("{warning}");
        }
    }
    let verdict_failure = |error: anyhow::Error| -> Result<Failure, Failure> {
        Ok(Failure {
            code: EXIT_FAILED,
            error,
            summary: Some(serde_json::to_value(&outcome.summary)?),
        })
    };
    let strict = matches!(cli.command, Some(Command::Check { strict: true, .. }));
    let failure = if check_failed {
        Some(verdict_failure(anyhow::anyhow!(
            "interference check failed: see {}",
            written.join("report.json").display()
        ))?)
    } else {
        match (strict, &outcome.report.interference) {
            (true, Some(report)) => match report.unchecked_pairs.first() {
                Some(first) => Some(verdict_failure(anyhow::anyhow!(
                    "--strict: {} pair(s) were not checked, for example {} vs {} at station {} ({}); see unchecked_pairs in {}",
                    report.unchecked_pairs.len(),
                    first.part_a,
                    first.part_b,
                    first.station,
                    first.reason,
                    written.join("report.json").display()
                ))?),
                None => None,
            },
            _ => None,
        }
    };
    if cli.json {
        // One line: the summary, or the error object that carries it.
        if failure.is_none() {
            println!("{}", serde_json::to_string(&outcome.summary)?);
        }
    } else if !cli.quiet {
        let mut verdict = match outcome.summary.interference_passes {
            Some(true) => ", clearances met".to_string(),
            Some(false) => ", INTERFERENCE".to_string(),
            None => String::new(),
        };
        if let Some(unchecked @ 1..) = outcome.summary.unchecked_pairs {
            verdict += &format!(" ({unchecked} pair(s) not checked: see unchecked_pairs in the report)");
        }
        println!(
            "{} \"{}\": {} part(s), {} station(s), {} warning(s){verdict} -> {}",
            match (&cli.command, mode) {
                (Some(Command::Export { .. }), _) => "exported",
                (_, Mode::Check) => "checked",
                _ => "designed",
            },
            scene.name,
            outcome.summary.parts,
            outcome.summary.stations,
            outcome.summary.warnings,
            written.display()
        );
    }
    if let Some(failure) = failure {
        return Err(failure);
    }
    Ok(())
}

/// `flapwright study`: validates the scene as given and the flags, then designs each kind
/// in place of its stations' mechanisms and prints the comparison.
fn study(
    cli: &Cli,
    scene_path: Option<&Path>,
    out: &Path,
    kinds: &[String],
    stations: &[String],
) -> Result<(), Failure> {
    use flapwright::kinds::MechanismScene;
    let (text, files) = read_scene_text(scene_path)?;
    let label = scene_path.map_or("(embedded default)".into(), |p| p.display().to_string());
    let scene = Scene::from_file_text(&text, &label, files.as_ref())
        .map_err(|e| bad_input(anyhow::Error::new(e).context(format!("invalid scene {label}"))))?;
    let kinds: Vec<String> = if kinds.is_empty() {
        flapwright::study::DEFAULT_KINDS.iter().map(|k| k.to_string()).collect()
    } else {
        kinds.to_vec()
    };
    let studied = MechanismScene::SYNTHESISED_KINDS.join(", ");
    for (i, kind) in kinds.iter().enumerate() {
        if !MechanismScene::KINDS.contains(&kind.as_str()) {
            return Err(bad_input(anyhow::anyhow!(
                "--kinds {kind}: unknown mechanism kind; the study compares {studied}"
            )));
        }
        if !MechanismScene::SYNTHESISED_KINDS.contains(&kind.as_str()) {
            return Err(bad_input(anyhow::anyhow!(
                "--kinds {kind}: cannot be studied: it is given by its dimensions, and the study puts kinds synthesised from the flap settings in place of the stations' mechanisms: {studied}"
            )));
        }
        if kinds[..i].contains(kind) {
            return Err(bad_input(anyhow::anyhow!("--kinds {kind}: named twice")));
        }
    }
    for (i, name) in stations.iter().enumerate() {
        if !scene.station.iter().any(|s| &s.name == name) {
            let names: Vec<&str> = scene.station.iter().map(|s| s.name.as_str()).collect();
            return Err(bad_input(anyhow::anyhow!(
                "--station {name}: no such station in \"{}\" (its stations: {})",
                scene.name,
                names.join(", ")
            )));
        }
        if stations[..i].contains(name) {
            return Err(bad_input(anyhow::anyhow!("--station {name}: named twice")));
        }
    }
    flapwright::study::requirements(&scene, &text, &label, stations).map_err(|e| bad_input(anyhow::Error::new(e)))?;
    let mut staged = StagedDir::create(out, scene_path, cli.force)?;
    print_notices(cli, &staged.take_notices());
    let study =
        flapwright::study::run(&scene, &text, files.as_ref(), &label, &kinds, stations, &staged).map_err(|error| {
            let code = match &error {
                flapwright::Error::NoKindDesigned(none) if none.input_problem => EXIT_BAD_INPUT,
                _ => EXIT_FAILED,
            };
            Failure {
                code,
                error: error.into(),
                summary: None,
            }
        })?;
    let committed = staged
        .commit()
        .with_context(|| format!("moving results into {}", out.display()))?;
    print_notices(cli, &committed.notices);
    let written = committed.folder;
    if cli.json {
        println!("{}", serde_json::to_string(&study)?);
    } else if !cli.quiet {
        println!("{}", flapwright::study::table(&study));
        println!(
            "studied \"{}\": {} kind(s) -> {}",
            study.scene,
            study.kinds.len(),
            written.display()
        );
    }
    Ok(())
}

/// Warnings about the output folder and what earlier runs left beside it (unless
/// `--quiet`).
fn print_notices(cli: &Cli, notices: &[String]) {
    if !cli.quiet {
        for notice in notices {
            eprintln!("warning: {notice}");
        }
    }
}

/// The scene's text and the files it may name (its folder's; none for the embedded scene).
fn read_scene_text(path: Option<&Path>) -> Result<(String, Box<dyn FileSource>), Failure> {
    match path {
        None => Ok((DEFAULT_SCENE_TOML.to_string(), Box::new(NoFiles))),
        Some(path) => {
            // No further than the size limit: an endless file (`/dev/zero`) is refused at once.
            let bytes = std::fs::File::open(path).and_then(Scene::read_bytes).map_err(|e| {
                bad_input(anyhow::Error::new(e).context(format!("reading scene file {}", path.display())))
            })?;
            let text = Scene::decode(bytes, &path.display().to_string())
                .map_err(|e| bad_input(anyhow::Error::new(e).context(format!("invalid scene {}", path.display()))))?;
            let files: Box<dyn FileSource> = match path.parent() {
                Some(folder) => Box::new(Folder::new(folder)),
                None => Box::new(NoFiles),
            };
            Ok((text, files))
        }
    }
}

/// The files on disk a scene reads besides itself: its airfoil files found next to it.
fn scene_inputs(scene: &flapwright::scene::Scene, files: &dyn FileSource) -> Vec<PathBuf> {
    use flapwright::scene::AirfoilRef;
    let names = scene
        .wing
        .iter()
        .flat_map(|w| w.sections.iter().map(|s| s.airfoil.as_str()))
        .chain(scene.flap.iter().filter_map(|f| f.airfoil.as_deref()));
    names
        .filter_map(|text| match AirfoilRef::parse(text) {
            Ok(AirfoilRef::File(name)) => files.path_of(&name),
            _ => None,
        })
        .collect()
}
