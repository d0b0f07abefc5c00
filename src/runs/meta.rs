//! Run metadata: what every output file records about the run that made it.
//!
//! Every file a command writes, `F`, gets a JSON sidecar `F.meta.json` (written atomically next
//! to it; a streaming output's partial file `F.partial` gets `F.partial.meta.json` while it runs).
//! The CSV columns stay plain; the sidecar holds:
//!
//! - `tool`, `version`: `superlube` and its version;
//! - `workflow`: `screen`, `landscape`, `corrugation`, `figures/…`, `equilibrate`, `slide`;
//! - `command_line`: the exact arguments (the program name written as `superlube`);
//! - `scene`: the full resolved scene in user units as a [`SceneFile`] (every field set; the
//!   lattices only when they differ from the pattern's preset), and `scene_toml`: the same as a
//!   ready-to-use `--scene` file (`jq -r .scene_toml F.meta.json > scene.toml`);
//! - `params`: the workflow's parameters in user units;
//! - `input_hash`: `sha256:` of the canonical JSON of (tool, version, workflow, scene, params):
//!   the inputs that determine the rows, without timestamps, paths or the command line, so two
//!   outputs of the same sweep (shards, a resumed run, a cached design stage) have the same hash;
//! - `warnings` (e.g. [`surrogate::Scene::edge_warning`]), `file`, `role` (the flag that named
//!   the file), `rows` (data rows of a CSV), `complete` (false for a partial file);
//! - `shard` (only for the output of `--shard i/n`): a [`ShardInfo`] — shard index and count,
//!   the sweep's item count, this shard's items, rows per item, row schema — recorded beside the
//!   unchanged `input_hash`, so `superlube merge` can check that shards belong to one sweep;
//! - `merged_from` (only for the output of `superlube merge`): the shard files merged.
//!
//! [`Sidecar`] reads a sidecar back (resume and merge checks).

use super::sweep::ShardInfo;
use anyhow::{bail, Context, Result};
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use surrogate::SceneFile;

/// The tool's version (Cargo package version).
pub const VERSION: &str = env!("CARGO_PKG_VERSION");

/// The sidecar of an output file: `F` → `F.meta.json`.
pub fn sidecar_path(path: &std::path::Path) -> std::path::PathBuf {
    let mut s = path.as_os_str().to_owned();
    s.push(".meta.json");
    std::path::PathBuf::from(s)
}

/// The inputs of a run: what determines its rows.
#[derive(Debug, Clone, Serialize)]
pub struct Inputs {
    /// Workflow name (`screen`, `landscape`, …).
    pub workflow: String,
    /// The resolved scene in user units (`None` for workflows that use several built-in scenes).
    pub scene: Option<SceneFile>,
    /// Workflow parameters in user units.
    pub params: serde_json::Value,
}

impl Inputs {
    /// `sha256:<hex>` of the canonical JSON of tool, version and these inputs.
    pub fn hash(&self) -> String {
        #[derive(Serialize)]
        struct Canon<'a> {
            tool: &'a str,
            version: &'a str,
            inputs: &'a Inputs,
        }
        // serde_json writes struct fields in declaration order and map keys sorted
        // (`serde_json::Value` objects are BTreeMaps): the text is canonical.
        let text = serde_json::to_vec(&Canon {
            tool: "superlube",
            version: VERSION,
            inputs: self,
        })
        .unwrap_or_default();
        let digest = Sha256::digest(&text);
        let hex: String = digest.iter().map(|b| format!("{b:02x}")).collect();
        format!("sha256:{hex}")
    }
}

/// A sidecar's content (see the module docs).
#[derive(Debug, Clone, Serialize)]
pub struct RunMeta {
    /// Always `superlube`.
    pub tool: &'static str,
    /// Tool version.
    pub version: &'static str,
    /// Workflow name.
    pub workflow: String,
    /// File this sidecar describes (file name only).
    pub file: String,
    /// The command-line flag that named the file (`--out`, `--json`, …).
    pub role: String,
    /// `false` while the file is a partial stream.
    pub complete: bool,
    /// Data rows of a CSV file.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rows: Option<u64>,
    /// Hash of the inputs (see [`Inputs::hash`]).
    pub input_hash: String,
    /// The exact command line.
    pub command_line: Vec<String>,
    /// Warnings about the inputs (edge overhang, …).
    pub warnings: Vec<String>,
    /// Resolved scene (user units), reloadable as a `--scene` file.
    pub scene: Option<SceneFile>,
    /// The same scene as TOML text.
    pub scene_toml: Option<String>,
    /// Workflow parameters (user units).
    pub params: serde_json::Value,
    /// The shard of the sweep this file holds (`--shard i/n`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shard: Option<ShardInfo>,
    /// The shard files a `superlube merge` output was made from.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub merged_from: Option<Vec<String>>,
}

impl RunMeta {
    /// The sidecar of `file` (written under `role`) for a run with `inputs`.
    pub fn new(
        inputs: &Inputs,
        warnings: &[String],
        file: &std::path::Path,
        role: &str,
    ) -> RunMeta {
        RunMeta {
            tool: "superlube",
            version: VERSION,
            workflow: inputs.workflow.clone(),
            file: file
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default(),
            role: role.to_string(),
            complete: true,
            rows: None,
            input_hash: inputs.hash(),
            command_line: command_line(),
            warnings: warnings.to_vec(),
            scene: inputs.scene.clone(),
            scene_toml: inputs.scene.as_ref().and_then(|s| toml::to_string(s).ok()),
            params: inputs.params.clone(),
            shard: None,
            merged_from: None,
        }
    }

    /// Pretty JSON text with a final newline.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default() + "\n"
    }
}

/// A sidecar read back from its JSON (the fields the resume and merge checks need).
#[derive(Debug, Clone, Deserialize)]
pub struct Sidecar {
    /// `superlube`.
    pub tool: String,
    /// Version of the tool that wrote it.
    pub version: String,
    /// Workflow name.
    pub workflow: String,
    /// Whether the file is complete (false: a partial stream).
    pub complete: bool,
    /// Data rows.
    #[serde(default)]
    pub rows: Option<u64>,
    /// Hash of the inputs.
    pub input_hash: String,
    /// Warnings recorded.
    #[serde(default)]
    pub warnings: Vec<String>,
    /// Resolved scene (user units).
    #[serde(default)]
    pub scene: Option<SceneFile>,
    /// Parameters (user units).
    #[serde(default)]
    pub params: serde_json::Value,
    /// The shard, for a `--shard` output.
    #[serde(default)]
    pub shard: Option<ShardInfo>,
}

impl Sidecar {
    /// Reads the sidecar of `file` (`file.meta.json`). Errors name the sidecar and why.
    pub fn of(file: &std::path::Path) -> Result<Sidecar> {
        let path = sidecar_path(file);
        let text = match std::fs::read_to_string(&path) {
            Ok(t) => t,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => bail!(
                "{} has no sidecar {} (needed to check which sweep it belongs to)",
                file.display(),
                path.display()
            ),
            Err(e) => return Err(e).with_context(|| format!("reading {}", path.display())),
        };
        let s: Sidecar = serde_json::from_str(&text)
            .with_context(|| format!("{} is not a superlube sidecar", path.display()))?;
        if s.tool != "superlube" {
            bail!("{} was not written by superlube", path.display());
        }
        Ok(s)
    }

    /// The inputs recorded (workflow, scene, parameters): hashing them again must give
    /// `input_hash` when the tool version is this one and the sidecar was not edited.
    pub fn inputs(&self) -> Inputs {
        Inputs {
            workflow: self.workflow.clone(),
            scene: self.scene.clone(),
            params: self.params.clone(),
        }
    }
}

/// Where two recorded inputs differ: up to `max` JSON paths (`params.load_mN`,
/// `scene.slider.theta_deg`, …) with both values, for "belongs to another sweep" messages.
pub fn input_differences(a: &Inputs, b: &Inputs, max: usize) -> Vec<String> {
    fn walk(path: &str, a: &serde_json::Value, b: &serde_json::Value, out: &mut Vec<String>) {
        use serde_json::Value;
        match (a, b) {
            (Value::Object(x), Value::Object(y)) => {
                let keys: std::collections::BTreeSet<&String> = x.keys().chain(y.keys()).collect();
                for k in keys {
                    let sub = if path.is_empty() {
                        k.clone()
                    } else {
                        format!("{path}.{k}")
                    };
                    walk(
                        &sub,
                        x.get(k).unwrap_or(&Value::Null),
                        y.get(k).unwrap_or(&Value::Null),
                        out,
                    );
                }
            }
            _ if a != b => {
                let short = |v: &Value| {
                    let t = v.to_string();
                    if t.chars().count() > 60 {
                        format!("{}…", t.chars().take(60).collect::<String>())
                    } else {
                        t
                    }
                };
                out.push(format!("{path}: {} vs {}", short(a), short(b)));
            }
            _ => {}
        }
    }
    let (x, y) = (
        serde_json::to_value(a).unwrap_or_default(),
        serde_json::to_value(b).unwrap_or_default(),
    );
    let mut out = Vec::new();
    walk("", &x, &y, &mut out);
    out.truncate(max);
    out
}

/// The command line of a command run in process (the Python module), recorded instead of the
/// process's arguments while set ([`set_command_line`]).
static COMMAND_LINE: std::sync::Mutex<Option<Vec<String>>> = std::sync::Mutex::new(None);

/// Sets (or with `None` clears) the command line the sidecars record, for a caller that runs
/// a command in process with its own arguments (one command at a time).
pub fn set_command_line(argv: Option<Vec<String>>) {
    *COMMAND_LINE.lock().unwrap_or_else(|e| e.into_inner()) = argv;
}

/// The process's arguments (or those set by [`set_command_line`]), the program name written as
/// `superlube`.
pub fn command_line() -> Vec<String> {
    let set = COMMAND_LINE
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .clone();
    let mut v: Vec<String> = set.unwrap_or_else(|| {
        std::env::args_os()
            .map(|a| a.to_string_lossy().into_owned())
            .collect()
    });
    if let Some(first) = v.first_mut() {
        *first = "superlube".into();
    }
    v
}

pub use surrogate::scene::scene_file;

#[cfg(test)]
mod tests {
    use super::*;
    use surrogate::Scene;

    #[test]
    fn hash_depends_on_inputs_only() {
        let s = Scene::preset("tri-tri").unwrap();
        let a = Inputs {
            workflow: "screen".into(),
            scene: Some(scene_file(&s)),
            params: serde_json::json!({"load_mN": [1.4]}),
        };
        let mut b = a.clone();
        assert_eq!(a.hash(), b.hash());
        assert!(a.hash().starts_with("sha256:") && a.hash().len() == 7 + 64);
        b.params = serde_json::json!({"load_mN": [1.5]});
        assert_ne!(a.hash(), b.hash());
        let mut s2 = s.clone();
        s2.substrate.seed = 2;
        b = a.clone();
        b.scene = Some(scene_file(&s2));
        assert_ne!(a.hash(), b.hash());
    }
}
