//! The statistics of a yield: the exact (Clopper–Pearson) binomial interval of a fraction, and
//! the one-sided lower confidence bound of a quantile from order statistics (Wilks).
//!
//! **Clopper–Pearson.** k of n devices hold: the two-sided interval at confidence γ is
//! [p_L, p_U] with P(X ≥ k | p_L) = (1 − γ)/2 and P(X ≤ k | p_U) = (1 − γ)/2, X ~ Bin(n, p)
//! (p_L = 0 when k = 0, p_U = 1 when k = n). Its coverage is at least γ for every p.
//!
//! **Wilks.** With the critical loads sorted, W_(1) ≤ … ≤ W_(n), the load that a fraction q of
//! devices hold, ξ (P(W_c ≥ ξ) = q), is bounded below by W_(r) with confidence γ when
//! P(Bin(n, 1 − q) ≥ r) ≥ γ; the bound is the largest such r. For r = 1 this is
//! 1 − qⁿ ≥ γ: n ≥ ln(1 − γ)/ln q (59 for q = γ = 0.95, [`min_samples`]).
//!
//! Cost: O(n) per binomial CDF, about 100 of them per interval (bisection on p).

/// P(X ≤ k) for X ~ Bin(n, p) (summed in log space, exact to rounding). O(n).
pub fn binomial_cdf(k: usize, n: usize, p: f64) -> f64 {
    if k >= n {
        return 1.0;
    }
    if p <= 0.0 {
        return 1.0;
    }
    if p >= 1.0 {
        return 0.0;
    }
    let (lp, lq) = (p.ln(), (1.0 - p).ln());
    let mut log_pmf = n as f64 * lq; // ln P(X = 0)
    let mut sum = log_pmf.exp();
    for i in 0..k {
        log_pmf += ((n - i) as f64 / (i + 1) as f64).ln() + lp - lq;
        sum += log_pmf.exp();
    }
    sum.min(1.0)
}

/// The p in [0, 1] at which the decreasing function `f(p)` crosses `target` (bisection to
/// 1e-12).
fn solve_decreasing(f: impl Fn(f64) -> f64, target: f64) -> f64 {
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if f(m) > target {
            lo = m;
        } else {
            hi = m;
        }
        if hi - lo < 1e-12 {
            break;
        }
    }
    0.5 * (lo + hi)
}

/// The two-sided Clopper–Pearson interval (p_L, p_U) of a fraction with `k` successes out of
/// `n` at confidence `confidence` (in (0, 1); module docs). `n` = 0: (0, 1).
pub fn clopper_pearson(k: usize, n: usize, confidence: f64) -> (f64, f64) {
    if n == 0 {
        return (0.0, 1.0);
    }
    let a = 0.5 * (1.0 - confidence);
    let lo = if k == 0 {
        0.0
    } else {
        // P(X ≥ k | p) = 1 − cdf(k − 1) increases with p: solve cdf(k − 1) = 1 − a
        solve_decreasing(|p| binomial_cdf(k - 1, n, p), 1.0 - a)
    };
    let hi = if k >= n {
        1.0
    } else {
        solve_decreasing(|p| binomial_cdf(k, n, p), a)
    };
    (lo, hi)
}

/// The rank r (1-based) of the order statistic W_(r) that bounds the load held by a fraction
/// `q` of devices from below with confidence `confidence`: the largest r with
/// P(Bin(n, 1 − q) ≥ r) ≥ confidence (module docs); `None` when even W_(1) is not enough (n
/// below [`min_samples`]).
pub fn wilks_rank(n: usize, q: f64, confidence: f64) -> Option<usize> {
    let mut best = None;
    for r in 1..=n {
        let p_at_least = 1.0 - binomial_cdf(r - 1, n, 1.0 - q);
        if p_at_least >= confidence {
            best = Some(r);
        } else {
            break;
        }
    }
    best
}

/// The fewest samples for which W_(1) bounds the q-quantile load with confidence
/// `confidence`: ⌈ln(1 − γ)/ln q⌉ (59 for 0.95/0.95).
pub fn min_samples(q: f64, confidence: f64) -> usize {
    ((1.0 - confidence).ln() / q.ln() - 1e-9).ceil().max(1.0) as usize
}

/// The point estimate of the load held by a fraction `q` of devices: the largest critical load
/// W such that at least ⌈q n⌉ of the `sorted` (ascending) critical loads are ≥ W, i.e.
/// W_(n − ⌈q n⌉ + 1). `None` when there are none.
pub fn quantile_load(sorted: &[f64], q: f64) -> Option<f64> {
    let n = sorted.len();
    if n == 0 {
        return None;
    }
    let need = ((q * n as f64) - 1e-9).ceil().clamp(1.0, n as f64) as usize;
    Some(sorted[n - need])
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    #[test]
    fn the_binomial_cdf_sums_the_pmf() {
        assert!((binomial_cdf(0, 3, 0.5) - 0.125).abs() < 1e-15);
        assert!((binomial_cdf(1, 3, 0.5) - 0.5).abs() < 1e-15);
        assert_eq!(binomial_cdf(3, 3, 0.2), 1.0);
        assert!((binomial_cdf(58, 59, 0.95) - (1.0 - 0.95f64.powi(59))).abs() < 1e-12);
    }

    /// Known values: k = n = 59 at 95 %: p_L = 0.025^(1/59); k = 0: p_U = 1 − 0.025^(1/n);
    /// 5 of 10: (0.187, 0.813) (published tables).
    #[test]
    fn clopper_pearson_matches_closed_forms_and_tables() {
        let (lo, hi) = clopper_pearson(59, 59, 0.95);
        assert!((lo - 0.025f64.powf(1.0 / 59.0)).abs() < 1e-9);
        assert_eq!(hi, 1.0);
        let (lo, hi) = clopper_pearson(0, 20, 0.95);
        assert_eq!(lo, 0.0);
        assert!((hi - (1.0 - 0.025f64.powf(1.0 / 20.0))).abs() < 1e-9);
        let (lo, hi) = clopper_pearson(5, 10, 0.95);
        assert!(
            (lo - 0.1871).abs() < 1e-4 && (hi - 0.8129).abs() < 1e-4,
            "{lo} {hi}"
        );
    }

    /// Wilks: 59 samples give the 95 %/95 % bound at the lowest critical load, 58 none; 93
    /// samples at 95 %/95 % allow the second lowest (1 − P(Bin(93, 0.05) ≤ 1) ≥ 0.95).
    #[test]
    fn wilks_gives_the_classic_sample_sizes() {
        assert_eq!(min_samples(0.95, 0.95), 59);
        assert_eq!(wilks_rank(59, 0.95, 0.95), Some(1));
        assert_eq!(wilks_rank(58, 0.95, 0.95), None);
        assert_eq!(wilks_rank(93, 0.95, 0.95), Some(2));
        assert_eq!(min_samples(0.9, 0.95), 29);
        assert_eq!(wilks_rank(29, 0.9, 0.95), Some(1));
    }

    #[test]
    fn the_quantile_load_leaves_the_right_number_below() {
        let w: Vec<f64> = (1..=59).map(f64::from).collect();
        // ⌈0.95 · 59⌉ = 57 samples hold W_(3)
        assert_eq!(quantile_load(&w, 0.95), Some(3.0));
        assert_eq!(quantile_load(&w[..20], 0.95), Some(2.0));
        assert_eq!(quantile_load(&[], 0.5), None);
    }

    /// The interval's coverage in a seeded simulation of a known yield (p = 0.9, 59 samples,
    /// 1000 repeats) is at least its nominal 95 % minus three standard errors of the
    /// simulation.
    #[test]
    fn the_interval_covers_a_known_yield() {
        let (p, n, repeats) = (0.9, 59usize, 1000usize);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(2026);
        let mut covered = 0;
        for _ in 0..repeats {
            let k = (0..n).filter(|_| rng.random::<f64>() < p).count();
            let (lo, hi) = clopper_pearson(k, n, 0.95);
            if lo <= p && p <= hi {
                covered += 1;
            }
        }
        let rate = covered as f64 / repeats as f64;
        let noise = 3.0 * (0.95f64 * 0.05 / repeats as f64).sqrt();
        assert!(rate >= 0.95 - noise, "coverage {rate}");
        // and the one-sided bound of the Wilks rank covers the true 0.95-quantile of a known
        // distribution (uniform on [0, 1]: ξ = 0.05) at least 95 % − noise of the time
        let mut held = 0;
        for _ in 0..repeats {
            let mut w: Vec<f64> = (0..59).map(|_| rng.random::<f64>()).collect();
            w.sort_by(f64::total_cmp);
            let r = wilks_rank(59, 0.95, 0.95).unwrap();
            if w[r - 1] <= 0.05 {
                held += 1;
            }
        }
        let rate = held as f64 / repeats as f64;
        assert!(rate >= 0.95 - noise, "Wilks coverage {rate}");
    }
}
