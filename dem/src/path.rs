//! The slide path checked against the substrate before a run starts.

use crate::{DemError, SimParams};
use surrogate::Scene;

/// Checks that the slider disc plus one slider sphere radius stays over the substrate rectangle
/// along the whole slide: from the disc centre at the scene's offset to `support_speed × slide_time`
/// further along the pulling direction α, plus a drift allowance of one substrate lattice
/// period in every direction (the slider settling into the corrugation when it is released).
/// Nothing to check when the run does not slide. The error names the flags to change and the
/// longest slide that would fit. Cost O(1).
pub fn check_path(scene: &Scene, params: &SimParams) -> Result<(), DemError> {
    let travel = params.protocol.support_speed * params.protocol.slide_time;
    if travel.is_nan() || travel <= 0.0 {
        return Ok(());
    }
    let um = 1e6;
    let lat = scene.substrate.lattice;
    let norm = |a: [f64; 2]| (a[0] * a[0] + a[1] * a[1]).sqrt();
    let drift = norm(lat.a1).max(norm(lat.a2));
    let reach = scene.slider.radius + scene.max_slider_sphere_radius() + drift;
    let half = [0.5 * scene.substrate.size[0], 0.5 * scene.substrate.size[1]];
    let lim = [half[0] - reach, half[1] - reach];
    let c0 = scene.slider.offset;
    let (s, c) = params.protocol.alpha.sin_cos();
    let d = [c, s];
    let c1 = [c0[0] + travel * d[0], c0[1] + travel * d[1]];
    let over = |p: [f64; 2]| (p[0].abs() - lim[0]).max(p[1].abs() - lim[1]);
    let (o0, o1) = (over(c0), over(c1));
    if o0 <= 0.0 && o1 <= 0.0 {
        return Ok(());
    }
    // longest travel from c0 along d that stays inside
    let mut t_max = f64::INFINITY;
    for k in 0..2 {
        if d[k] > 1e-12 {
            t_max = t_max.min((lim[k] - c0[k]) / d[k]);
        } else if d[k] < -1e-12 {
            t_max = t_max.min((lim[k] + c0[k]) / -d[k]);
        }
    }
    let (which, p, o) = if o0 > 0.0 {
        ("start", c0, o0)
    } else {
        ("end", c1, o1)
    };
    let fix = if o0 > 0.0 {
        "the slider does not fit at its start: change --offset-um or enlarge the substrate (--substrate-um)".to_string()
    } else {
        format!(
            "at {} m/s the longest slide that fits is {:.3} µs; shorten --slide-us or --speed-m-s, change --alpha-deg or --offset-um, or enlarge the substrate (--substrate-um)",
            params.protocol.support_speed,
            (t_max.max(0.0) / params.protocol.support_speed) * 1e6
        )
    };
    Err(DemError::Path(format!(
        "at its {which} point the slider centre is at [{:.3}, {:.3}] µm (offset [{:.3}, {:.3}] µm + {:.3} µm of travel = speed × slide time along {:.3}° from x); the disc (radius {:.3} µm) plus one sphere radius ({:.3} µm) and a drift allowance of one substrate period ({:.3} µm) reach {:.3} µm beyond the {}x{} µm substrate; {fix}",
        p[0] * um,
        p[1] * um,
        c0[0] * um,
        c0[1] * um,
        travel * um,
        params.protocol.alpha.to_degrees(),
        scene.slider.radius * um,
        scene.max_slider_sphere_radius() * um,
        drift * um,
        o * um,
        scene.substrate.size[0] * um,
        scene.substrate.size[1] * um,
    )))
}
