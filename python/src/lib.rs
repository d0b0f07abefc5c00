//! `superlube._native`: the Python module's bridge to the `superlube` commands.
//!
//! Four functions, no physics: `scene` resolves and validates a scene exactly as every
//! command does (preset ← scene file ← keyword fields; errors name the field), `flags` lists
//! a command's options (the Python layer maps snake-case keywords onto them), `renamed` its
//! old option names (clap's hidden aliases, which the Python layer accepts with a warning as
//! the command line does with a note), and `run` runs
//! one command line in process — the same flag checks, the same study workflow, the same files
//! and sidecars as the `superlube` binary — on a worker thread with the GIL released, forwarding
//! its progress to a Python callback on the calling thread and stopping it on Ctrl-C or when the
//! callback raises. The Python package (`superlube/`) turns keywords into flags and reads the
//! files back into pandas/numpy.

use clap::{CommandFactory, Parser};
use pyo3::exceptions::{PyKeyboardInterrupt, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc, Mutex};
use std::time::Duration;
use superlube::cli::Cli;
use superlube::runs::meta::{scene_file, set_command_line};
use superlube::runs::progress::Progress;
use superlube::runs::progress::{with_reporter, Cancelled};
use surrogate::SceneFile;

/// Held while a command runs (see [`run`]).
static RUNNING: Mutex<()> = Mutex::new(());

/// How often the calling thread wakes to deliver progress and check for Ctrl-C.
const POLL: Duration = Duration::from_millis(100);

/// Progress of the running command as the calling thread last saw it.
#[derive(Default)]
struct Snapshot {
    stage: String,
    unit: String,
    total: u64,
    done: u64,
    status: String,
    notes: Vec<String>,
    changed: bool,
}

/// What the worker and the calling thread share.
#[derive(Default)]
struct Shared {
    /// Set by the calling thread (Ctrl-C, a raising callback); the worker's next progress call
    /// unwinds with [`Cancelled`].
    cancel: AtomicBool,
    /// Whether a stage began, i.e. the command's checks passed and work started.
    started: AtomicBool,
    snap: Mutex<Snapshot>,
}

impl Shared {
    fn lock(&self) -> std::sync::MutexGuard<'_, Snapshot> {
        self.snap.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn check(&self) {
        if self.cancel.load(Ordering::Relaxed) {
            std::panic::panic_any(Cancelled);
        }
    }

    /// The progress since the last call as a dict, if anything changed.
    fn take<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let mut s = self.lock();
        if !s.changed {
            return Ok(None);
        }
        s.changed = false;
        let d = PyDict::new(py);
        d.set_item("stage", &s.stage)?;
        d.set_item("done", s.done)?;
        d.set_item("total", s.total)?;
        d.set_item("unit", &s.unit)?;
        d.set_item("status", &s.status)?;
        d.set_item("notes", std::mem::take(&mut s.notes))?;
        Ok(Some(d))
    }
}

/// The [`Progress`] the command's reporter forwards to: records, never prints. Stage, advance
/// and update unwind with [`Cancelled`] once cancelled (notes and finish never do: they may run
/// during unwinding).
struct Forward(Arc<Shared>);

impl Progress for Forward {
    fn stage(&self, name: &str, total: u64, unit: &str) {
        self.0.check();
        self.0.started.store(true, Ordering::Relaxed);
        let mut s = self.0.lock();
        s.stage = name.into();
        s.unit = unit.into();
        s.total = total;
        s.done = 0;
        s.status.clear();
        s.changed = true;
    }
    fn advance(&self, n: u64) {
        self.0.check();
        let mut s = self.0.lock();
        s.done += n;
        s.changed = true;
    }
    fn update(&self, done: u64, status: &str) {
        self.0.check();
        let mut s = self.0.lock();
        s.done = done;
        s.status = status.into();
        s.changed = true;
    }
    fn note(&self, line: &str) {
        let mut s = self.0.lock();
        s.notes.push(line.into());
        s.changed = true;
    }
    fn finish(&self) {
        self.0.lock().changed = true;
    }
}

fn panic_message(p: &(dyn std::any::Any + Send)) -> String {
    p.downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| p.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into())
}

/// Runs one `superlube` command line (`argv[0]` is the program name) in process and returns
/// when it finished. `callback(progress: dict)` is called on the calling thread at most every
/// 0.1 s with keys stage, done, total, unit, status, notes (new log lines). `threads`: size of
/// the rayon pool (default: the global pool, every core). Errors: `ValueError` for a bad flag or
/// input (found before any work), `RuntimeError` for a failure during the run,
/// `KeyboardInterrupt` on Ctrl-C, or the callback's own exception; an interrupted command stops
/// at its next progress step.
#[pyfunction]
#[pyo3(signature = (argv, callback=None, threads=None))]
fn run(
    py: Python<'_>,
    argv: Vec<String>,
    callback: Option<PyObject>,
    threads: Option<usize>,
) -> PyResult<()> {
    let cli = Cli::try_parse_from(&argv)
        .map_err(|e| PyValueError::new_err(e.render().to_string().trim_end().to_string()))?;
    let pool = match threads {
        Some(0) => return Err(PyValueError::new_err("`threads`: must be at least 1")),
        Some(n) => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| PyRuntimeError::new_err(e.to_string()))?,
        ),
        None => None,
    };
    // One command at a time per process (the sidecars' recorded command line is global).
    let _running = loop {
        match RUNNING.try_lock() {
            Ok(g) => break g,
            Err(std::sync::TryLockError::Poisoned(e)) => break e.into_inner(),
            Err(std::sync::TryLockError::WouldBlock) => {
                py.allow_threads(|| std::thread::sleep(POLL));
                py.check_signals()?;
            }
        }
    };
    set_command_line(Some(argv.clone()));
    let shared = Arc::new(Shared::default());
    let (tx, rx) = mpsc::channel::<()>();
    let sh = shared.clone();
    let worker = std::thread::Builder::new()
        .name("superlube".into())
        .spawn(move || {
            let job = move || {
                let fwd: Arc<dyn Progress + Send> = Arc::new(Forward(sh));
                with_reporter(fwd, || superlube::cli::run(cli))
            };
            let r = catch_unwind(AssertUnwindSafe(|| match pool {
                Some(p) => p.install(job),
                None => job(),
            }));
            let _ = tx.send(());
            r
        })
        .map_err(|e| PyRuntimeError::new_err(e.to_string()))?;
    let rx = Mutex::new(rx); // `allow_threads` needs Sync captures
    let mut err: Option<PyErr> = None;
    let stop = |e: PyErr, err: &mut Option<PyErr>| {
        shared.cancel.store(true, Ordering::Relaxed);
        err.get_or_insert(e);
    };
    loop {
        let finished = !matches!(
            py.allow_threads(|| {
                rx.lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .recv_timeout(POLL)
            }),
            Err(mpsc::RecvTimeoutError::Timeout)
        );
        if err.is_none() {
            if let Some(cb) = &callback {
                if let Ok(Some(ev)) = shared.take(py) {
                    if let Err(e) = cb.call1(py, (ev,)) {
                        stop(e, &mut err);
                    }
                }
            }
        }
        if err.is_none() {
            if let Err(e) = py.check_signals() {
                stop(e, &mut err);
            }
        }
        if finished {
            break;
        }
    }
    let joined = py.allow_threads(|| worker.join());
    set_command_line(None);
    if let Some(e) = err {
        return Err(e);
    }
    match joined {
        Ok(Ok(Ok(()))) => Ok(()),
        Ok(Ok(Err(e))) => {
            let msg = format!("{e:#}");
            Err(if shared.started.load(Ordering::Relaxed) {
                PyRuntimeError::new_err(msg)
            } else {
                PyValueError::new_err(msg)
            })
        }
        Ok(Err(p)) | Err(p) if p.is::<Cancelled>() => Err(PyKeyboardInterrupt::new_err("")),
        Ok(Err(p)) | Err(p) => Err(PyRuntimeError::new_err(format!(
            "superlube panicked: {}",
            panic_message(p.as_ref())
        ))),
    }
}

/// The clap definition of subcommand `command` (`ValueError` naming it when there is none).
fn subcommand(command: &str) -> PyResult<clap::Command> {
    Cli::command()
        .find_subcommand(command)
        .cloned()
        .ok_or_else(|| PyValueError::new_err(format!("no command `{command}`")))
}

/// The long options of command `command` as (name, takes a value) pairs, e.g.
/// `("load-mn", true)`, `("force", false)`.
#[pyfunction]
fn flags(command: &str) -> PyResult<Vec<(String, bool)>> {
    let sub = subcommand(command)?;
    Ok(sub
        .get_arguments()
        .filter_map(|a| {
            a.get_long()
                .map(|l| (l.to_string(), a.get_action().takes_values()))
        })
        .collect())
}

/// The long options of command `command` that may be given more than once (`design --vary`,
/// `--scene`): a list of values for one of them is one flag per value.
#[pyfunction]
fn repeated(command: &str) -> PyResult<Vec<String>> {
    let sub = subcommand(command)?;
    Ok(sub
        .get_arguments()
        .filter(|a| matches!(a.get_action(), clap::ArgAction::Append))
        .filter_map(|a| a.get_long().map(str::to_string))
        .collect())
}

/// The renamed options of command `command` as (old name, current name) pairs, e.g.
/// `("model", "solver")` for `screen`: the hidden clap aliases that `superlube` still accepts
/// for a release with a note (`cli::renamed`).
#[pyfunction]
fn renamed(command: &str) -> PyResult<Vec<(String, String)>> {
    let sub = subcommand(command)?;
    Ok(sub
        .get_arguments()
        .filter_map(|a| Some((a.get_long()?, a.get_all_aliases()?)))
        .flat_map(|(new, olds)| {
            olds.into_iter()
                .map(move |o| (o.to_string(), new.to_string()))
        })
        .collect())
}

/// THE scene resolution of every command, on a scene file `path` (or none) with the fields of
/// `overlay` (TOML text in the scene file's format) on top: returns the merged scene file as
/// TOML, the fully resolved scene file as JSON (every field, user units) and the warnings
/// (slider over the substrate edge). `ValueError` naming the field for a bad one.
#[pyfunction]
#[pyo3(signature = (path, overlay))]
fn scene(path: Option<&str>, overlay: &str) -> PyResult<(String, String, Vec<String>)> {
    let bad = |e: &dyn std::fmt::Display| PyValueError::new_err(e.to_string());
    let base = match path {
        Some(p) => SceneFile::read(std::path::Path::new(p)).map_err(|e| bad(&e))?,
        None => SceneFile::default(),
    };
    let over = SceneFile::from_toml(overlay, "Scene keywords").map_err(|e| bad(&e))?;
    let merged = base.merge(&over);
    let scene = merged.into_scene().map_err(|e| bad(&e))?;
    scene.validate().map_err(|e| bad(&e))?;
    let text = toml::to_string(&merged).map_err(|e| bad(&e))?;
    let resolved = serde_json::to_string(&scene_file(&scene)).map_err(|e| bad(&e))?;
    Ok((text, resolved, scene.edge_warning().into_iter().collect()))
}

/// Silences the default panic message of a [`Cancelled`] unwind (an interrupt, not a bug).
fn quiet_cancel_panics() {
    let prev = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if !info.payload().is::<Cancelled>() {
            prev(info);
        }
    }));
}

/// The native half of the `superlube` Python package.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    quiet_cancel_panics();
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(flags, m)?)?;
    m.add_function(wrap_pyfunction!(repeated, m)?)?;
    m.add_function(wrap_pyfunction!(renamed, m)?)?;
    m.add_function(wrap_pyfunction!(scene, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
