//! One device of a yield as the workflow follows it ([`Device`]): its draw, its estimated
//! critical load and bracket, and the DEM's decisions on it.

use super::critical::CriticalLoad;
use super::fabrication::Sample;
use super::row::{DecidedBy, YieldRow};
use crate::study::rows::label;
use surrogate::units::{m_to_um, n_to_mn, pa_to_gpa};

/// A device: drawn, estimated, and decided by the DEM where asked.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Device {
    /// Its draw.
    pub sample: Sample,
    /// The estimate's critical load and bracket.
    pub estimate: CriticalLoad,
    /// DEM runs on it: (load N, superlubric).
    pub dem: Vec<(f64, bool)>,
}

impl Device {
    /// Whether the estimate cannot decide the device at `w` (N): `w` lies in its band bracket
    /// (W_low, W_high].
    pub fn in_band(&self, w: f64) -> bool {
        self.estimate.low < w && w <= self.estimate.high
    }

    /// What the DEM says of the device at `w` (N): `Some(true)` when it held at a load ≥ `w`,
    /// `Some(false)` when it failed at a load ≤ `w`, `None` when no run decides `w`.
    pub fn dem_at(&self, w: f64) -> Option<bool> {
        let held = self.dem.iter().any(|&(l, ok)| ok && l >= w);
        let failed = self.dem.iter().any(|&(l, ok)| !ok && l <= w);
        match (held, failed) {
            (true, false) => Some(true),
            (false, true) => Some(false),
            _ => None,
        }
    }

    /// The critical load (N) that agrees with the estimate and with every DEM decision: the
    /// estimate's W_c, raised to the highest load the DEM held, or lowered below the lowest
    /// load it failed at (to the highest load known good below it: W_low, a held load, else
    /// that load less `resolution`).
    pub fn critical(&self, resolution: f64) -> f64 {
        let mut wc = self.estimate.load;
        let held = self
            .dem
            .iter()
            .filter(|d| d.1)
            .map(|d| d.0)
            .fold(None, |m: Option<f64>, l| Some(m.map_or(l, |m| m.max(l))));
        let failed = self
            .dem
            .iter()
            .filter(|d| !d.1)
            .map(|d| d.0)
            .fold(None, |m: Option<f64>, l| Some(m.map_or(l, |m| m.min(l))));
        if let Some(f) = failed {
            if wc >= f {
                wc = [Some(self.estimate.low), held]
                    .into_iter()
                    .flatten()
                    .filter(|&x| x < f)
                    .reduce(f64::max)
                    .unwrap_or(f * (1.0 - resolution));
            }
        }
        if let Some(h) = held {
            if wc < h && failed.is_none_or(|f| h < f) {
                wc = h;
            }
        }
        wc
    }

    /// Its row of `yield.csv`, with `quoted` the final quoted load (N).
    pub fn row(&self, resolution: f64, quoted: Option<f64>) -> YieldRow {
        let s = &self.sample;
        let e = &self.estimate;
        let mn = |w: f64| label(n_to_mn(w));
        let diam = |f: fn(f64, f64) -> f64, init: f64| {
            s.slider_radii
                .as_ref()
                .map(|r| label(m_to_um(2.0 * r.iter().copied().fold(init, f))))
        };
        let decided_by = match quoted {
            Some(w) if self.in_band(w) && self.dem_at(w).is_some() => DecidedBy::Dem,
            _ => DecidedBy::Estimate,
        };
        let join = |v: Vec<String>| v.join(";");
        YieldRow {
            sample: s.index,
            theta_offset_deg: s.theta_offset_deg,
            direction_offset_deg: s.direction_offset_deg,
            seed: s.substrate_seed,
            p_crit_GPa: label(pa_to_gpa(s.p_crit)),
            sphere_diameter_min_um: diam(f64::min, f64::INFINITY),
            sphere_diameter_max_um: diam(f64::max, 0.0),
            critical_load_mN: mn(self.critical(resolution)),
            critical_load_low_mN: mn(e.low),
            critical_load_high_mN: mn(e.high),
            critical_load_estimate_mN: mn(e.load),
            limited_by: e.limited_by,
            decided_by,
            dem_loads_mN: join(self.dem.iter().map(|d| mn(d.0).to_string()).collect()),
            dem_superlubric: join(self.dem.iter().map(|d| d.1.to_string()).collect()),
            estimates: e.estimates,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::fab_yield::critical::Limit;

    fn device(low: f64, load: f64, high: f64, dem: Vec<(f64, bool)>) -> Device {
        Device {
            sample: Sample {
                index: 0,
                theta_offset_deg: 0.0,
                direction_offset_deg: 0.0,
                substrate_seed: 1 << 63,
                p_crit: 4e9,
                slider_radii: None,
            },
            estimate: CriticalLoad {
                load,
                low,
                high,
                limited_by: Limit::Path,
                censored: false,
                estimates: 3,
                resonance_from: None,
            },
            dem,
        }
    }

    /// The DEM moves the critical load to its side of every run: a failure at 1.5 below the
    /// estimate's 1.6 lowers it to W_low (1.2); a success at 1.7 above it raises it there.
    #[test]
    fn the_dem_overrules_the_estimate_in_the_band() {
        let d = device(1.2, 1.6, 1.9, vec![]);
        assert!(d.in_band(1.5) && d.in_band(1.9) && !d.in_band(1.2) && !d.in_band(2.0));
        assert_eq!(d.critical(0.01), 1.6);
        let failed = device(1.2, 1.6, 1.9, vec![(1.5, false)]);
        assert_eq!(failed.critical(0.01), 1.2);
        assert_eq!(failed.dem_at(1.5), Some(false));
        assert_eq!(failed.dem_at(1.4), None);
        let held = device(1.2, 1.6, 1.9, vec![(1.7, true)]);
        assert_eq!(held.critical(0.01), 1.7);
        assert_eq!(held.dem_at(1.65), Some(true));
        // a failure below W_low: just below the failed load
        let odd = device(1.2, 1.6, 1.9, vec![(1.0, false)]);
        assert!((odd.critical(0.01) - 0.99).abs() < 1e-12);
        assert_eq!(held.row(0.01, Some(1.7)).decided_by, DecidedBy::Dem);
        assert_eq!(d.row(0.01, Some(1.0)).decided_by, DecidedBy::Estimate);
    }
}
