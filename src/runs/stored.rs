//! Reuse of a finished file by its inputs: the one rule behind a design's stages and a batch's
//! runs. A file is reused when it and its sidecar exist, the sidecar says complete, and its
//! `input_hash` equals the hash of the inputs it would be made with now; a file whose sidecar
//! names other inputs is an error naming the inputs that differ (never mixed, never silently
//! overwritten). Cost: one sidecar read and one hash.

use super::meta::{input_differences, sidecar_path, Inputs, Sidecar};
use anyhow::{bail, Context, Result};
use serde::de::DeserializeOwned;
use std::path::{Path, PathBuf};

/// The finished file `path` for `inputs`: `None` when absent, only partial, or without its
/// sidecar (interrupted between the two renames: to be redone); an error when its sidecar
/// names other inputs. `whose` completes "made with other inputs than this …'s" and `hint`
/// (may be empty) follows "never mixed" in that error.
pub fn finished(path: &Path, inputs: &Inputs, whose: &str, hint: &str) -> Result<Option<PathBuf>> {
    if !path.exists() {
        return Ok(None);
    }
    let s = match Sidecar::of(path) {
        Ok(s) => s,
        Err(_) if !sidecar_path(path).exists() => return Ok(None),
        Err(e) => return Err(e),
    };
    if s.input_hash != inputs.hash() {
        let diff = input_differences(&s.inputs(), inputs, 8);
        bail!(
            "{} was made with other inputs than {whose} ({}): never mixed{hint}",
            path.display(),
            if diff.is_empty() {
                format!("written by superlube {}", s.version)
            } else {
                diff.join("; ")
            }
        );
    }
    Ok(s.complete.then(|| path.to_path_buf()))
}

/// Reads the finished JSON file `path` (see [`finished`]); `what` names the file's kind in a
/// parse error ("… is not a `what` of this version").
pub fn load_json<T: DeserializeOwned>(
    path: &Path,
    inputs: &Inputs,
    whose: &str,
    hint: &str,
    what: &str,
) -> Result<Option<T>> {
    match finished(path, inputs, whose, hint)? {
        None => Ok(None),
        Some(p) => {
            let text =
                std::fs::read_to_string(&p).with_context(|| format!("reading {}", p.display()))?;
            Ok(Some(serde_json::from_str(&text).with_context(|| {
                format!("{} is not a {what} of this version", p.display())
            })?))
        }
    }
}
