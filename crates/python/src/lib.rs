//! Flapwright's Python module (`flapwright._native`, wrapped by the `flapwright` package in
//! `python/flapwright`): a scene designed, checked, studied or swept in memory from its
//! TOML text, the results handed over as JSON text or CSV text, which the package turns
//! into Python objects and pandas tables. Written with PyO3 (the binding crate made for the
//! job) and built by maturin (`pip install .` at the repository's root).
//!
//! The computation runs with the interpreter's lock released, so other Python threads go
//! on (a Dask worker's heartbeat, say). Errors are Python exceptions: `SceneError` carries
//! the scene's problems as `(file, line, col, key, message)` tuples, as the command line
//! prints them; `DesignError` anything else, with the whole chain of causes.

use std::path::Path;

use flapwright::pipeline::{self, Inputs, Mode};
use flapwright::scene::{FileSource, Folder, NoFiles, Scene, SceneError as Problems};
use flapwright::sink::MemorySink;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

pyo3::create_exception!(_native, DesignError, PyException, "A design that could not be made.");
pyo3::create_exception!(
    _native,
    SceneError,
    DesignError,
    "A scene with problems: `problems` lists (file, line, col, key, message)."
);

/// The scene's files: the folder beside a scene read from a file, none for text.
fn files_of(folder: Option<&str>) -> Box<dyn FileSource> {
    match folder {
        Some(folder) => Box::new(Folder::new(Path::new(folder))),
        None => Box::new(NoFiles),
    }
}

/// A problem as Python sees it: (file, line, col, key, message), the place `None` where the
/// problem has none in a file.
type LocatedTuple = (Option<String>, Option<usize>, Option<usize>, String, String);

/// A `SceneError` exception whose `problems` attribute lists the located problems.
fn scene_exception(py: Python<'_>, error: &Problems) -> PyErr {
    let problems: Vec<LocatedTuple> = match error {
        Problems::Located(problems) => problems
            .iter()
            .map(|p| {
                (
                    Some(p.file.clone()),
                    Some(p.location.line),
                    Some(p.location.column),
                    p.problem.path.clone(),
                    p.problem.message.clone(),
                )
            })
            .collect(),
        Problems::Invalid(problems) => problems
            .iter()
            .map(|p| (None, None, None, p.path.clone(), p.message.clone()))
            .collect(),
    };
    let exception = SceneError::new_err(error.to_string());
    let value = exception.value(py);
    let set = PyTuple::new(py, problems).and_then(|problems| value.setattr("problems", problems));
    match set {
        Ok(()) => exception,
        Err(error) => error,
    }
}

fn design_exception(py: Python<'_>, error: flapwright::Error) -> PyErr {
    match error.into_scene_error() {
        Ok(scene) => scene_exception(py, &scene),
        Err(error) => DesignError::new_err(error.chain_message()),
    }
}

/// Designs `scene` into memory (its files dropped: the caller wants the report).
fn design_in_memory(
    scene: &Scene,
    text: &str,
    files: &dyn FileSource,
    mode: Mode,
) -> flapwright::Result<pipeline::Outcome> {
    let inputs = Inputs {
        scene,
        scene_text: text,
        files,
        wing_cache: None,
    };
    pipeline::design(&inputs, mode, &MemorySink::new())
}

/// The scene text of `scene_json` (a dict as JSON) as TOML.
#[pyfunction]
fn toml_of_json(scene_json: &str) -> PyResult<String> {
    let value: toml::Value = serde_json::from_str(scene_json)
        .map_err(|e| DesignError::new_err(format!("the scene dict is not a TOML table: {e}")))?;
    toml::to_string(&value).map_err(|e| DesignError::new_err(format!("the scene dict is not a TOML table: {e}")))
}

/// Designs (`mode` "design", "check" or "export") the scene `text` read from `file`, its
/// files in `folder`: the report as JSON.
#[pyfunction]
#[pyo3(signature = (text, file, folder=None, mode="design"))]
fn design_json(py: Python<'_>, text: &str, file: &str, folder: Option<&str>, mode: &str) -> PyResult<String> {
    let mode = match mode {
        "design" => Mode::Design,
        "check" => Mode::Check,
        "export" => Mode::Export,
        other => {
            return Err(DesignError::new_err(format!(
                "mode {other:?}: one of \"design\", \"check\", \"export\""
            )))
        }
    };
    let files = files_of(folder);
    let scene = Scene::from_file_text(text, file, files.as_ref()).map_err(|e| scene_exception(py, &e))?;
    let result = py.detach(|| {
        design_in_memory(&scene, text, files.as_ref(), mode)
            .and_then(|outcome| serde_json::to_string(&outcome.report).map_err(flapwright::Error::SerialisingReport))
    });
    result.map_err(|e| design_exception(py, e))
}

/// Seconds each of `repeats` designs of the scene takes in Rust alone (no report JSON, no
/// Python objects): the baseline of the Python call's overhead (`python/bench/overhead.py`).
#[pyfunction]
fn design_seconds(py: Python<'_>, text: &str, file: &str, folder: Option<&str>, repeats: usize) -> PyResult<Vec<f64>> {
    let files = files_of(folder);
    let scene = Scene::from_file_text(text, file, files.as_ref()).map_err(|e| scene_exception(py, &e))?;
    let result = py.detach(|| {
        (0..repeats)
            .map(|_| {
                let start = std::time::Instant::now();
                design_in_memory(&scene, text, files.as_ref(), Mode::Design).map(|_| start.elapsed().as_secs_f64())
            })
            .collect::<Result<Vec<f64>, _>>()
    });
    result.map_err(|e| design_exception(py, e))
}

/// The trade study of `kinds` (all synthesised kinds when empty) at `stations` (all when
/// empty): `study.json` as text.
#[pyfunction]
#[pyo3(signature = (text, file, folder=None, kinds=Vec::new(), stations=Vec::new()))]
fn study_json(
    py: Python<'_>,
    text: &str,
    file: &str,
    folder: Option<&str>,
    kinds: Vec<String>,
    stations: Vec<String>,
) -> PyResult<String> {
    let files = files_of(folder);
    let scene = Scene::from_file_text(text, file, files.as_ref()).map_err(|e| scene_exception(py, &e))?;
    let kinds = if kinds.is_empty() {
        flapwright::study::DEFAULT_KINDS.iter().map(|k| k.to_string()).collect()
    } else {
        kinds
    };
    let result = py.detach(|| {
        let sink = MemorySink::new();
        flapwright::study::run(&scene, text, files.as_ref(), file, &kinds, &stations, &sink)
            .and_then(|study| serde_json::to_string(&study).map_err(flapwright::Error::SerialisingStudy))
    });
    result.map_err(|e| design_exception(py, e))
}

/// Every variant of the scene (`vary`: `KEY=START:STOP:STEP` or `KEY=A,B,C`, their product;
/// or `variants_csv`, a table whose header names the keys), those of `shard` (`I/N`),
/// designed in parallel: the table as CSV text, as `flapwright sweep` writes it.
#[pyfunction]
#[pyo3(signature = (text, file, folder=None, vary=Vec::new(), variants_csv=None, shard=None))]
fn sweep_csv(
    py: Python<'_>,
    text: &str,
    file: &str,
    folder: Option<&str>,
    vary: Vec<String>,
    variants_csv: Option<&str>,
    shard: Option<&str>,
) -> PyResult<String> {
    use flapwright::sweep::{csv_bytes, csv_header, Shard, Sweep, Variants};
    let bad = |e: flapwright::sweep::SweepError| DesignError::new_err(e.to_string());
    let files = files_of(folder);
    Scene::from_file_text(text, file, files.as_ref()).map_err(|e| scene_exception(py, &e))?;
    let variants = Variants::from_arguments(&vary, variants_csv).map_err(bad)?;
    let shard = match shard {
        Some(given) => given.parse::<Shard>().map_err(bad)?,
        None => Shard::ALL,
    };
    let sweep = Sweep::new(text, file, files.as_ref(), variants).map_err(bad)?;
    let header = csv_header(&sweep.variants().keys);
    let indices: Vec<usize> = (0..sweep.variants().rows.len()).filter(|&i| shard.takes(i)).collect();
    let rows = py.detach(|| sweep.design(&indices));
    let cells: Vec<Vec<String>> = rows.iter().map(|r| r.csv_record()).collect();
    String::from_utf8(csv_bytes(&header, &cells)).map_err(|e| DesignError::new_err(e.to_string()))
}

/// The lean sweep handed to Python: column names, the columns' bytes, rows, why it stopped.
type LeanColumns<'py> = (
    Vec<&'static str>,
    Bound<'py, pyo3::types::PyBytes>,
    usize,
    Option<String>,
);

/// The thesis track's lean deployment sweep (`thesis_lean_sweep_into`, the published
/// case, `000_...` Table 2) at `samples` nut positions under the thesis's `load` case
/// (`cruise` or `landing`): the column names, the columns as one buffer of little-endian
/// `f64` (column after column, each `samples` long, fewer when the sweep stopped), the
/// samples computed and why it stopped, if it did.
#[pyfunction]
fn thesis_sweep<'py>(py: Python<'py>, samples: usize, load: &str) -> PyResult<LeanColumns<'py>> {
    use flapwright_kinds::{thesis_lean_sweep_into, LeanColumn};
    use flapwright_mechanism::LoadCase;
    let load = match load {
        "cruise" => LoadCase::thesis_cruise(),
        "landing" => LoadCase::thesis_landing(),
        other => {
            return Err(DesignError::new_err(format!(
                "load `{other}`: the thesis's cases are `cruise` and `landing`"
            )))
        }
    };
    // Each thread's columns reuse one buffer (`lean_sweep_into`): fresh pages for them cost
    // a third of the call.
    thread_local! {
        static COLUMNS: std::cell::RefCell<flapwright_kinds::LeanSweep> = std::cell::RefCell::default();
    }
    let (rows, stopped) = py
        .detach(|| {
            COLUMNS.with_borrow_mut(|sweep| {
                thesis_lean_sweep_into(samples, &load, sweep)?;
                Ok::<_, flapwright_mechanism::Error>((
                    sweep.len(),
                    sweep.stopped.as_ref().map(|s| s.reason.to_string()),
                ))
            })
        })
        .map_err(|e| DesignError::new_err(e.to_string()))?;
    // Written straight into the Python object: no buffer between (`detach` ran on this
    // thread, so its columns are this thread's).
    let bytes = COLUMNS.with_borrow(|sweep| {
        let values = sweep.values();
        pyo3::types::PyBytes::new_with(py, 8 * values.len(), |buffer| {
            for (chunk, value) in buffer.chunks_exact_mut(8).zip(values) {
                chunk.copy_from_slice(&value.to_le_bytes());
            }
            Ok(())
        })
    })?;
    Ok((LeanColumn::ALL.iter().map(|c| c.name()).collect(), bytes, rows, stopped))
}

/// The native half of the `flapwright` package.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("DesignError", m.py().get_type::<DesignError>())?;
    m.add("SceneError", m.py().get_type::<SceneError>())?;
    m.add_function(wrap_pyfunction!(toml_of_json, m)?)?;
    m.add_function(wrap_pyfunction!(design_json, m)?)?;
    m.add_function(wrap_pyfunction!(design_seconds, m)?)?;
    m.add_function(wrap_pyfunction!(study_json, m)?)?;
    m.add_function(wrap_pyfunction!(sweep_csv, m)?)?;
    m.add_function(wrap_pyfunction!(thesis_sweep, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("FIGURE_COLUMNS", flapwright::sweep::FIGURE_COLUMNS.to_vec())?;
    Ok(())
}
