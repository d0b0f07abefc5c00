//! The batch's progress: one stage over its runs, each run's own progress folded in.

use crate::runs::progress::Progress;
use std::sync::Mutex;

/// Reports the batch as one stage: the sum over runs of the fraction done (in per-mille of a
/// run), with the number of finished and running runs as status.
pub(super) struct BatchProgress<'a> {
    pub(super) parent: &'a dyn Progress,
    /// Fraction done per run to do, runs finished, runs running.
    pub(super) state: Mutex<(Vec<f64>, usize, usize)>,
}

impl BatchProgress<'_> {
    fn set(&self, k: usize, f: f64) {
        let mut s = self.state.lock().unwrap_or_else(|e| e.into_inner());
        s.0[k] = f.clamp(0.0, 1.0);
        let done: f64 = s.0.iter().sum();
        let status = format!("{}/{} runs done, {} running", s.1, s.0.len(), s.2);
        drop(s);
        self.parent.update((done * 1000.0).round() as u64, &status);
    }

    pub(super) fn started(&self, k: usize) {
        self.state.lock().unwrap_or_else(|e| e.into_inner()).2 += 1;
        self.set(k, 0.0);
    }

    pub(super) fn finished(&self, k: usize) {
        {
            let mut s = self.state.lock().unwrap_or_else(|e| e.into_inner());
            s.1 += 1;
            s.2 = s.2.saturating_sub(1);
        }
        self.set(k, 1.0);
    }
}

/// One run's view of the batch progress.
pub(super) struct RunProgress<'a> {
    pub(super) batch: &'a BatchProgress<'a>,
    pub(super) k: usize,
    pub(super) total: Mutex<u64>,
    /// `Some(name)`: forward notes prefixed with the run's name.
    pub(super) notes: Option<&'a str>,
}

impl Progress for RunProgress<'_> {
    fn stage(&self, _: &str, total: u64, _: &str) {
        *self.total.lock().unwrap_or_else(|e| e.into_inner()) = total.max(1);
    }
    fn advance(&self, _: u64) {}
    fn update(&self, done: u64, _: &str) {
        let t = *self.total.lock().unwrap_or_else(|e| e.into_inner());
        self.batch.set(self.k, done as f64 / t as f64);
    }
    fn note(&self, line: &str) {
        if let Some(name) = self.notes {
            self.batch.parent.note(&format!("{name}: {line}"));
        }
    }
    fn finish(&self) {}
}
