//! [`LatticeFile`]: a body's lattice in a scene file, in user units, and its conversion to a
//! [`Lattice`] and basis (m).

use super::Lattice;
use crate::error::SceneError;
use crate::units::um_to_m;
use serde::{Deserialize, Serialize};

/// A lattice in user units. `kind` is `triangular`, `square`, `rectangular` (needs
/// `spacing_um` and `spacing_y_um`) or `oblique` (needs `a1_um` and `a2_um`).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LatticeFile {
    /// Lattice kind.
    pub kind: String,
    /// Nearest-neighbour spacing (µm) of triangular/square, x spacing of rectangular. Default 3.
    pub spacing_um: Option<f64>,
    /// y spacing (µm) of a rectangular lattice.
    pub spacing_y_um: Option<f64>,
    /// First primitive vector (µm) of an oblique lattice.
    pub a1_um: Option<[f64; 2]>,
    /// Second primitive vector (µm) of an oblique lattice.
    pub a2_um: Option<[f64; 2]>,
    /// Basis sites (µm) in each lattice cell; the first sits at the slider (substrate) centre.
    /// Not with `honeycomb`/`kagome` (their basis is built in).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub basis_um: Option<Vec<[f64; 2]>>,
}

impl LatticeFile {
    /// Converts to a [`Lattice`] (m); `field` names the table in errors.
    pub fn to_lattice(&self, field: &str) -> Result<Lattice, SceneError> {
        let s = um_to_m(self.spacing_um.unwrap_or(3.0));
        let need = |v: Option<[f64; 2]>, name: &str| {
            v.map(|a| [um_to_m(a[0]), um_to_m(a[1])]).ok_or_else(|| {
                SceneError::invalid(
                    &format!("{field}.{name}"),
                    "missing",
                    "required for an oblique lattice",
                )
            })
        };
        let l = match self.kind.as_str() {
            "triangular" | "tri" => Lattice::triangular(s),
            "square" => Lattice::square(s),
            "rectangular" => {
                let sy = self.spacing_y_um.ok_or_else(|| {
                    SceneError::invalid(
                        &format!("{field}.spacing_y_um"),
                        "missing",
                        "required for a rectangular lattice",
                    )
                })?;
                Lattice::rectangular(s, um_to_m(sy))
            }
            "oblique" => Lattice::oblique(need(self.a1_um, "a1_um")?, need(self.a2_um, "a2_um")?),
            "honeycomb" | "kagome" => Lattice::triangular(s),
            other => {
                return Err(SceneError::Unknown {
                    field: format!("{field}.kind"),
                    what: "lattice".into(),
                    name: other.into(),
                    expected: "triangular, square, rectangular, oblique, honeycomb, kagome".into(),
                })
            }
        };
        for (name, v) in [
            ("spacing_um", self.spacing_um),
            ("spacing_y_um", self.spacing_y_um),
        ] {
            if let Some(sp) = v {
                if !(sp.is_finite() && sp > 0.0) {
                    return Err(SceneError::invalid(
                        &format!("{field}.{name}"),
                        sp,
                        "must be a positive number",
                    ));
                }
            }
        }
        l.validate(field)?;
        Ok(l)
    }

    /// The basis (m) of the lattice: `basis_um`, or the built-in one of `honeycomb`
    /// (`[0, 0]`, `[s/2, s/(2√3)]`: nearest neighbours s/√3 apart) and `kagome` (`[0, 0]`,
    /// `[s/2, 0]`, `[s/4, s√3/4]`: nearest neighbours s/2 apart), `s` = `spacing_um` (the
    /// triangular lattice constant). Empty: a Bravais lattice.
    pub fn to_basis(&self, field: &str) -> Result<Vec<[f64; 2]>, SceneError> {
        let s = um_to_m(self.spacing_um.unwrap_or(3.0));
        let preset = match self.kind.as_str() {
            "honeycomb" => Some(vec![[0.0, 0.0], [0.5 * s, 0.5 * s / 3f64.sqrt()]]),
            "kagome" => Some(vec![
                [0.0, 0.0],
                [0.5 * s, 0.0],
                [0.25 * s, 0.25 * 3f64.sqrt() * s],
            ]),
            _ => None,
        };
        match (preset, &self.basis_um) {
            (Some(_), Some(_)) => Err(SceneError::invalid(
                &format!("{field}.basis_um"),
                "given",
                &format!("a {} lattice has its basis built in; use kind = \"triangular\" with basis_um for another basis", self.kind),
            )),
            (Some(b), None) => Ok(b),
            (None, Some(b)) if b.is_empty() => Err(SceneError::invalid(
                &format!("{field}.basis_um"),
                "[]",
                "needs at least one site (the first sits at the centre)",
            )),
            (None, Some(b)) => Ok(b.iter().map(|p| p.map(um_to_m)).collect()),
            (None, None) => Ok(Vec::new()),
        }
    }
}
