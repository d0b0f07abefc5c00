//! The output row types: ONE struct and ONE CSV/JSON schema per kind of row, used by every
//! command that writes that kind of row. Columns and keys are in user units and say so in their
//! names; the values are converted from SI with `surrogate::units` here and nowhere else.
//!
//! | row | written by | columns |
//! |---|---|---|
//! | [`ScreenRow`] | `screen --out`, `figures` (sweep_*.csv) | `pattern,theta_deg,load_mN,contacts,p_max_GPa,z_um,coating_failed,failed_contacts,tilt_x_urad,tilt_y_urad,model,residual_rel,iterations,error` |
//! | [`ContactRow`] | `screen --contacts-out`, `landscape --contacts-out`, `figures` (contact_map_*.csv) | `slider_index,substrate_index,x_um,y_um,z_um,overlap_nm,force_uN,p0_GPa,failed` |
//! | [`LandscapeRow`] | `landscape --out`, `figures` (landscape_*.csv) | `x_um,y_um,dz_nm` |
//! | [`LandscapeZRow`] | `landscape --shard i/n --out` (a shard, merged by `superlube merge`), the landscape's spill file | `x_um,y_um,z_um` (z exact, see [`exact_um`]) |
//! | [`CorrugationRow`] | `corrugation --out`, `figures` (corrugation_square-tri.csv) | `theta_deg,load_mN,line_deg,alpha_deg,direction_deg,corrugation_nm,max_lateral_force_mN` |
//! | [`FrictionRow`] | `friction --out`, `design` (`friction_<pattern>.csv`) | `pattern,theta_deg,alpha_deg,load_mN,mu_est,p_max_GPa,failed_fraction,mu_coating,mu_corrugation,mu_quasi_static,mu_est_spread,eta,barrier_pJ,max_lateral_force_mN,p_max_mean_GPa,contacts_mean,k_spring_N_m,line_deg,direction_deg,path_length_um,path_step_um,samples,periodic,slips,transverse_offset_um,tilt_pair_ratio,mount_resonance,verdict,error` (`verdict`: `friction`, `design`) |
//! | [`DemSample`] | `equilibrate --out`, `slide --out` | `t_us,support_x_um,spring_force_mN,z_um,contacts,p_max_GPa,failed_contacts,p_max_peak_GPa` |
//! | [`EquilibrateReport`], [`SlideReport`] | `equilibrate --json`, `slide --json` | JSON objects (keys documented on the fields) |
//! | [`BatchRow`] | `slide --out-dir DIR` (`DIR/runs.csv`), `figures --friction` (`runs.csv`) | `name,pattern,theta_deg,alpha_deg,load_mN,sigma_h_um,seed,E_GPa,p_crit_GPa,mu1,mu2,mu_constant,mount,model_requested,model,rigid_z,equilibrate_us,relax_us,slide_us,speed_m_s,dt_us,friction_mN,friction_std_mN,mu,mean_contacts,max_p_max_GPa,mean_failed_contacts,locked_in,advance_ratio,steps,wall_s,status,error` |
//! | [`ConfigStatsRow`] | `slide --out-dir DIR --seeds …` (`DIR/seeds.csv`), `figures --friction` (`friction_fig*.csv`) | `series,pattern,theta_deg,alpha_deg,sigma_h_um,E_GPa,load_mN,n,n_ok,friction_mean_mN,friction_std_mN,friction_min_mN,friction_max_mN,mu_mean,mu_std,mu_min,mu_max,max_p_max_GPa,mean_failed_contacts,locked_in_runs` |

mod batch;
mod corrugation;
mod dem_summary;
mod format;
mod friction;
mod landscape;
mod screen;
mod stats;
pub mod verdict;

pub use batch::{BatchRow, ConfigStatsRow, RunStatus};
pub use corrugation::CorrugationRow;
pub use dem_summary::{DemCase, EquilibrateReport, RunInfo, SlideReport};
pub use format::{clean, exact_um, label, parse_exact_um};
pub use friction::FrictionRow;
pub use landscape::{LandscapeRow, LandscapeZRow};
pub use screen::{ContactRow, ScreenRow};
pub use stats::stats;

pub use dem::protocol::Sample as DemSample;
pub use dem::protocol::{EquilibrateSummary, SlideSummary};

#[cfg(test)]
mod tests;
