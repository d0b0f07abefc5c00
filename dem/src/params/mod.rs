//! [`SimParams`]: every knob of the DEM engine (SI units), composed of one part per concern, the
//! way LAMMPS GRANULAR composes a contact model of sub-models:
//!
//! | part | file | what |
//! |---|---|---|
//! | [`ProtocolParams`] | `protocol.rs` | load, drive (K0, support, α), phases, sampling |
//! | [`ContactParams`] | `contact.rs` | contact damping γ_n, γ_t, Mindlin history |
//! | [`MountParams`] | `mount.rs` | slider and substrate springs, control layer, rigid-z / implicit |
//! | [`NumericsParams`] | `numerics.rs` | dt, skin, viscous bath, parallel chunks, overlap guard |
//! | [`ActiveSetParams`] | `active_set.rs` | pruning and the active set |
//!
//! Serialized flat (each part `#[serde(flatten)]`): the checkpoint header's `params.<field>`
//! keys are those of the one flat struct this replaced, so checkpoints stay compatible.

mod active_set;
mod contact;
mod mount;
mod numerics;
mod protocol;

pub use active_set::ActiveSetParams;
pub use contact::{ContactParams, Tangential};
pub use mount::MountParams;
pub use numerics::{DampingFrame, NumericsParams};
pub use protocol::ProtocolParams;

use serde::{Deserialize, Serialize};

/// Every knob of a DEM run (SI: s, m, N/m, N, rad), one part per concern. Defaults = the
/// reference study (docs/physics.md, Tier 3) except `numerics.dt`, which defaults to a
/// fraction of the stable step.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct SimParams {
    /// Load, drive, phases and sampling.
    #[serde(flatten)]
    pub protocol: ProtocolParams,
    /// Contact damping and tangential history.
    #[serde(flatten)]
    pub contact: ContactParams,
    /// Slider and substrate springs, control layer, mount model.
    #[serde(flatten)]
    pub mount: MountParams,
    /// Time step, skin, viscous bath, parallel passes, overlap guard.
    #[serde(flatten)]
    pub numerics: NumericsParams,
    /// Pruning and the active set.
    #[serde(flatten)]
    pub active: ActiveSetParams,
}

#[cfg(test)]
mod tests {
    use super::SimParams;
    use surrogate::friction::FrictionParams;

    /// The surrogate's friction estimate mirrors the DEM protocol with its own copies of these
    /// knobs (the `surrogate` crate cannot read `SimParams`): the defaults must stay equal, or
    /// μ_est would silently estimate another protocol than the DEM runs.
    #[test]
    fn friction_estimate_defaults_mirror_the_dem_protocol() {
        let d = SimParams::default();
        let f = FrictionParams::default();
        let (pr, m) = (&d.protocol, &d.mount);
        assert_eq!(f.k0, pr.k0);
        assert_eq!(f.k_slider_xy, m.k_slider_xy);
        assert_eq!(f.k_substrate_xy, m.k_substrate_xy);
        assert_eq!(f.speed, pr.support_speed);
        assert_eq!(f.slide_time, pr.slide_time);
        assert!((f.window_start - pr.measure_from * pr.slide_time).abs() <= 1e-12 * pr.slide_time);
        assert_eq!(f.tau, d.numerics.damping_time);
        assert_eq!(f.control_sphere_radius, m.control_sphere_radius);
    }

    /// The flat serialized form (checkpoint headers) keeps every field of the flat struct this
    /// replaced under its own name, and reads back.
    #[test]
    fn parts_serialize_flat_and_round_trip() {
        let d = SimParams::default();
        let v = serde_json::to_value(&d).unwrap();
        let o = v.as_object().unwrap();
        for k in [
            "load",
            "k0",
            "gamma_n",
            "k_slider_z",
            "dt",
            "active_set",
            "active_margin",
        ] {
            assert!(o.contains_key(k), "{k}");
        }
        assert_eq!(o.len(), 30, "{o:?}");
        let back: SimParams = serde_json::from_value(v).unwrap();
        assert_eq!(back, d);
    }
}
