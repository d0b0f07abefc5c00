//! The design's output directory as a store of finished stages.
//!
//! Every stage result is a file with the study layer's sidecar (`F.meta.json`: the stage's
//! inputs and their `input_hash`, [`crate::runs::meta`]). A stage is *reused* when its file
//! and sidecar exist, the sidecar says complete, and its `input_hash` equals the hash of the
//! inputs the stage would run with now; a stage file whose sidecar names other inputs is never
//! used nor overwritten silently: the run stops with an error naming the file and the inputs
//! that differ. The whole design's inputs are recorded first in `design.json`
//! ([`Store::claim`]), so a re-run with other inputs and the same `--out-dir` is refused before
//! any work.
//!
//! Final outputs (report, ranking, CSVs behind the plots, PNGs) are rewritten only when their
//! bytes change ([`Store::write_if_changed`]), so a second run of a finished design leaves every
//! file as it was.

use crate::runs::meta::{input_differences, sidecar_path, Inputs, Sidecar};
use crate::runs::output::Outputs;
use anyhow::{bail, Context, Result};
use serde::de::DeserializeOwned;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// File-name form of a number (`0.35`, `-15`): the label of a stored stage or DEM run.
pub fn tag(v: f64) -> String {
    format!("{}", crate::study::rows::label(v))
}

/// What the error of a stage made with other inputs suggests.
fn hint() -> String {
    format!(
        "; remove it or use another {}",
        crate::study::input::Input::OutDir
    )
}

/// The output directory of a design.
pub struct Store {
    dir: PathBuf,
    /// What named the directory (the caller's flag or keyword), in messages and in the
    /// sidecar of `design.json`.
    label: String,
}

impl Store {
    /// The store at `dir` (created when a file is first written), named in messages and
    /// sidecars as the output directory input ([`crate::study::input::Input::OutDir`]).
    pub fn new(dir: &Path) -> Store {
        Store {
            dir: dir.to_path_buf(),
            label: crate::study::input::Input::OutDir.keyword().to_string(),
        }
    }

    /// The store named by `label` (the command line's flag) in messages and sidecars.
    pub fn labelled(mut self, label: &str) -> Store {
        self.label = label.to_string();
        self
    }

    /// The directory.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// `dir/rel`.
    pub fn path(&self, rel: &str) -> PathBuf {
        self.dir.join(rel)
    }

    /// Checks that `dir` holds no design of other inputs: reads `design.json` if present and
    /// compares its `input_hash`; writes it when absent. Errors list the inputs that differ.
    /// Returns whether a design of these inputs was already there.
    pub fn claim(&self, inputs: &Inputs) -> Result<bool> {
        let flag = self.label.as_str();
        let path = self.path("design.json");
        if path.exists() {
            let s: Sidecar = std::fs::read_to_string(&path)
                .map_err(anyhow::Error::from)
                .and_then(|t| Ok(serde_json::from_str(&t)?))
                .with_context(|| {
                    format!(
                        "`{flag}` {} holds a design.json that is not a superlube design record; give another {flag}",
                        self.dir.display()
                    )
                })?;
            if s.input_hash != inputs.hash() {
                let diff = input_differences(&s.inputs(), inputs, 8);
                bail!(
                    "`{flag}` {} holds a design made with other inputs ({}); give another {flag} or remove the directory (nothing was computed)",
                    self.dir.display(),
                    if diff.is_empty() {
                        format!("written by superlube {}", s.version)
                    } else {
                        diff.join("; ")
                    }
                );
            }
            return Ok(true);
        }
        std::fs::create_dir_all(&self.dir)
            .with_context(|| format!("creating {}", self.dir.display()))?;
        let record = crate::runs::meta::RunMeta::new(inputs, &[], &path, flag);
        surrogate::atomic_file::write_atomic(&path, record.to_json().as_bytes())
            .with_context(|| format!("writing {}", path.display()))?;
        Ok(false)
    }

    /// The finished stage file `rel` for `inputs`: `None` when absent (or only partial); an
    /// error when its sidecar names other inputs ([`crate::runs::stored::finished`]).
    pub fn finished(&self, rel: &str, inputs: &Inputs) -> Result<Option<PathBuf>> {
        crate::runs::stored::finished(&self.path(rel), inputs, "this design's", &hint())
    }

    /// Reads the finished JSON stage `rel` (see [`Store::finished`]).
    pub fn load_json<T: DeserializeOwned>(&self, rel: &str, inputs: &Inputs) -> Result<Option<T>> {
        crate::runs::stored::load_json(
            &self.path(rel),
            inputs,
            "this design's",
            &hint(),
            "stage file",
        )
    }

    /// Reads the finished CSV stage `rel` (see [`Store::finished`]).
    pub fn load_csv<T: DeserializeOwned>(
        &self,
        rel: &str,
        inputs: &Inputs,
    ) -> Result<Option<Vec<T>>> {
        match self.finished(rel, inputs)? {
            None => Ok(None),
            Some(p) => {
                let rows: Result<Vec<T>, csv::Error> =
                    csv::Reader::from_path(&p).and_then(|mut r| r.deserialize().collect());
                Ok(Some(
                    rows.with_context(|| format!("reading {}", p.display()))?,
                ))
            }
        }
    }

    /// Writes the stage file `rel` (atomically, with its sidecar for `inputs`).
    pub fn save(
        &self,
        rel: &str,
        inputs: &Inputs,
        bytes: Vec<u8>,
        rows: Option<u64>,
    ) -> Result<()> {
        let mut outs = Outputs::new(inputs.clone(), vec![]);
        outs.write("stage", Some(&self.path(rel)), Ok(bytes), rows);
        outs.finish()
    }

    /// Writes the JSON stage `rel`.
    pub fn save_json<T: Serialize>(&self, rel: &str, inputs: &Inputs, v: &T) -> Result<()> {
        let text = serde_json::to_string_pretty(v)? + "\n";
        self.save(rel, inputs, text.into_bytes(), None)
    }

    /// Writes a final output `rel` with its sidecar through `outs`, unless the file already
    /// holds exactly `bytes` and has its sidecar (then nothing is touched). Returns whether it
    /// wrote.
    pub fn write_if_changed(
        &self,
        outs: &mut Outputs,
        rel: &str,
        bytes: Result<Vec<u8>>,
        rows: Option<u64>,
    ) -> bool {
        let path = self.path(rel);
        if let Ok(b) = &bytes {
            if std::fs::read(&path).is_ok_and(|old| &old == b) && sidecar_path(&path).exists() {
                return false;
            }
        }
        outs.write(rel, Some(&path), bytes, rows);
        true
    }
}

/// A stage's record of its own wall time.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Timing {
    /// Wall time of the stage when it was computed (s).
    pub wall_s: f64,
}
