//! Progress reporting shared by every workflow: a workflow announces stages and advances through
//! a [`Progress`] callback object; the command line shows it with [`Reporter`] (a live bar on a
//! terminal, plain lines every few percent when stderr is a log file or a batch job's output).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::cell::RefCell;
use std::io::IsTerminal;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// What a workflow tells its caller while it runs. Implementations must be cheap and
/// thread-safe: [`Progress::advance`] is called from the parallel workers.
pub trait Progress: Sync {
    /// A new stage `name` of `total` units of work (`unit` names one unit, e.g. `θ`, `solves`,
    /// `steps`). Ends the previous stage.
    fn stage(&self, name: &str, total: u64, unit: &str);
    /// `n` more units of the current stage are done.
    fn advance(&self, n: u64);
    /// Absolute position `done` in the current stage and a short status (e.g. the DEM phase and
    /// simulated time: `relax, t = 12.00/320.00 µs`).
    fn update(&self, done: u64, status: &str);
    /// A log line (warnings, the model chosen, the time step…), shown above any bar.
    fn note(&self, line: &str);
    /// The current stage is finished.
    fn finish(&self);
}

/// Reports nothing (library use, tests).
pub struct Silent;

impl Progress for Silent {
    fn stage(&self, _: &str, _: u64, _: &str) {}
    fn advance(&self, _: u64) {}
    fn update(&self, _: u64, _: &str) {}
    fn note(&self, _: &str) {}
    fn finish(&self) {}
}

/// Percent step between two plain progress lines.
pub const LINE_EVERY_PERCENT: u64 = 5;

/// The command line's reporter on stderr: an `indicatif` bar with ETA when stderr is a
/// terminal; otherwise plain lines `stage: 35% (352/1000 θ) [status] elapsed 12.3 s, ETA 22.8 s`
/// every [`LINE_EVERY_PERCENT`] % (and at 100 %), so log files and batch jobs see progress too.
pub struct Reporter {
    bar: bool,
    state: Mutex<State>,
    /// Set by [`with_reporter`]: every call goes there instead of stderr.
    forward: Option<Arc<dyn Progress + Send>>,
}

/// The payload of a panic by which a [`Progress`] stops the workflow it watches (a caller's
/// interrupt: the Python module's Ctrl-C or a raising callback). Code that catches panics (the
/// DEM batch's per-run `catch_unwind`) must resume this one, not record it as a failure.
#[derive(Debug, Clone, Copy)]
pub struct Cancelled;

/// The filter every note passes through before it is printed or forwarded (set once by the
/// command line: it names the workflows' inputs by their flags).
static NOTE_FILTER: std::sync::OnceLock<fn(&str) -> String> = std::sync::OnceLock::new();

/// Sets the note filter (the first call wins; later calls are ignored).
pub fn set_note_filter(f: fn(&str) -> String) {
    let _ = NOTE_FILTER.set(f);
}

/// `line` through the note filter.
fn filtered(line: &str) -> std::borrow::Cow<'_, str> {
    match NOTE_FILTER.get() {
        Some(f) => std::borrow::Cow::Owned(f(line)),
        None => std::borrow::Cow::Borrowed(line),
    }
}

thread_local! {
    static FORWARD: RefCell<Option<Arc<dyn Progress + Send>>> = const { RefCell::new(None) };
}

/// Runs `f` with every [`Reporter::stderr`] made on this thread forwarding to `progress`
/// (library callers of the commands, e.g. the Python module, see the progress of
/// `cli::run` without a terminal). Restores the previous reporter afterwards, also on panic.
pub fn with_reporter<R>(progress: Arc<dyn Progress + Send>, f: impl FnOnce() -> R) -> R {
    struct Restore(Option<Arc<dyn Progress + Send>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            let prev = self.0.take();
            FORWARD.with(|c| *c.borrow_mut() = prev);
        }
    }
    let _restore = Restore(FORWARD.with(|c| c.borrow_mut().replace(progress)));
    f()
}

struct State {
    name: String,
    unit: String,
    total: u64,
    done: u64,
    status: String,
    started: Instant,
    next_pct: u64,
    pb: Option<ProgressBar>,
}

impl Reporter {
    /// A bar if stderr is a terminal, plain lines otherwise.
    /// Inside [`with_reporter`]: forwards there instead.
    pub fn stderr() -> Reporter {
        let mut r = Reporter::new(std::io::stderr().is_terminal());
        r.forward = FORWARD.with(|c| c.borrow().clone());
        r
    }

    /// `bar = true`: live bar; `false`: plain lines.
    pub fn new(bar: bool) -> Reporter {
        Reporter {
            bar,
            state: Mutex::new(State {
                name: String::new(),
                unit: String::new(),
                total: 0,
                done: 0,
                status: String::new(),
                started: Instant::now(),
                next_pct: LINE_EVERY_PERCENT,
                pb: None,
            }),
            forward: None,
        }
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// `h:mm:ss` or `12.3 s`.
fn fmt_duration(d: Duration) -> String {
    let s = d.as_secs_f64();
    if s < 60.0 {
        format!("{s:.1} s")
    } else {
        let t = s.round() as u64;
        format!("{}:{:02}:{:02}", t / 3600, (t / 60) % 60, t % 60)
    }
}

impl State {
    fn line(&self) -> String {
        let elapsed = self.started.elapsed();
        let pct = (100 * self.done).checked_div(self.total).unwrap_or(100);
        let eta = if self.done > 0 && self.done < self.total {
            let rest = elapsed.as_secs_f64() * (self.total - self.done) as f64 / self.done as f64;
            format!(", ETA {}", fmt_duration(Duration::from_secs_f64(rest)))
        } else {
            String::new()
        };
        let status = if self.status.is_empty() {
            String::new()
        } else {
            format!(" {}", self.status)
        };
        format!(
            "{}: {pct}% ({}/{} {}){status} elapsed {}{eta}",
            self.name,
            self.done,
            self.total,
            self.unit,
            fmt_duration(elapsed)
        )
    }

    /// Prints a plain line when `done` crossed the next percent mark.
    fn maybe_line(&mut self) {
        if self.pb.is_some() || self.total == 0 {
            return;
        }
        let pct = 100 * self.done / self.total;
        if pct >= self.next_pct {
            eprintln!("{}", self.line());
            self.next_pct = (pct / LINE_EVERY_PERCENT + 1) * LINE_EVERY_PERCENT;
        }
    }
}

impl Progress for Reporter {
    fn stage(&self, name: &str, total: u64, unit: &str) {
        if let Some(f) = &self.forward {
            return f.stage(name, total, unit);
        }
        let mut s = self.lock();
        if let Some(pb) = s.pb.take() {
            pb.finish_and_clear();
        }
        s.name = name.to_string();
        s.unit = unit.to_string();
        s.total = total;
        s.done = 0;
        s.status.clear();
        s.started = Instant::now();
        s.next_pct = LINE_EVERY_PERCENT;
        if self.bar {
            let pb = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::stderr());
            pb.set_style(
                ProgressStyle::with_template(
                    "{prefix} {bar:30} {percent:>3}% {pos}/{len} {msg} [{elapsed_precise} < {eta_precise}]",
                )
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
            );
            pb.set_prefix(name.to_string());
            pb.set_message(unit.to_string());
            s.pb = Some(pb);
        }
    }

    fn advance(&self, n: u64) {
        if let Some(f) = &self.forward {
            return f.advance(n);
        }
        let mut s = self.lock();
        s.done += n;
        if let Some(pb) = &s.pb {
            pb.inc(n);
        }
        s.maybe_line();
    }

    fn update(&self, done: u64, status: &str) {
        if let Some(f) = &self.forward {
            return f.update(done, status);
        }
        let mut s = self.lock();
        s.done = done;
        s.status = status.to_string();
        if let Some(pb) = &s.pb {
            pb.set_position(done);
            pb.set_message(status.to_string());
        }
        s.maybe_line();
    }

    fn note(&self, line: &str) {
        let line = &*filtered(line);
        if let Some(f) = &self.forward {
            return f.note(line);
        }
        let s = self.lock();
        match &s.pb {
            Some(pb) => pb.suspend(|| eprintln!("{line}")),
            None => eprintln!("{line}"),
        }
    }

    fn finish(&self) {
        if let Some(f) = &self.forward {
            return f.finish();
        }
        let mut s = self.lock();
        if let Some(pb) = s.pb.take() {
            pb.finish_and_clear();
        } else if s.total > 0 && s.next_pct <= 100 && s.done > 0 {
            // A stage that ended early (an error) or whose last update was below 100 %.
            let line = s.line();
            eprintln!("{line}");
        }
        s.total = 0;
    }
}
