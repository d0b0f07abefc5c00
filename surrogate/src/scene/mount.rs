//! [`Mount`]: how the slider's control layer may tilt. A property of the scene that both tiers
//! obey (the quasi-static solver as a moment balance, the DEM as tilt degrees of freedom of the
//! control layer).

use crate::error::SceneError;
use serde::{Deserialize, Serialize};

/// The study's anti-tilt spring stiffness K1 (N/m) between the centres of mass of opposing
/// halves of the control layer.
pub const STUDY_K1: f64 = 1e6;

/// The slider mount: which tilts (rotations about the in-plane x and y axes) the control layer
/// may take.
///
/// Tilt convention (both tiers): slider sphere i, at lateral offset `(x_i, y_i)` from the disc
/// centre, sits at height `z + t_x·y_i − t_y·x_i` for tilts `t = [t_x, t_y]` (rad) about x and y.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Mount {
    /// No tilt: the control layer only translates (t = 0 always).
    Locked,
    /// Free tilt: no restoring moment (the contact forces alone balance the moments).
    Free,
    /// The study's mount: the control layer is divided into four quarters and the centres of
    /// mass of opposing halves (left–right, upper–lower, in the slider's own frame) are coupled
    /// by vertical springs of stiffness `k1` (N/m). For a rigid control layer this is the
    /// rotational stiffness of [`Mount::tilt_stiffness`].
    Springs {
        /// Spring stiffness K1 (N/m) between opposing half-layer centres of mass. Study: 1e6.
        k1: f64,
    },
}

impl Default for Mount {
    /// The study's anti-tilt springs, K1 = 10⁶ N/m.
    fn default() -> Self {
        Mount::Springs { k1: STUDY_K1 }
    }
}

impl Mount {
    /// The kebab-case name used in files and on the command line: `locked`, `free`, `springs`.
    pub fn name(&self) -> &'static str {
        match self {
            Mount::Locked => "locked",
            Mount::Free => "free",
            Mount::Springs { .. } => "springs",
        }
    }

    /// Parses `locked | free | springs`; `k1` (N/m) is the spring stiffness used by `springs`
    /// (default [`STUDY_K1`]) and must not be given with the others. `field` names the option
    /// in errors.
    pub fn parse(name: &str, k1: Option<f64>, field: &str) -> Result<Mount, SceneError> {
        let m = match name {
            "locked" => Mount::Locked,
            "free" => Mount::Free,
            "springs" => Mount::Springs {
                k1: k1.unwrap_or(STUDY_K1),
            },
            other => {
                return Err(SceneError::Unknown {
                    field: field.into(),
                    what: "tilt mount".into(),
                    name: other.into(),
                    expected: "locked, free, springs".into(),
                })
            }
        };
        if k1.is_some() && !matches!(m, Mount::Springs { .. }) {
            return Err(SceneError::invalid(
                &format!("{field}_k1_N_m"),
                k1.unwrap_or_default(),
                &format!("only applies to `springs`, not to `{name}`"),
            ));
        }
        m.validate(field)?;
        Ok(m)
    }

    /// Checks the stiffness (finite, ≥ 0); `field` names the option in errors.
    pub fn validate(&self, field: &str) -> Result<(), SceneError> {
        if let Mount::Springs { k1 } = self {
            if !(k1.is_finite() && *k1 >= 0.0) {
                return Err(SceneError::invalid(
                    &format!("{field}_k1_N_m"),
                    k1,
                    "must be a non-negative stiffness in N/m",
                ));
            }
        }
        Ok(())
    }

    /// Whether the control layer has tilt degrees of freedom (`free` or `springs`).
    pub fn tilts(&self) -> bool {
        !matches!(self, Mount::Locked)
    }

    /// Rotational stiffness tensor `K_t` (N·m/rad, 2×2, lab frame, acting on `[t_x, t_y]`) of the
    /// mount for a slider whose sites, relative to the disc centre **in the slider's own
    /// (unrotated) frame**, are `local`, rotated by `theta` (rad). The restoring moment is
    /// `M = −K_t·t` and the stored energy `½ tᵀ K_t t`.
    ///
    /// Math: in the slider frame (x', y'), tilting about x' by t'_x moves the upper half
    /// (y' > 0) and the lower half (y' < 0) apart in z by `t'_x·d_y`, `d_y = ȳ'_upper − ȳ'_lower`
    /// the distance between their centres of mass, so the K1 spring stores `½ K1 d_y² t'_x²`;
    /// likewise `½ K1 d_x² t'_y²` about y' with the left/right halves. Sites on a dividing line
    /// count half to each side. In the lab frame `K_t = R(θ) diag(K1 d_y², K1 d_x²) R(θ)ᵀ`.
    /// Zero for `free` and `locked` (locked has no tilt at all). Cost O(N).
    pub fn tilt_stiffness(&self, local: &[[f64; 2]], theta: f64) -> [[f64; 2]; 2] {
        rotate_tilt_stiffness(self.principal_tilt_stiffness(local), theta)
    }

    /// The principal rotational stiffnesses `[K1·d_y², K1·d_x²]` (N·m/rad) about the slider's own
    /// (unrotated) x' and y' axes (see [`Mount::tilt_stiffness`] for the math); zero for `free`
    /// and `locked`. The lab-frame tensor at rotation θ is [`rotate_tilt_stiffness`] of it.
    /// Cost O(N).
    pub fn principal_tilt_stiffness(&self, local: &[[f64; 2]]) -> [f64; 2] {
        let k1 = match self {
            Mount::Springs { k1 } => *k1,
            _ => return [0.0; 2],
        };
        let d = |axis: usize| {
            let (mut sp, mut wp, mut sn, mut wn) = (0.0, 0.0, 0.0, 0.0);
            for p in local {
                let v = p[axis];
                if v > 0.0 {
                    sp += v;
                    wp += 1.0;
                } else if v < 0.0 {
                    sn += v;
                    wn += 1.0;
                } else {
                    wp += 0.5;
                    wn += 0.5;
                }
            }
            if wp > 0.0 && wn > 0.0 {
                sp / wp - sn / wn
            } else {
                0.0
            }
        };
        let (dx, dy) = (d(0), d(1));
        [k1 * dy * dy, k1 * dx * dx]
    }
}

/// The lab-frame rotational stiffness tensor `R(θ) diag(k[0], k[1]) R(θ)ᵀ` (N·m/rad) of principal
/// stiffnesses `k` about the slider's own axes, for the slider rotated by `theta` (rad). O(1).
pub fn rotate_tilt_stiffness(k: [f64; 2], theta: f64) -> [[f64; 2]; 2] {
    let [kx, ky] = k;
    let (s, c) = theta.sin_cos();
    [
        [c * c * kx + s * s * ky, c * s * (kx - ky)],
        [c * s * (kx - ky), s * s * kx + c * c * ky],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_and_names() {
        assert_eq!(Mount::parse("locked", None, "tilt").unwrap(), Mount::Locked);
        assert_eq!(
            Mount::parse("springs", None, "tilt").unwrap(),
            Mount::Springs { k1: 1e6 }
        );
        assert_eq!(
            Mount::parse("springs", Some(5.0), "tilt").unwrap(),
            Mount::Springs { k1: 5.0 }
        );
        let e = Mount::parse("wobbly", None, "slider.tilt").unwrap_err();
        assert!(e.to_string().contains("slider.tilt"), "{e}");
        let e = Mount::parse("free", Some(1.0), "slider.tilt").unwrap_err();
        assert!(e.to_string().contains("slider.tilt_k1_N_m"), "{e}");
        let e = Mount::parse("springs", Some(-1.0), "slider.tilt").unwrap_err();
        assert!(e.to_string().contains("slider.tilt_k1_N_m"), "{e}");
        assert_eq!(Mount::default().name(), "springs");
    }

    #[test]
    fn tilt_stiffness_of_two_by_two_square() {
        // Four sites at (±1, ±1): halves 2 apart in both directions → K1·4 on both axes,
        // isotropic, so rotation leaves it unchanged.
        let local = [[1.0, 1.0], [-1.0, 1.0], [1.0, -1.0], [-1.0, -1.0]];
        let m = Mount::Springs { k1: 3.0 };
        for th in [0.0, 0.3, 1.0] {
            let k = m.tilt_stiffness(&local, th);
            assert!((k[0][0] - 12.0).abs() < 1e-12 && (k[1][1] - 12.0).abs() < 1e-12);
            assert!(k[0][1].abs() < 1e-12 && k[1][0].abs() < 1e-12);
        }
        assert_eq!(Mount::Free.tilt_stiffness(&local, 0.0), [[0.0; 2]; 2]);
        // A site on the dividing line counts half to each side.
        let local = [[0.0, 2.0], [0.0, -2.0], [0.0, 0.0]];
        let k = m.tilt_stiffness(&local, 0.0);
        // upper: (2 + 0)/1.5, lower: (−2 + 0)/1.5 → d_y = 8/3
        assert!((k[0][0] - 3.0 * (8.0f64 / 3.0).powi(2)).abs() < 1e-12);
    }
}
