//! One device of a yield as the workflow follows it ([`Device`]): its draw, its estimated
//! critical load and bracket, and the DEM's decisions on it.

use super::calibration::{Band, BandSource, Pair};
use super::critical::CriticalLoad;
use super::fabrication::Sample;
use super::margin::{estimate_at, transferred_limit, Ratios};
use super::row::{DecidedBy, YieldRow};
use crate::study::rows::label;
use surrogate::units::{m_to_um, n_to_mn, pa_to_gpa};

/// One DEM run on a device: its load, verdict and what it measured.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[allow(non_snake_case)]
pub struct DemRun {
    /// Load (N).
    pub load: f64,
    /// The DEM's verdict: superlubric.
    pub superlubric: bool,
    /// Its largest P_max over every step (GPa; `None`: the run failed).
    pub p_max_GPa: Option<f64>,
    /// μ_DEM (`None`: the run failed or locked in).
    pub mu: Option<f64>,
}

/// A device: drawn, estimated, and decided by the DEM where asked.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Device {
    /// Its draw.
    pub sample: Sample,
    /// The estimate's critical load and bracket.
    pub estimate: CriticalLoad,
    /// DEM runs on it.
    pub dem: Vec<DemRun>,
    /// Whether it is a device of the DEM check (drawn after the yield's own).
    #[serde(default)]
    pub check: bool,
}

/// Where the lower end of a device's [`Bounds`] comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Floor {
    /// The band (or the device's own worst ratios) transferred through its estimate: a
    /// prediction, not a DEM run.
    Transferred,
    /// A load the DEM held.
    Held,
    /// Nothing: the DEM failed the device at or below its transferred floor (low = 0).
    Lost,
}

/// What the yield knows of a device's DEM critical load (N): it lies in [low, high]; `located`
/// when the DEM bracketed it to the resolution (then low = high = the highest load held).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Lowest possible value.
    pub low: f64,
    /// Where `low` comes from.
    pub floor: Floor,
    /// Highest possible value.
    pub high: f64,
    /// The DEM located it.
    pub located: bool,
    /// The DEM failed it above its highest held load ([`Device::failed`]): only the DEM's
    /// own location decides it.
    pub failed: bool,
}

impl Device {
    /// The highest load (N) the DEM held.
    pub fn held(&self) -> Option<f64> {
        self.dem
            .iter()
            .filter(|r| r.superlubric)
            .map(|r| r.load)
            .reduce(f64::max)
    }

    /// The lowest load (N) above the highest held one ([`Device::held`]) that the DEM failed
    /// at: the failure that bounds the device's critical load from above. A failure below a
    /// held load (μ_DEM above μ_sl at a low load, superlubric higher up) is a floor, not a
    /// critical load: [`Device::lowest_failure`] still sees it.
    pub fn failed(&self) -> Option<f64> {
        let held = self.held().unwrap_or(f64::NEG_INFINITY);
        self.dem
            .iter()
            .filter(|r| !r.superlubric && r.load > held)
            .map(|r| r.load)
            .reduce(f64::min)
    }

    /// The lowest load (N) the DEM failed at, wherever it lies.
    pub fn lowest_failure(&self) -> Option<f64> {
        self.dem
            .iter()
            .filter(|r| !r.superlubric)
            .map(|r| r.load)
            .reduce(f64::min)
    }

    /// The DEM critical load (N) when the DEM held at a and failed at b > a with
    /// b − a ≤ `resolution`·b: a.
    pub fn located(&self, resolution: f64) -> Option<f64> {
        match (self.held(), self.failed()) {
            (Some(a), Some(b)) if a < b && b - a <= resolution * b => Some(a),
            _ => None,
        }
    }

    /// P_crit (GPa) of the device.
    fn p_crit_gpa(&self) -> f64 {
        pa_to_gpa(self.sample.p_crit)
    }

    /// The pairs of its DEM runs: each run's P_max and μ beside the estimate's at its load
    /// (runs without a measurement give none).
    pub fn pairs(&self) -> Vec<Pair> {
        self.dem
            .iter()
            .filter_map(|r| {
                let (pe, me) = estimate_at(&self.estimate.probes, r.load);
                Some(Pair {
                    sample: self.sample.index,
                    load_mN: label(n_to_mn(r.load)),
                    p_max_estimate_GPa: pe?,
                    p_max_dem_GPa: r.p_max_GPa?,
                    mu_estimate: me?,
                    mu_dem: r.mu.filter(|&m| m > 0.0)?,
                    p_crit_GPa: self.p_crit_gpa(),
                    check: self.check,
                })
            })
            .collect()
    }

    /// The load (N) where the DEM's verdict turns if the DEM is the estimate scaled by `r`
    /// ([`transferred_limit`]).
    pub fn limit_with(&self, r: Ratios, mu_sl: f64) -> f64 {
        transferred_limit(&self.estimate.probes, r, self.p_crit_gpa(), mu_sl)
    }

    /// The predicted DEM critical load (N): the margin of its own DEM run nearest to the
    /// band's prediction, among those whose coating held, transferred through its estimate,
    /// else the band's bias-corrected centre (a run whose coating failed measures the failure,
    /// not the margin: [`super::calibration`]).
    pub fn predicted(&self, band: &Band, mu_sl: f64) -> f64 {
        let centre = self.limit_with(band.centre(), mu_sl);
        self.pairs()
            .iter()
            .filter(|p| p.coating_held())
            .map(|p| (p, n_to_mn(centre) - p.load_mN))
            .filter(|(p, _)| p.p_ratio().is_finite() && p.mu_ratio().is_finite())
            .min_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
            .map_or(centre, |(p, _)| self.limit_with(p.ratios(), mu_sl))
    }

    /// Where the device's DEM critical load can lie (N): the band's bracket (the estimate's
    /// own [W_low, W_high] for the global band; the design's worst and best ratios transferred
    /// through its estimate otherwise), its lower end widened to the worst ratios of its own
    /// runs, narrowed by its DEM runs (a held load is a lower
    /// bound, one failed above every held load an upper bound; a failure below the band drops
    /// the band's lower edge).
    pub fn bounds(&self, band: &Band, mu_sl: f64, resolution: f64) -> Bounds {
        if let Some(v) = self.located(resolution) {
            return Bounds {
                low: v,
                floor: Floor::Held,
                high: v,
                located: true,
                failed: true,
            };
        }
        let (mut low, mut high) = match band.source {
            BandSource::Global => (self.estimate.low, self.estimate.high),
            BandSource::Design => {
                let lo = self.limit_with(band.worst(), mu_sl);
                (lo, self.limit_with(band.best(), mu_sl).max(lo))
            }
        };
        // its own runs, where they show the DEM worse than the band (a run whose coating
        // failed is left out of the band, not out of its own device's bracket)
        let own = self.pairs();
        if !own.is_empty() {
            let worst = own.iter().fold(band.worst(), |w, p| Ratios {
                p: w.p.max(p.p_ratio()),
                mu: w.mu.min(p.mu_ratio()),
            });
            low = low.min(self.limit_with(worst, mu_sl));
        }
        let (held, failed) = (self.held(), self.failed());
        let mut floor = Floor::Transferred;
        if let Some(b) = failed {
            if low >= b {
                low = 0.0;
                floor = Floor::Lost;
            }
            high = high.min(b);
        }
        if let Some(a) = held {
            if a >= low {
                floor = Floor::Held;
            }
            low = low.max(a);
            high = high.max(a);
            if let Some(b) = failed {
                high = high.min(b).max(a);
            }
        }
        Bounds {
            low,
            floor,
            high,
            located: false,
            failed: failed.is_some(),
        }
    }

    /// Its row of `yield.csv`: `critical` its critical load (N) as the yield counts it, and
    /// who set it.
    pub fn row(&self, critical: f64, decided_by: DecidedBy) -> YieldRow {
        let s = &self.sample;
        let e = &self.estimate;
        let mn = |w: f64| label(n_to_mn(w));
        let diam = |f: fn(f64, f64) -> f64, init: f64| {
            s.slider_radii
                .as_ref()
                .map(|r| label(m_to_um(2.0 * r.iter().copied().fold(init, f))))
        };
        let join = |v: Vec<String>| v.join(";");
        YieldRow {
            sample: s.index,
            check: self.check,
            theta_offset_deg: s.theta_offset_deg,
            direction_offset_deg: s.direction_offset_deg,
            seed: s.substrate_seed,
            p_crit_GPa: label(pa_to_gpa(s.p_crit)),
            sphere_diameter_min_um: diam(f64::min, f64::INFINITY),
            sphere_diameter_max_um: diam(f64::max, 0.0),
            critical_load_mN: mn(critical),
            critical_load_low_mN: mn(e.low),
            critical_load_high_mN: mn(e.high),
            critical_load_estimate_mN: mn(e.load),
            limited_by: e.limited_by,
            decided_by,
            dem_loads_mN: join(self.dem.iter().map(|d| mn(d.load).to_string()).collect()),
            dem_superlubric: join(self.dem.iter().map(|d| d.superlubric.to_string()).collect()),
            estimates: e.estimates,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::study::fab_yield::critical::Limit;

    fn device(low: f64, load: f64, high: f64, dem: &[(f64, bool)]) -> Device {
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
                probes: Vec::new(),
            },
            dem: dem
                .iter()
                .map(|&(load, superlubric)| DemRun {
                    load,
                    superlubric,
                    p_max_GPa: None,
                    mu: None,
                })
                .collect(),
            check: false,
        }
    }

    /// The DEM narrows the bracket to its side of every run: a failure at 1.5 caps it there, a
    /// success at 1.7 raises its floor; a failure below W_low drops the band's floor; a held
    /// and a failed run within the resolution locate it at the held load; a failure below a
    /// held load bounds nothing.
    #[test]
    fn the_dem_narrows_the_bracket() {
        let g = Band::global();
        let b = |d: &Device| {
            let b = d.bounds(&g, 0.02, 0.01);
            (b.low, b.high, b.located)
        };
        let d = device(1.2, 1.6, 1.9, &[]);
        assert_eq!(b(&d), (1.2, 1.9, false));
        let failed = device(1.2, 1.6, 1.9, &[(1.5, false)]);
        assert_eq!(b(&failed), (1.2, 1.5, false));
        let held = device(1.2, 1.6, 1.9, &[(1.7, true)]);
        assert_eq!(b(&held), (1.7, 1.9, false));
        let odd = device(1.2, 1.6, 1.9, &[(1.0, false)]);
        assert_eq!(b(&odd), (0.0, 1.0, false));
        let located = device(1.2, 1.6, 1.9, &[(1.4, false), (1.39, true)]);
        assert_eq!(b(&located), (1.39, 1.39, true));
        let wide = device(1.2, 1.6, 1.9, &[(1.4, false), (1.3, true)]);
        assert_eq!(b(&wide), (1.3, 1.4, false));
        // a failure below a held load is a floor: it bounds nothing, the summary still sees it
        let floor = device(1.2, 1.6, 1.9, &[(1.0, false), (1.5, true), (1.7, false)]);
        assert_eq!(
            (floor.failed(), floor.lowest_failure()),
            (Some(1.7), Some(1.0))
        );
        assert_eq!(b(&floor), (1.5, 1.7, false));
        // where each floor comes from: the band, a held run, or nothing left
        let src = |d: &Device| d.bounds(&g, 0.02, 0.01).floor;
        assert_eq!(
            [src(&d), src(&failed), src(&held), src(&odd), src(&wide)],
            [
                Floor::Transferred,
                Floor::Transferred,
                Floor::Held,
                Floor::Lost,
                Floor::Held
            ]
        );
    }
}
