//! [`OutlineFile`]: the slider outline in a scene file, in user units, and its conversion to an
//! [`Outline`] (m).

use super::Outline;
use crate::error::SceneError;
use crate::units::um_to_m;
use serde::{Deserialize, Serialize};

/// A slider outline in user units: `kind = "disc"` (`radius_um`), `"rectangle"`
/// (`size_um = [w, h]`) or `"polygon"` (`sides` and `radius_um` for a regular polygon with a
/// vertex on +x, or `vertices_um = [[x, y], …]`), all in the slider's frame about its centre.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutlineFile {
    /// Outline kind.
    pub kind: String,
    /// Disc radius or regular-polygon circumradius (µm).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius_um: Option<f64>,
    /// Rectangle sides `[w, h]` (µm).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub size_um: Option<[f64; 2]>,
    /// Number of sides of a regular polygon.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sides: Option<u32>,
    /// Vertices (µm) of an arbitrary polygon, in order.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertices_um: Option<Vec<[f64; 2]>>,
}

impl OutlineFile {
    /// Converts to an [`Outline`] (m) and, for a disc, its radius (m). `field` names it.
    pub fn to_outline(&self, field: &str) -> Result<(Outline, Option<f64>), SceneError> {
        let missing =
            |name: &str, why: &str| SceneError::invalid(&format!("{field}.{name}"), "missing", why);
        let o = match self.kind.as_str() {
            "disc" => {
                let r = self
                    .radius_um
                    .ok_or_else(|| missing("radius_um", "required for a disc"))?;
                if !(r.is_finite() && r > 0.0) {
                    return Err(SceneError::invalid(
                        &format!("{field}.radius_um"),
                        r,
                        "must be a positive number",
                    ));
                }
                return Ok((Outline::Disc, Some(um_to_m(r))));
            }
            "rectangle" => Outline::Rectangle {
                size: self
                    .size_um
                    .ok_or_else(|| missing("size_um", "required for a rectangle"))?
                    .map(um_to_m),
            },
            "polygon" => match (&self.vertices_um, self.sides, self.radius_um) {
                (Some(v), None, None) => Outline::Polygon {
                    vertices: v.iter().map(|p| p.map(um_to_m)).collect(),
                },
                (None, Some(sides), Some(r)) => Outline::RegularPolygon {
                    sides,
                    radius: um_to_m(r),
                },
                _ => {
                    return Err(missing(
                        "vertices_um",
                        "a polygon needs either vertices_um, or sides and radius_um",
                    ))
                }
            },
            other => {
                return Err(SceneError::Unknown {
                    field: format!("{field}.kind"),
                    what: "outline".into(),
                    name: other.into(),
                    expected: "disc, rectangle, polygon".into(),
                })
            }
        };
        o.validate(field)?;
        Ok((o, None))
    }
}
